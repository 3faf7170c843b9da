#version 450
// Resolves every instance's joint in the world: instance id -> character m = id / k and
// joint j = id % k (k joints per character); reads the character's frame position, blends
// the two baked frames around it (nlerp rotations, lerp translations), and places the result
// with the character's ground frame and scale.
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes instances
#include "bindings.glsl"

layout(local_size_x = 64) in;

vec4 quatMultiply(vec4 a, vec4 b) {
    return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}

void main() {
    const uint id = gl_GlobalInvocationID.x;
    if (id >= push.characterCount * push.jointsPerCharacter) return;
    const uint m = id / push.jointsPerCharacter;
    const uint j = id % push.jointsPerCharacter;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    if (j >= clip.jointCount) {  // a clip with fewer joints than k: nothing to draw here
        instances[id] = InstanceGpu(vec4(0.0), vec4(0.0, 0.0, 0.0, 1.0), vec4(0.0));
        return;
    }
    const float frame = clamp(character.frame, 0.0, float(clip.frameCount - 1));
    const uint f0 = uint(floor(frame));
    const uint f1 = min(f0 + 1, clip.frameCount - 1);
    const float t = frame - float(f0);
    const PoseGpu a = poses[clip.firstPose + f0 * clip.jointCount + j];
    const PoseGpu b = poses[clip.firstPose + f1 * clip.jointCount + j];
    // nlerp on the short arc; neighbouring frames are close, so this matches slerp closely.
    const vec4 bRotation = dot(a.rotation, b.rotation) < 0.0 ? -b.rotation : b.rotation;
    const vec4 rotation = normalize(mix(a.rotation, bRotation, t));
    const vec3 local = mix(a.translation.xyz, b.translation.xyz, t) * character.scale;

    const float yaw = character.groundFrame.w;
    const float c = cos(yaw), s = sin(yaw);
    // Rotation about +Y by yaw: x' = c x + s z, z' = -s x + c z (matches core/math.h).
    const vec3 world = character.groundFrame.xyz + vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
    const vec4 yawQuat = vec4(0.0, sin(0.5 * yaw), 0.0, cos(0.5 * yaw));
    const vec4 color = unpackUnorm4x8(character.color);
    instances[id] = InstanceGpu(vec4(world, jointRadius[clip.firstJoint + j] * character.scale),
                                quatMultiply(yawQuat, rotation), vec4(color.rgb, 1.0));
}
