#version 450
// The visibility path's contact shadows too large for splat_shadows.comp's one invocation a
// shadow (shadow_splat.glsl): a workgroup per listed shadow, its invocations taking every
// kSplatGroupSize-th texel of the bound, so a near character's shadow is cast 64 texels at a
// time and the shadows spread over the CPU's threads. Dispatched indirectly, with as many
// workgroups as shadows were listed (up to kLargestSplatGroups).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES
#include "shadow_splat.glsl"

layout(local_size_x = kSplatGroupSize) in;

void main() {
    const SplatFrame frame = splatFrame();
    const float cullHeight = push.cullHeight;
    const uint list = kLargeShadowList * push.characterCount;
    // Past kLargestSplatGroups listed, each workgroup takes more than one.
    for (uint listed = gl_WorkGroupID.x; listed < characterLists[list + kLargeShadowListed]; listed += gl_NumWorkGroups.x) {
        Shadow shadow;
        if (!shadowOf(characterLists[list + kLargeShadowFirst + listed], frame, cullHeight, shadow)) continue;
        const ivec2 size = max(shadow.hi - shadow.lo + 1, ivec2(0));
        const int texels = size.x * size.y;
        for (int t = int(gl_LocalInvocationIndex); t < texels; t += int(kSplatGroupSize)) shadowTexel(shadow, ivec2(t % size.x, t / size.x), frame);
    }
}
