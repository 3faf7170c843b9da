#include "throng/crowd/crowd.h"

#include <algorithm>
#include <cmath>

#include "throng/core/rng.h"

namespace throng::crowd {
namespace {

// Pleasant, distinguishable clothing colours: hue spread evenly, moderate saturation.
std::uint32_t characterColor(Rng& rng) {
    const float hue = rng.uniform() * 6.0F;
    const float saturation = rng.uniform(0.55F, 0.85F), value = rng.uniform(0.6F, 0.95F);
    const float c = value * saturation, x = c * (1.0F - std::abs(std::fmod(hue, 2.0F) - 1.0F)), m = value - c;
    glm::vec3 rgb;
    switch (static_cast<int>(hue)) {
        case 0: rgb = {c, x, 0}; break;
        case 1: rgb = {x, c, 0}; break;
        case 2: rgb = {0, c, x}; break;
        case 3: rgb = {0, x, c}; break;
        case 4: rgb = {x, 0, c}; break;
        default: rgb = {c, 0, x}; break;
    }
    rgb += m;
    const auto byte = [](float v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0F, 1.0F) * 255.0F)); };
    return byte(rgb.r) | (byte(rgb.g) << 8U) | (byte(rgb.b) << 16U) | (255U << 24U);
}

}  // namespace

Result<Crowd> Crowd::spawnPaperCrowd(std::span<const motion::BakedClip> clips, const SpawnOptions& options) {
    if (clips.empty()) return Error{Error::Kind::BadInput, "a crowd needs at least one clip", {}};
    if (options.count < 1)
        return Error{Error::Kind::BadInput, "the crowd needs at least one character, got " + std::to_string(options.count), {}};
    Rng rng(options.seed);
    Crowd crowd;
    const auto count = static_cast<std::size_t>(options.count);
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(options.count))));
    const int rows = (options.count + columns - 1) / columns;
    const float jitter = 0.25F * options.spacing;  // keeps neighbours at least half a spacing apart
    for (std::size_t i = 0; i < count; ++i) {
        const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
        const float x = (static_cast<float>(column) - 0.5F * static_cast<float>(columns - 1)) * options.spacing + rng.uniform(-jitter, jitter);
        const float z = (static_cast<float>(row) - 0.5F * static_cast<float>(rows - 1)) * options.spacing + rng.uniform(-jitter, jitter);
        const std::uint32_t clip = static_cast<std::uint32_t>(i % clips.size());
        const motion::LoopRange loop = clips[clip].loop();
        crowd.ground_.push_back({{x, z}, options.heading});
        crowd.frame_.push_back(static_cast<double>(loop.first) + static_cast<double>(rng.uniform()) * std::max(loop.length(), 0));
        crowd.clip_.push_back(clip);
        crowd.speed_.push_back(1.0F);
        crowd.scale_.push_back(rng.uniform(0.95F, 1.05F));
        crowd.color_.push_back(characterColor(rng));
    }
    return crowd;
}

void Crowd::step(std::span<const motion::BakedClip> clips, double seconds) {
    for (std::size_t i = 0; i < ground_.size(); ++i) {
        const motion::BakedClip& clip = clips[clip_[i]];
        const double from = frame_[i];
        const double to = from + seconds / clip.frameTime * speed_[i];
        // Paper: C_{i+1} = C_i + M_o (p0^i - p0^{i-1}); composing ground frames is that update,
        // with the clip's own turning included and the loop seam continued (see RootMotionTrack).
        const motion::GroundFrame delta = clip.rootMotion.delta(from, to);
        ground_[i] = ground_[i].then({delta.position * static_cast<double>(scale_[i]), delta.yaw});
        frame_[i] = clip.rootMotion.wrap(to);
    }
}

void Crowd::pack(std::span<CharacterState> out) const {
    for (std::size_t i = 0; i < ground_.size(); ++i) {
        const motion::GroundFrame& g = ground_[i];
        out[i] = {glm::vec4(static_cast<float>(g.position.x), 0.0F, static_cast<float>(g.position.y), static_cast<float>(g.yaw)),
                  clip_[i], static_cast<float>(frame_[i]), scale_[i], color_[i]};
    }
}

}  // namespace throng::crowd
