#version 450
// The visibility path's contact shadows (shadow_splat.glsl): one invocation per character casts
// the ray of every pixel inside its shadow's screen bound onto the ground. A rasterised quad
// per character costs a CPU rasteriser more set-up than the few pixels most shadows cover. A
// shadow whose bound passes kLargestSplatShadow pixels is listed for splat_large_shadows.comp
// instead: one invocation would loop over all of its pixels alone (a near character's covers
// thousands, and its whole workgroup, on one CPU thread, waits for that one lane).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES
#include "culling.glsl"
#include "shadow_splat.glsl"

layout(local_size_x = kSplatGroupSize) in;

const int kLargestSplatShadow = 1024;  // pixels of screen bound

// A character resolve_bones.comp skins (its planning pass's own test) marks the squares its bounding
// sphere may cover: skin.frag, drawn after the shading, tests against the ground's depth there,
// so those squares are not shaded opaque (shading_tiles.glsl). One too near the eye to bound
// sets skinEverywhere instead (marking every square from here cost lavapipe 1.7 ms a frame).
void markSkin(uint m) {
    const CharacterGpu character = characters[m];
    bool visible;
    if (!skinnedAt(tallInView(character, visible)) || !visible) return;
    vec2 middle;
    float radius;
    if (!screenCircle(vec4(characterCentre(character), push.cullRadius * character.scale), middle, radius)) {
        atomicOr(skinEverywhere, 1u);
        return;
    }
    // A pixel to spare each side: the mark is what keeps a skinned body's feet behind the ground.
    const vec2 last = scene.viewport.xy - 1.0;
    markBodyTiles(ivec2(floor(clamp(middle - radius - 1.0, vec2(0.0), last))), ivec2(ceil(clamp(middle + radius + 1.0, vec2(0.0), last))), kSkinMark);
}

void splatShadow(uint m) {
    markSkin(m);
    Shadow shadow;
    if (!shadowOf(m, shadow)) return;
    // A bound empty both ways has a positive area too: that character (behind the eye, or off
    // the frame) is listed, and its workgroup finds no pixel. (Left to the loops instead, such
    // bounds made this pass 1.5 ms slower on lavapipe.)
    markBodyTiles(shadow.lo, shadow.hi, kShadowMark);  // the ground there is shaded with its shadows read
    const ivec2 size = shadow.hi - shadow.lo + 1;
    if (size.x * size.y > kLargestSplatShadow) {
        const uint list = kLargeShadowList * push.characterCount, at = atomicAdd(characterLists[list + kLargeShadowListed], 1u);
        characterLists[list + kLargeShadowFirst + at] = m;
        atomicMax(characterLists[list], min(at + 1u, kLargestSplatGroups));  // its dispatch's workgroups
        return;
    }
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) shadowPixel(shadow, ivec2(x, y));
}

void main() {
    // One invocation per character of the batch (culled ones find an empty or clipped bound).
    const uint m = gl_GlobalInvocationID.x;
    if (m < push.characterCount) splatShadow(m);
}
