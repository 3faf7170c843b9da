#include "throng/crowd/character_state.h"

namespace throng::crowd {
namespace {

// Mixes `other` into `base` by `weight` as pose.glsl's mixPose: nlerp on the short arc, lerp.
motion::JointPose mixPose(const motion::JointPose& base, const motion::JointPose& other, float weight) {
    const glm::quat shortArc = glm::dot(base.rotation, other.rotation) < 0.0F ? -other.rotation : other.rotation;
    motion::JointPose out;
    out.rotation = glm::normalize(base.rotation * (1.0F - weight) + shortArc * weight);
    out.translation = glm::mix(base.translation, other.translation, weight);
    return out;
}

// The character's pose of `joint` in its ground frame, unscaled: its clip, blended, then
// crossfaded (pose.glsl's blendedPose).
motion::JointPose blendedPose(std::span<const motion::BakedClip> clips, const CharacterState& character, int joint) {
    const motion::BakedClip& clip = clips[character.clip];
    motion::JointPose pose = clip.sample(character.frame, joint);
    const auto sameSkeleton = [&](std::uint32_t other) { return other < clips.size() && clips[other].jointCount() == clip.jointCount(); };
    if (character.blend != 0.0F && sameSkeleton(character.blendClip))
        pose = mixPose(pose, clips[character.blendClip].sample(character.blendFrame, joint), character.blend);
    if (character.fromWeight != 0.0F && sameSkeleton(character.fromClip))
        pose = mixPose(pose, clips[character.fromClip].sample(character.fromFrame, joint), character.fromWeight);
    return pose;
}

}  // namespace

JointWorld sampleJointWorld(std::span<const motion::BakedClip> clips, const CharacterState& character, int joint) {
    const motion::BakedClip& clip = clips[character.clip];
    const motion::JointPose pose = blendedPose(clips, character, joint);
    // In float and in this order, as pose.glsl: the cpu render path must draw what the GPU draws.
    glm::vec3 local = pose.translation * character.scale;
    glm::quat rotation = pose.rotation;
    const std::uint8_t leg = clip.footLeg.empty() ? 0 : clip.footLeg[static_cast<std::size_t>(joint)];
    const float twist = leg == 0 ? 0.0F : character.footTwist[leg - 1];
    if (twist != 0.0F) {
        const glm::vec3 ankle = blendedPose(clips, character, clip.anatomy.legs[leg - 1U].ankle).translation * character.scale;
        const glm::vec3 offset = local - ankle;
        const float tc = std::cos(twist), ts = std::sin(twist);
        local = ankle + glm::vec3(tc * offset.x + ts * offset.z, offset.y, -ts * offset.x + tc * offset.z);
        rotation = glm::angleAxis(twist, glm::vec3(0.0F, 1.0F, 0.0F)) * rotation;
    }
    const float yaw = character.groundFrame.w;
    const float c = std::cos(yaw), s = std::sin(yaw);
    JointWorld out;
    out.position = glm::vec3(character.groundFrame) + glm::vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
    out.orientation = glm::angleAxis(yaw, glm::vec3(0.0F, 1.0F, 0.0F)) * rotation;
    out.radius = clip.jointRadius[static_cast<std::size_t>(joint)] * character.scale;
    return out;
}

}  // namespace throng::crowd
