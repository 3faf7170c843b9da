#version 450
// The visibility path's shading squares (shading_tiles.glsl): two triangles per listed square.
// The draw's firstVertex picks the list (shading_tiles.glsl's, times 6): 0 the body squares, 6
// the ground squares no shadow touches, 12 the joint squares, 18 the ground squares a shadow may
// darken, then 24, 30 and 36 the opaque ground, body and joint squares.
// Each corner also passes on the ray through it, affine across the frame, so the shading
// interpolates it instead of working it out per pixel (on a CPU rasteriser, a matrix a pixel
// costs more than the ground's whole pattern).
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "shading_tiles.glsl"
#include "sphere_cast.glsl"

// The ray from the eye through the corner's point on the near plane, not normalised: the near
// plane's points are affine in the frame's coordinates, so this interpolates exactly.
layout(location = 0) noperspective out vec3 groundRay;
// The scene, for the shading to read as flat inputs: lavapipe fetches a uniform buffer's value
// lane by lane in a fragment shader, for every pixel, and a flat input once per block.
layout(location = 1) flat out SceneData tileScene;

void main() {
    const uint list = uint(gl_VertexIndex) / 6u, corner = uint(gl_VertexIndex) % 6u;
    const uvec2 grid = tileGrid();
    const uint tile = tileData[tileListStart(list) + uint(gl_InstanceIndex)];
    // Corners (0,0) (1,0) (0,1), then (0,1) (1,0) (1,1).
    const uvec2 offset = uvec2(corner == 1u || corner == 4u || corner == 5u ? 1u : 0u, corner == 2u || corner == 3u || corner == 5u ? 1u : 0u);
    const vec2 pixel = min(vec2((uvec2(tile % grid.x, tile / grid.x) + offset) * uint(kShadingTile)), scene.viewport.xy);
    gl_Position = vec4(pixel / scene.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
    groundRay = rayToNearPlane(gl_Position.xy);
    tileScene = scene;
}
