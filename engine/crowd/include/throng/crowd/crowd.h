#pragma once
// Crowd state as a structure of arrays, its seeded spawning, the per-frame step, and the
// packing of every character into the contiguous CharacterState array the GPU reads.

#include <cstdint>
#include <span>
#include <vector>

#include "throng/core/error.h"
#include "throng/motion/baked_clip.h"

namespace throng::crowd {

/// One character as the GPU reads it (std430; mirrored in shaders/gpu_types.glsl).
struct CharacterState {
    glm::vec4 groundFrame{0.0F};  ///< xyz: world position of the ground frame (metres, y = 0); w: yaw (radians).
    std::uint32_t clip = 0;       ///< Index into the clip table.
    float frame = 0.0F;           ///< Frame position inside the clip's loop, fractional.
    float scale = 1.0F;           ///< Uniform body scale.
    std::uint32_t color = 0;      ///< RGBA8 (R in the low byte), linear colour.
};
static_assert(sizeof(CharacterState) == 32);

/// How to spawn the paper's simple crowd.
struct SpawnOptions {
    int count = 2000;             ///< Characters, >= 1.
    float spacing = 1.6F;         ///< Metres between neighbouring characters (jittered grid: no overlaps).
    float heading = 0.0F;         ///< Shared heading M_o in radians (0 walks toward +Z).
    std::uint64_t seed = 1;       ///< Same seed, same crowd.
};

/// Structure of arrays: one entry per character in every vector.
class Crowd {
public:
    /// The paper's crowd: jittered-grid positions centred on the origin, one shared heading,
    /// a random start frame inside each clip's loop, per-character colour and a small scale
    /// variation. Clips are assigned round-robin. Fails on a count < 1 or no clips.
    static Result<Crowd> spawnPaperCrowd(std::span<const motion::BakedClip> clips, const SpawnOptions& options);

    /// Advances every character by `seconds` of playback in the paper's group mode: each
    /// moves by the root-motion displacement of exactly the stretch of clip it played.
    void step(std::span<const motion::BakedClip> clips, double seconds);

    /// Writes one CharacterState per character into `out` (size() entries).
    void pack(std::span<CharacterState> out) const;

    [[nodiscard]] int size() const { return static_cast<int>(ground_.size()); }
    [[nodiscard]] const motion::GroundFrame& groundFrame(int i) const { return ground_[static_cast<std::size_t>(i)]; }
    [[nodiscard]] double frame(int i) const { return frame_[static_cast<std::size_t>(i)]; }
    [[nodiscard]] std::uint32_t clip(int i) const { return clip_[static_cast<std::size_t>(i)]; }

private:
    std::vector<motion::GroundFrame> ground_;  ///< World ground frame (position, yaw) of each character.
    std::vector<double> frame_;                ///< Frame position, wrapped into the clip's loop.
    std::vector<std::uint32_t> clip_;
    std::vector<float> speed_;                 ///< Playback speed multiplier.
    std::vector<float> scale_;
    std::vector<std::uint32_t> color_;
};

}  // namespace throng::crowd
