#version 450
// The paper's path: no compute pass. Every vertex of every joint sphere resolves its joint
// itself from the instance index (m = id / k, j = id % k), the character's frame position and
// the baked table, then places the sphere vertex. Same result as resolve.comp + sphere.vert,
// but the joint is recomputed once per vertex instead of once per instance.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "pose.glsl"

layout(location = 0) in vec3 unitPosition;
layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 albedo;

void main() {
    const uint m = uint(gl_InstanceIndex) / push.jointsPerCharacter;
    const uint j = uint(gl_InstanceIndex) % push.jointsPerCharacter;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    if (j >= clip.jointCount) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
        return;
    }
    // The joint's sphere needs no orientation: the position only, as resolve.comp computes it.
    const CharacterPose pose = characterPose(character, clip);
    const vec3 centre = poseToWorld(pose, jointTranslation(pose, j));
    // The radius is scaled first, as resolve.comp stores it, so both paths round alike.
    const float radius = jointRadiusAt(clip, j) * character.scale;
    worldPosition = centre + unitPosition * radius;
    worldNormal = unitPosition;
    albedo = unpackUnorm4x8(character.color).rgb;
    gl_Position = scene.viewProjection * vec4(worldPosition, 1.0);
}
