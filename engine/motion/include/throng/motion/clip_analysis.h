#pragma once
// Measurements on baked poses that the bake uses and tests check: unit inference, T-pose
// detection, gait period and loop detection. Pure functions over flat arrays.

#include <span>
#include <string>
#include <vector>

#include "throng/core/math.h"
#include "throng/motion/root_motion.h"

namespace throng::motion {

struct UnitGuess {
    double metresPerUnit = 1.0;
    const char* name = "metres";
};

/// Picks the length unit that makes `heightInFileUnits` a plausible human height
/// (~1.7 m): metres, centimetres, millimetres, inches, or CMU's ASF unit (0.056444 m).
[[nodiscard]] UnitGuess guessUnits(double heightInFileUnits);

/// In-place joint positions of one clip, frame-major: positions[f * joints + j].
struct PoseSeries {
    std::span<const glm::vec3> positions;
    int frames = 0;
    int joints = 0;
    [[nodiscard]] std::span<const glm::vec3> frame(int f) const {
        return positions.subspan(static_cast<std::size_t>(f) * joints, static_cast<std::size_t>(joints));
    }
};

/// Root-mean-square joint distance between two frames (metres when the series is).
[[nodiscard]] double poseDistance(const PoseSeries& poses, int a, int b);

/// True when frame 0 stands apart from the motion like the synthetic T-pose of the CMU
/// conversions: its distance to frame 1 is many times the clip's typical frame step.
[[nodiscard]] bool looksLikeSyntheticFirstFrame(const PoseSeries& poses);

/// Which frames belong to the clip's travelling part. A start-walk-stop capture stands still
/// at both ends, and standing frames match each other perfectly, so loop search must skip them.
struct TravelMask {
    std::vector<char> moving;   ///< Per frame: 1 if the root travels at >= half the clip's top speed.
    bool locomotion = false;    ///< The body makes at least 0.2 m/s over some 3 s (or the whole, shorter clip).
    double topSpeed = 0.0;      ///< Metres per second.
};

/// Builds the mask from the root's ground positions (metres). Frames before `firstFrame`
/// are never moving. A clip that is not locomotion has every later frame marked moving.
[[nodiscard]] TravelMask travelMask(std::span<const glm::dvec2> ground, double frameTime, int firstFrame);

/// Gait period in frames of a locomotion clip: the lag between 0.35 s and 1.8 s with the
/// smallest mean pose distance over travelling frames, if that minimum is clearly below the
/// typical distance and not at the 0.35 s bound; else 0 ("no gait").
[[nodiscard]] double estimateGaitPeriod(const PoseSeries& poses, double frameTime, const TravelMask& mask);

/// The loop [first, last] inside the travelling part, at least one gait period long (without
/// a gait: a third of the usable clip for locomotion, over half of it otherwise), whose
/// poses and velocities match best;
/// among near-ties, the longest. Falls back to the whole usable clip when it is too short.
[[nodiscard]] LoopRange detectLoop(const PoseSeries& poses, double gaitPeriod, int firstFrame, const TravelMask& mask);

}  // namespace throng::motion
