#version 450
// Resolves every instance's joint in the world: instance id -> character m = id / k and
// joint j = id % k (k joints per character); samples the joint at the character's frame
// position and places it with the character's ground frame and scale (pose.glsl).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes instances
#include "bindings.glsl"
#include "pose.glsl"

layout(local_size_x = 64) in;

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
    const CharacterPose pose = characterPose(character, clip);
    const vec4 color = unpackUnorm4x8(character.color);
    instances[id] = InstanceGpu(vec4(poseToWorld(pose, jointTranslation(pose, j)), jointRadiusAt(clip, j) * character.scale),
                                poseToWorldRotation(pose, jointRotation(pose, j)), vec4(color.rgb, 1.0));
}
