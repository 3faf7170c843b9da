#pragma once
// One character as the GPU reads it, and joint sampling: the one C++ definition of where a
// character's joint is in the world. It mirrors shaders/pose.glsl step for step, in float and
// in the same order, so the cpu render path and the GPU tests' checker agree with the shaders
// (to the last bits of the GPU's own cos, sin and mix: about 1e-7 of the body's height).

#include <cstdint>

#include "throng/core/math.h"
#include "throng/motion/baked_clip.h"

namespace throng::crowd {

/// One character as the GPU reads it (std430; `CharacterGpu` in shaders/gpu_types.glsl).
struct CharacterState {
    glm::vec4 groundFrame{0.0F};  ///< xyz: world position of the ground frame (metres, y = 0); w: yaw (radians).
    std::uint32_t clip = 0;       ///< Index into the clip table.
    float frame = 0.0F;           ///< Frame position inside the clip's loop, fractional.
    float scale = 1.0F;           ///< Uniform body scale.
    std::uint32_t color = 0;      ///< RGBA8 (R in the low byte), linear colour.
    /// Per leg (anatomy.legs), radians: the foot (BakedClip::footLeg joints) turned about the
    /// ankle, in the ground frame, the way yaw turns the body. A planted foot takes a steering
    /// turn back this way, so it stays put while the body turns over it; a foot in the air
    /// twists ahead of the turn (Crowd::twistFeet). 0 draws the clip as baked.
    glm::vec2 footTwist{0.0F};
    glm::vec2 unused{0.0F};       ///< Pads to std430's 16-byte stride.
};
static_assert(sizeof(CharacterState) == 48);

/// One joint of one character, placed in the world.
struct JointWorld {
    glm::vec3 position{0.0F};                        ///< World position, metres.
    glm::quat orientation{1.0F, 0.0F, 0.0F, 0.0F};  ///< World orientation (yaw ∘ the baked orientation).
    float radius = 0.0F;                             ///< Sphere radius, metres: the clip's joint radius × scale.
};

/// Samples `joint` (0 <= joint < clip.jointCount()) of `clip` for `character`, as
/// shaders/pose.glsl does: the frame position clamped into [0, frameCount - 1]; nlerp on the
/// short arc of the rotations and lerp of the translations between the two frames around it
/// (BakedClip::sample); the translation times `character.scale`; a foot joint turned about its
/// ankle (sampled the same way) by the leg's footTwist, unless that is exactly 0; then the ground frame: a
/// rotation by the yaw about +Y and the ground frame's position. `character.clip` is not read:
/// the caller passes the clip it names.
[[nodiscard]] JointWorld sampleJointWorld(const motion::BakedClip& clip, const CharacterState& character, int joint);

}  // namespace throng::crowd
