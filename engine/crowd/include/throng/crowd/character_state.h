#pragma once
// One character as the GPU reads it, and joint sampling: the one C++ definition of where a
// character's joint is in the world. It mirrors shaders/pose.glsl step for step, in float and
// in the same order, so the cpu render path and the GPU tests' checker agree with the shaders
// (to the last bits of the GPU's own cos, sin and mix: about 1e-7 of the body's height).

#include <cstdint>
#include <span>

#include "throng/core/math.h"
#include "throng/motion/baked_clip.h"

namespace throng::crowd {

/// One character as the GPU reads it (std430; `CharacterGpu` in shaders/gpu_types.glsl).
/// Its pose is up to three clip samples: `clip` at `frame`, blended toward `blendClip` at
/// `blendFrame` by `blend` (speed blending: two clips of a locomotion set at the same gait
/// phase), then that toward `fromClip` at `fromFrame` by `fromWeight` (a crossfade from what
/// the character played before). A weight of exactly 0 leaves its clip unread.
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
    std::uint32_t blendClip = 0;  ///< The second clip of a speed blend (same skeleton as `clip`).
    float blendFrame = 0.0F;      ///< Its frame position.
    float blend = 0.0F;           ///< Weight of blendClip, 0..1; 0: `clip` alone.
    std::uint32_t fromClip = 0;   ///< A transition's outgoing clip (same skeleton).
    float fromFrame = 0.0F;       ///< Its frame position.
    float fromWeight = 0.0F;      ///< Weight of fromClip over the blend, 0..1, falling to 0 as the transition ends.
};
static_assert(sizeof(CharacterState) == 64);

/// One joint of one character, placed in the world.
struct JointWorld {
    glm::vec3 position{0.0F};                        ///< World position, metres.
    glm::quat orientation{1.0F, 0.0F, 0.0F, 0.0F};  ///< World orientation (yaw ∘ the baked orientation).
    float radius = 0.0F;                             ///< Sphere radius, metres: the clip's joint radius × scale.
};

/// Samples `joint` (0 <= joint < the clip's jointCount()) for `character`, as
/// shaders/pose.glsl does. Each clip sample (BakedClip::sample) takes the frame position
/// clamped into [0, frameCount - 1], nlerp on the short arc of the rotations and lerp of the
/// translations between the two frames around it. The blend and the transition mix those
/// samples the same way (nlerp, lerp) by their weights, skipping a clip whose weight is
/// exactly 0 or whose joint count differs. Then the translation times `character.scale`; a
/// foot joint turned about its ankle (sampled the same way) by the leg's footTwist, unless that
/// is exactly 0; then the ground frame: a rotation by the yaw about +Y and the ground frame's
/// position. `clips` is the table the character's clip indices name.
[[nodiscard]] JointWorld sampleJointWorld(std::span<const motion::BakedClip> clips, const CharacterState& character, int joint);

}  // namespace throng::crowd
