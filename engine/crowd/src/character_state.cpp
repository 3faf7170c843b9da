#include "throng/crowd/character_state.h"

namespace throng::crowd {

JointWorld sampleJointWorld(const motion::BakedClip& clip, const CharacterState& character, int joint) {
    const motion::JointPose pose = clip.sample(character.frame, joint);
    // In float and in this order, as pose.glsl: the cpu render path must draw what the GPU draws.
    glm::vec3 local = pose.translation * character.scale;
    glm::quat rotation = pose.rotation;
    const std::uint8_t leg = clip.footLeg.empty() ? 0 : clip.footLeg[static_cast<std::size_t>(joint)];
    const float twist = leg == 0 ? 0.0F : character.footTwist[leg - 1];
    if (twist != 0.0F) {
        const glm::vec3 ankle = clip.sample(character.frame, clip.anatomy.legs[leg - 1U].ankle).translation * character.scale;
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
