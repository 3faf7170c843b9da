#version 450
// The fast path's compute pass: one invocation per character. A character whose bounding
// sphere is outside the view frustum writes nothing; a visible one reserves room for its
// joints with one atomic add on the indirect draw's vertex count and writes them there, so the
// draw touches only what can be seen. Joints of one character stay together and in order.
// Distant characters keep only their major joints (level of detail).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes instances, the draw arguments and the instance owners
#include "bindings.glsl"
#include "culling.glsl"
#include "pose.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint m = gl_GlobalInvocationID.x;
    if (m >= push.characterCount) return;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const vec3 centre = characterCentre(character);
    if (!insideFrustum(centre, push.cullRadius * character.scale)) return;
    // Level of detail: a character drawn only a few dozen pixels tall keeps its major joints;
    // the small ones would overlap them within a pixel or two anyway.
    const bool coarse = pixelsTall(character, centre) < push.lodPixels;
    uint kept = 0;
    for (uint j = 0; j < clip.jointCount; ++j) kept += (coarse && isDetailJoint(clip, j)) ? 0u : 1u;
    uint slot = atomicAdd(draw.vertexCount, kept);
    if (coarse)
        atomicAdd(draw.coarseCharacters, 1u);
    else
        atomicAdd(draw.fullCharacters, 1u);
    const vec4 color = vec4(unpackUnorm4x8(character.color).rgb, 1.0);
    for (uint j = 0; j < clip.jointCount; ++j) {
        if (coarse && isDetailJoint(clip, j)) continue;
        // Spheres need no orientation; the fast path samples the position only.
        const vec3 world = groundToWorld(character, sampleJointTranslation(character, clip, j));
        instances[slot] = InstanceGpu(vec4(world, jointRadiusAt(clip, j) * character.scale), vec4(0.0, 0.0, 0.0, 1.0), color);
        instanceOwners[slot] = uvec2(m, j);  // character, joint
        ++slot;
    }
}
