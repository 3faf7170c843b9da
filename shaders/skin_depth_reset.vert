#version 450
// The visibility path's depth, reset to the far plane (1) where skinned bodies may draw, just
// before they do: nothing else in that path tests or writes depth, so the attachment is not
// cleared (lavapipe clears a whole frame's depth, about 0.4 ms at 1280 x 720, for the few
// pixels skinned bodies cover). One quad per skinned body's screen bound as the contact shadows'
// splat listed it (shading_tiles.glsl's skinBoxes, which hold every pixel its mesh may cover);
// past kSkinBoxes, or with one too near the eye to bound, instance 0 covers the whole frame.
// Unused instances collapse to a point. Drawn with no fragment shader and no colour written.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "shading_tiles.glsl"

void main() {
    const uint box = uint(gl_InstanceIndex), corner = uint(gl_VertexIndex) % 6u;
    const bool everywhere = unboundedSkin != 0u || skinBoxCount > kSkinBoxes;
    vec2 lo = vec2(0.0), hi = vec2(0.0);  // pixel edges
    if (everywhere) {
        if (box == 0u) hi = scene.viewport.xy;
    } else if (box < skinBoxCount) {
        const ivec4 bound = skinBoxes[box];  // first and last pixel, inclusive
        lo = clamp(vec2(bound.xy), vec2(0.0), scene.viewport.xy);
        hi = clamp(vec2(bound.zw + 1), vec2(0.0), scene.viewport.xy);
    }
    // Corners (0,0) (1,0) (0,1), then (0,1) (1,0) (1,1).
    const bvec2 far = bvec2(corner == 1u || corner == 4u || corner == 5u, corner == 2u || corner == 3u || corner == 5u);
    const vec2 pixel = mix(lo, hi, vec2(far));
    gl_Position = vec4(pixel / scene.viewport.xy * 2.0 - 1.0, 1.0, 1.0);
}
