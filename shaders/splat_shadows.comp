#version 450
// The visibility path's contact shadows (shadow_splat.glsl): one invocation per character casts
// the ray of every texel inside its shadow's screen bound onto the ground. A rasterised quad
// per character costs a CPU rasteriser more set-up than the few texels most shadows cover. A
// shadow whose bound passes kLargestSplatShadow texels is listed for splat_large_shadows.comp
// instead: one invocation would loop over all of its texels alone (a near character's covers
// thousands, and its whole workgroup, on one CPU thread, waits for that one lane).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES
#include "culling.glsl"
#include "shadow_splat.glsl"

layout(local_size_x = kSplatGroupSize) in;

const int kLargestSplatShadow = 1024;  // texels of screen bound

// A skinned character's screen bound (its culling sphere's, a square's width to spare), for
// the shading squares whose pixels the next frame keeps (shading_tiles.glsl).
void listSkinnedBound(uint m, SplatFrame frame) {
    const CharacterGpu character = characters[m];
    vec2 centre;
    float radius;
    const bool bounded = screenCircle(frame, vec4(characterCentre(character), push.cullRadius * character.scale), centre, radius);
    const float spare = radius + float(kShadingTile);
    listSkinBox(ivec2(max(floor(centre - spare), vec2(-1.0))), ivec2(min(ceil(centre + spare), frame.viewport.xy + 1.0)), bounded);
}

void splatShadow(uint m, SplatFrame frame, float cullHeight, uint characterCount) {
    if (bodyLevels[m].level == 3u) listSkinnedBound(m, frame);
    Shadow shadow;
    if (!shadowOf(m, frame, cullHeight, shadow)) return;
    // A bound empty both ways has a positive area too: that character (behind the eye, or off
    // the frame) is listed, and its workgroup finds no texel. (Left to the loops instead, such
    // bounds made this pass 1.5 ms slower on lavapipe.)
    ivec2 pixelsLo, pixelsHi;
    shadowPixelBound(shadow, frame, pixelsLo, pixelsHi);
    markBodyTiles(pixelsLo, pixelsHi, kShadowMark, frame.tilesAcross);  // the ground there is shaded with its shadows read
    const ivec2 size = shadow.hi - shadow.lo + 1;
    if (size.x * size.y > kLargestSplatShadow) {
        const uint list = kLargeShadowList * characterCount, at = atomicAdd(characterLists[list + kLargeShadowListed], 1u);
        characterLists[list + kLargeShadowFirst + at] = m;
        atomicMax(characterLists[list], min(at + 1u, kLargestSplatGroups));  // its dispatch's workgroups
        return;
    }
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) shadowTexel(shadow, ivec2(x, y), frame);
}

void main() {
    // One invocation per character of the batch (culled ones find an empty or clipped bound).
    const SplatFrame frame = splatFrame();
    const uint m = gl_GlobalInvocationID.x, characterCount = push.characterCount;
    const float cullHeight = push.cullHeight;
    if (m < characterCount) splatShadow(m, frame, cullHeight, characterCount);
}
