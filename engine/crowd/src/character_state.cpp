#include "throng/crowd/character_state.h"

namespace throng::crowd {

JointWorld sampleJointWorld(const motion::BakedClip& clip, const CharacterState& character, int joint) {
    const motion::JointPose pose = clip.sample(character.frame, joint);
    // In float and in this order, as pose.glsl: the cpu render path must draw what the GPU draws.
    const glm::vec3 local = pose.translation * character.scale;
    const float yaw = character.groundFrame.w;
    const float c = std::cos(yaw), s = std::sin(yaw);
    JointWorld out;
    out.position = glm::vec3(character.groundFrame) + glm::vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
    out.orientation = glm::angleAxis(yaw, glm::vec3(0.0F, 1.0F, 0.0F)) * pose.rotation;
    out.radius = clip.jointRadius[static_cast<std::size_t>(joint)] * character.scale;
    return out;
}

}  // namespace throng::crowd
