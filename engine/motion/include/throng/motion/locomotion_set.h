#pragma once
// Locomotion sets: clips of one skeleton at different natural speeds (an idle, walks, runs)
// that a character blends by speed, each with a gait clock that aligns them by gait phase
// (Kovar & Gleicher 2003: blended clips must be registered in time, or the feet argue).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "throng/core/error.h"
#include "throng/motion/baked_clip.h"

namespace throng::motion {

/// A clip's gait as a clock. Gait time counts cycles: 0 at a left heel strike, each next left
/// strike one more, linear in frames between strikes, and endless (the clip's loop repeats).
/// A loop holds `cycles()` of them.
class GaitClock {
public:
    /// nullopt when the clip's left foot never strikes inside its loop (no gait).
    [[nodiscard]] static std::optional<GaitClock> of(const BakedClip& clip);

    [[nodiscard]] int cycles() const { return static_cast<int>(strikes_.size()); }
    /// Seconds per gait cycle at playback 1: the loop's duration over its cycles.
    [[nodiscard]] double cycleSeconds() const { return cycleSeconds_; }
    /// 1 / cycleSeconds(), stored: blendForSpeed runs for every blending character each step.
    [[nodiscard]] double cyclesPerSecond() const { return cyclesPerSecond_; }
    /// Gait time of an unwrapped frame position (monotonic, continuous).
    [[nodiscard]] double cyclesAt(double frame) const {
        // Cycle j (any integer) starts at strikes_[j mod m] + loopLength_ * floor(j / m) and ends
        // where cycle j + 1 starts; gait time is linear in frames inside it. Inline, with
        // fastFloor and stored reciprocals (a division's latency is four multiplications'):
        // the crowd step calls these for every blending character. A product that rounds a hair
        // past a loop's edge lands on the same gait time through the clamp.
        if (!std::isfinite(frame)) return 0.0;
        const double loops = fastFloor((frame - strikes_.front()) * inverseLoopLength_);
        const double inLoop = frame - loops * loopLength_;  // in [strikes_[0], strikes_[0] + loopLength_), to rounding
        // One cycle a loop: the sum below with m = 1 and j = 0, to the bit.
        if (strikes_.size() == 1) return loops + std::clamp((inLoop - strikes_.front()) * inverseSpans_.front(), 0.0, 1.0);
        std::size_t j = strikes_.size() - 1;
        while (j > 0 && inLoop < strikes_[j]) --j;
        return loops * static_cast<double>(strikes_.size()) + static_cast<double>(j) + std::clamp((inLoop - strikes_[j]) * inverseSpans_[j], 0.0, 1.0);
    }
    /// The unwrapped frame position at gait time `cycles`: cyclesAt's inverse.
    [[nodiscard]] double frameAt(double cycles) const {
        const auto m = static_cast<double>(strikes_.size());
        if (!std::isfinite(cycles)) return strikes_.front();
        const double whole = fastFloor(cycles);
        if (strikes_.size() == 1) {
            // One cycle a loop (every clip of the project's set): the loop count is `whole`, as
            // divideWhole gives it, with nothing to divide; `end - start` as below, not
            // loopLength_, which differs from it in the last bit.
            const double start = strikes_.front(), end = start + loopLength_;
            return whole * loopLength_ + start + (cycles - whole) * (end - start);
        }
        const auto [loops, inCycle] = divideWhole(whole, m, inverseCycles_);
        const auto j = static_cast<std::size_t>(std::clamp(inCycle, 0.0, m - 1.0));
        const double start = strikes_[j];
        const double end = j + 1 < strikes_.size() ? strikes_[j + 1] : strikes_.front() + loopLength_;
        return loops * loopLength_ + start + (cycles - whole) * (end - start);
    }

private:
    std::vector<double> strikes_;  ///< Left strikes in [first, first + loop length), ascending.
    double loopLength_ = 0.0;      ///< Frames.
    double cycleSeconds_ = 0.0, cyclesPerSecond_ = 0.0;
    double inverseLoopLength_ = 0.0, inverseCycles_ = 0.0;  ///< 1 / loopLength_, 1 / cycles().
    std::vector<double> inverseSpans_;  ///< Per cycle of the loop: 1 / its length in frames.
};

/// One clip of a set.
struct LocomotionClip {
    std::uint32_t clip = 0;            ///< Index into the crowd's clip table.
    double speed = 0.0;                ///< Natural ground speed, m/s at playback 1 (0 for the idle).
    std::optional<GaitClock> gait;     ///< nullopt for the idle only.
};

/// Clips of one skeleton a character blends by speed: an optional idle (standing, no gait)
/// and one or more gaits, slowest first.
struct LocomotionSet {
    std::optional<LocomotionClip> idle;
    std::vector<LocomotionClip> gaits;  ///< Ascending natural speed, at least one.

    /// The slowest and fastest ground speed the set can show, m/s at scale 1: from 0 (with an
    /// idle; else the slowest gait played at kSlowestPlayback) to the fastest gait played at
    /// kFastestPlayback.
    [[nodiscard]] double slowest() const;
    [[nodiscard]] double fastest() const;

    /// How far playback may stretch a blend from its natural rate: beyond them a gait looks
    /// like slow motion or a shuffle, so the set's speed range ends there.
    static constexpr double kSlowestPlayback = 0.85;
    static constexpr double kFastestPlayback = 1.2;
};

/// Checks and orders a set: every clip the same skeleton (joint count and names) as the
/// first; every clip a gait except at most one idle. A clip is the idle when it shows no gait
/// (GaitClock::of is empty) and travels slower than a stroll (under 0.3 m/s); a clip with no
/// gait that travels faster is refused, and so is one with a gait that doesn't travel (a walk
/// in place). Fails (BadInput)
/// with one line naming the clip at fault.
[[nodiscard]] Result<LocomotionSet> makeLocomotionSet(std::span<const BakedClip> clips, std::span<const std::uint32_t> members);

/// What a character plays at one ground speed: two clips of the set, the weight of the
/// second, and how fast its gait runs.
struct SpeedBlend {
    const LocomotionClip* lower = nullptr;  ///< Never null for a valid set.
    const LocomotionClip* upper = nullptr;  ///< The same as lower when the speed is at or past an end of the set.
    double weight = 0.0;                    ///< Of upper, 0..1.
    double playback = 1.0;                  ///< Stretch of the blend's natural rate, kSlowestPlayback..kFastestPlayback.
    double cyclesPerSecond = 0.0;           ///< Gait cycles per second of the gaits (stretch included); the idle keeps its own time.
};

/// The blend that walks at `speed` (m/s at scale 1, clamped into the set's range): the
/// neighbouring clips by natural speed and the weight whose blended stride times blended
/// cadence is `speed`; playback stretches only past the slowest or fastest gait.
[[nodiscard]] SpeedBlend blendForSpeed(const LocomotionSet& set, double speed);

}  // namespace throng::motion
