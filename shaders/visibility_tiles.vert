#version 450
// The visibility path's shading squares (shading_tiles.glsl): two triangles per listed square.
// The draw's firstVertex picks the list: 0 the body squares, 6 the ground squares.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "shading_tiles.glsl"

void main() {
    const uint list = uint(gl_VertexIndex) / 6u, corner = uint(gl_VertexIndex) % 6u;
    const uvec2 grid = tileGrid();
    const uint tile = tileData[grid.x * grid.y * (1u + list) + uint(gl_InstanceIndex)];
    // Corners (0,0) (1,0) (0,1), then (0,1) (1,0) (1,1).
    const uvec2 offset = uvec2(corner == 1u || corner == 4u || corner == 5u ? 1u : 0u, corner == 2u || corner == 3u || corner == 5u ? 1u : 0u);
    const vec2 pixel = min(vec2((uvec2(tile % grid.x, tile / grid.x) + offset) * uint(kShadingTile)), scene.viewport.xy);
    gl_Position = vec4(pixel / scene.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
}
