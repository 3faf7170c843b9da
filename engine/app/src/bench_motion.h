#pragma once
// What a benchmark's characters played: the shares of its timed frames that mixed clips, and
// the caption and JSON fields that name the motion.

#include <cstdint>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "throng/app/cli.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/baked_clip.h"

namespace throng::app {

/// How much of the timed motion mixed clips: per character and timed frame, whether its pose
/// blended two clips of a set (0 < blend < 1) and whether a transition's outgoing clip showed
/// (0 < fromWeight < 1). A scene meant to time blends and transitions shows here that it did.
class MotionShares {
public:
    void count(const crowd::Crowd& crowd) {
        for (int i = 0; i < crowd.size(); ++i) {
            blending_ += inUse(crowd.blendWeight(i)) ? 1 : 0;
            fading_ += inUse(crowd.fromWeight(i)) ? 1 : 0;
        }
        samples_ += crowd.size();
    }
    [[nodiscard]] double blend() const { return share(blending_); }
    [[nodiscard]] double transition() const { return share(fading_); }

private:
    static bool inUse(float weight) { return weight > 0.0F && weight < 1.0F; }
    [[nodiscard]] double share(std::int64_t part) const { return samples_ > 0 ? static_cast<double>(part) / static_cast<double>(samples_) : 0.0; }
    std::int64_t samples_ = 0, blending_ = 0, fading_ = 0;
};

/// What the characters played, for the caption and the JSON header: a figure of blending
/// characters must never pass for one of the single walk.
struct MotionNote {
    std::string caption;  ///< "motion: walk.bvh, each clip as it is" or "motion: blend of 4 clips (...) at 1-1.6 m/s"
    /// "motion" ("clips", "blend" or "scene"), "clips" (their files), "ground_speed" ([min, max]
    /// m/s of a blend, else null), "scene" (the --scene file, or null).
    nlohmann::ordered_json fields;
};

[[nodiscard]] MotionNote describeMotion(const BenchCommand& command, std::span<const motion::BakedClip> clips);

}  // namespace throng::app
