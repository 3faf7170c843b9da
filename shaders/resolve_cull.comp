#version 450
// The fast path's compute pass: one invocation per character. A character whose bounding
// sphere is outside the view frustum writes nothing; a visible one reserves room for its
// joints with one atomic add on the indirect draw's vertex count and writes them there, so the
// draw touches only what can be seen. Joints of one character stay together and in order.
// Distant characters keep only their major joints (level of detail).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes instances, the draw arguments and the instance owners
#include "bindings.glsl"

layout(local_size_x = 64) in;

bool visible(vec3 centre, float radius) {
    for (int p = 0; p < 6; ++p)
        if (dot(push.frustum[p].xyz, centre) + push.frustum[p].w < -radius) return false;
    return true;
}

void main() {
    const uint m = gl_GlobalInvocationID.x;
    if (m >= push.characterCount) return;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const vec3 centre = character.groundFrame.xyz + vec3(0.0, push.cullHeight * character.scale, 0.0);
    if (!visible(centre, push.cullRadius * character.scale)) return;
    // Level of detail: a character drawn only a few dozen pixels tall keeps its major joints;
    // the small ones would overlap them within a pixel or two anyway.
    const float onScreen = 2.0 * push.cullHeight * character.scale * scene.viewport.z / max(distance(centre, scene.cameraPosition.xyz), 1e-3);
    const bool coarse = onScreen < push.lodPixels;
    uint kept = 0;
    for (uint j = 0; j < clip.jointCount; ++j) kept += (coarse && jointDetail[clip.firstJoint + j] != 0u) ? 0u : 1u;
    uint slot = atomicAdd(draw.vertexCount, kept);
    const float frame = clamp(character.frame, 0.0, float(clip.frameCount - 1));
    const uint f0 = uint(floor(frame));
    const uint f1 = min(f0 + 1, clip.frameCount - 1);
    const float t = frame - float(f0);
    const float c = cos(character.groundFrame.w), s = sin(character.groundFrame.w);
    const vec4 color = vec4(unpackUnorm4x8(character.color).rgb, 1.0);
    for (uint j = 0; j < clip.jointCount; ++j) {
        if (coarse && jointDetail[clip.firstJoint + j] != 0u) continue;
        const vec3 local = mix(poses[clip.firstPose + f0 * clip.jointCount + j].translation.xyz,
                               poses[clip.firstPose + f1 * clip.jointCount + j].translation.xyz, t) * character.scale;
        const vec3 world = character.groundFrame.xyz + vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
        // Spheres need no orientation; the fast path leaves it out of the work.
        instances[slot] = InstanceGpu(vec4(world, jointRadius[clip.firstJoint + j] * character.scale), vec4(0.0, 0.0, 0.0, 1.0), color);
        instanceOwners[slot] = uvec2(m, j);  // character, joint
        ++slot;
    }
}
