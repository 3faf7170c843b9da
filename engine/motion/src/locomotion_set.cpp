#include "throng/motion/locomotion_set.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace throng::motion {

std::optional<GaitClock> GaitClock::of(const BakedClip& clip) {
    if (clip.leftLeg < 0 || clip.isStatic) return std::nullopt;
    const std::vector<FootContact>& left = clip.footContacts[static_cast<std::size_t>(clip.leftLeg)];
    const LoopRange loop = clip.loop();
    if (left.empty() || loop.length() < 2) return std::nullopt;
    GaitClock clock;
    clock.loopLength_ = loop.length();
    for (const FootContact& contact : left) clock.strikes_.push_back(contact.strike);
    std::sort(clock.strikes_.begin(), clock.strikes_.end());
    clock.cycleSeconds_ = clock.loopLength_ * clip.frameTime / static_cast<double>(clock.strikes_.size());
    clock.cyclesPerSecond_ = 1.0 / clock.cycleSeconds_;
    clock.inverseLoopLength_ = 1.0 / clock.loopLength_;
    clock.inverseCycles_ = 1.0 / static_cast<double>(clock.strikes_.size());
    for (std::size_t j = 0; j < clock.strikes_.size(); ++j) {
        const double end = j + 1 < clock.strikes_.size() ? clock.strikes_[j + 1] : clock.strikes_.front() + clock.loopLength_;
        clock.inverseSpans_.push_back(1.0 / (end - clock.strikes_[j]));
    }
    return clock;
}

double LocomotionSet::slowest() const { return idle ? 0.0 : gaits.front().speed * kSlowestPlayback; }
double LocomotionSet::fastest() const { return gaits.back().speed * kFastestPlayback; }

Result<LocomotionSet> makeLocomotionSet(std::span<const BakedClip> clips, std::span<const std::uint32_t> members) {
    const auto fail = [](std::string message) { return Error{Error::Kind::BadInput, std::move(message), {}}; };
    if (members.empty()) return fail("a locomotion set needs at least one clip");
    for (std::uint32_t c : members)
        if (c >= clips.size()) return fail("a locomotion set names clip " + std::to_string(c) + ", which doesn't exist");
    const BakedClip& first = clips[members.front()];
    // Above this a clip with no gait is travelling, not standing: it can't be timed by phase.
    constexpr double kStandingSpeed = 0.3;
    LocomotionSet set;
    for (std::uint32_t c : members) {
        const BakedClip& clip = clips[c];
        if (clip.jointNames != first.jointNames)
            return fail("locomotion set: " + clip.name + " has a different skeleton from " + first.name + " (" +
                        std::to_string(clip.jointCount()) + " vs " + std::to_string(first.jointCount()) +
                        " joints, or other names): a set blends clips of one skeleton");
        std::optional<GaitClock> gait = GaitClock::of(clip);
        if (!gait) {
            if (clip.speed >= kStandingSpeed)
                return fail("locomotion set: " + clip.name + " travels at " + std::to_string(clip.speed) +
                            " m/s but shows no gait (the left foot never strikes in its loop), so it can't be phase-aligned");
            if (set.idle)
                return fail("locomotion set: " + clip.name + " and " + clips[set.idle->clip].name +
                            " both stand (no gait): a set has at most one idle");
            set.idle = LocomotionClip{c, 0.0, std::nullopt};
            continue;
        }
        if (!(clip.speed >= kStandingSpeed))
            return fail("locomotion set: " + clip.name + " shows a gait but travels at " + std::to_string(clip.speed) +
                        " m/s (walking in place?): a set's gaits must travel for their speeds to blend");
        set.gaits.push_back({c, clip.speed, std::move(gait)});
    }
    if (set.gaits.empty()) return fail("locomotion set: no clip shows a gait (a walk or a run); an idle alone can't travel");
    // By speed, through an index (sorting the clips themselves moves their clocks about, where
    // GCC 12 sees uninitialised vectors that aren't).
    std::vector<std::size_t> bySpeed(set.gaits.size());
    for (std::size_t k = 0; k < bySpeed.size(); ++k) bySpeed[k] = k;
    std::stable_sort(bySpeed.begin(), bySpeed.end(), [&](std::size_t a, std::size_t b) { return set.gaits[a].speed < set.gaits[b].speed; });
    std::vector<LocomotionClip> ordered;
    ordered.reserve(bySpeed.size());
    for (std::size_t k : bySpeed) ordered.push_back(std::move(set.gaits[k]));
    set.gaits = std::move(ordered);
    for (std::size_t k = 1; k < set.gaits.size(); ++k)
        if (!(set.gaits[k].speed > set.gaits[k - 1].speed * 1.05))
            return fail("locomotion set: " + clips[set.gaits[k - 1].clip].name + " and " + clips[set.gaits[k].clip].name +
                        " walk at nearly the same speed (" + std::to_string(set.gaits[k].speed) +
                        " m/s): a blend needs their speeds at least 5% apart");
    return set;
}

namespace {

// Gait cycles per second of a blend at weight w. From the idle the slowest gait keeps its own
// cadence and its steps shorten: slowing the cadence too slid the feet more (4.97 against 4.49
// cm per contact at 0.4 m/s, tests/quality/test_speed_blending_acceptance.cpp).
double cadence(const LocomotionClip& lower, const LocomotionClip& upper, double w) {
    const double up = upper.gait->cyclesPerSecond();
    if (!lower.gait) return up;
    // A division, not a product with cyclesPerSecond(): the product rounds differently, and the
    // crowd's results are kept to the bit across speed-ups (as are the stored reciprocals').
    return (1.0 - w) / lower.gait->cycleSeconds() + w * up;
}

// cadence at w = 0 (the lower clip's own, or the upper's from the idle), to the bit, without
// its division; at w = 1 it is upper.gait->cyclesPerSecond().
double lowerCadence(const LocomotionClip& lower, const LocomotionClip& upper) {
    return lower.gait ? lower.gait->cyclesPerSecond() : upper.gait->cyclesPerSecond();
}

// Metres per gait cycle at playback 1 (the idle's is 0). The blend's natural ground speed at
// weight w is the blended stride times the blended cadence.
double stride(const LocomotionClip& clip) { return clip.gait ? clip.speed * clip.gait->cycleSeconds() : 0.0; }

// The weight at which the blend of neighbours `lower` and `upper` walks at v, for v between
// the blend's natural speeds at w = 0 and 1. Blended stride and cadence are both linear in w,
// so their product is a quadratic in w, rising on [0, 1]: solved in closed form (this runs for
// every character every step; a bisection here was half the crowd step's time), with the root
// taken in the form that doesn't cancel (the unit test holds the speed to 1e-9).
double weightForSpeed(const LocomotionClip& lower, const LocomotionClip& upper, double v) {
    const double lowerStride = stride(lower), upperStride = stride(upper);
    const double lowerRate = lowerCadence(lower, upper), upperRate = upper.gait->cyclesPerSecond();
    // (s0 + w ds)(c0 + w dc) = v  ->  a w² + b w + c = 0
    const double ds = upperStride - lowerStride, dc = upperRate - lowerRate;
    const double a = ds * dc, b = lowerStride * dc + lowerRate * ds, c = lowerStride * lowerRate - v;
    double w = 0.0;
    if (std::abs(a) <= 1e-12 * std::abs(b)) {
        w = -c / b;
    } else {
        const double q = -0.5 * (b + std::copysign(std::sqrt(std::max(b * b - 4.0 * a * c, 0.0)), b));
        const double r1 = q / a, r2 = c / q;
        w = (r1 >= -1e-9 && r1 <= 1.0 + 1e-9) ? r1 : r2;
    }
    return std::clamp(w, 0.0, 1.0);
}

}  // namespace

SpeedBlend blendForSpeed(const LocomotionSet& set, double speed) {
    const double v = std::clamp(std::isfinite(speed) ? speed : 0.0, set.slowest(), set.fastest());
    const LocomotionClip& slowestGait = set.gaits.front();
    const LocomotionClip& fastestGait = set.gaits.back();
    // Past either end of the gaits: that gait alone, its playback stretched.
    const auto alone = [](const LocomotionClip& clip, double playback) {
        return SpeedBlend{&clip, &clip, 0.0, playback, playback / clip.gait->cycleSeconds()};
    };
    if (v >= fastestGait.speed) return alone(fastestGait, v / fastestGait.speed);
    if (v <= slowestGait.speed && !set.idle) return alone(slowestGait, v / slowestGait.speed);
    const LocomotionClip* lower = set.idle ? &*set.idle : &slowestGait;
    const LocomotionClip* upper = &slowestGait;
    for (std::size_t k = 0; k < set.gaits.size(); ++k)
        if (set.gaits[k].speed > v || (k + 1 == set.gaits.size())) {
            upper = &set.gaits[k];
            lower = k == 0 ? (set.idle ? &*set.idle : upper) : &set.gaits[k - 1];
            break;
        }
    if (lower == upper) return alone(*upper, v / upper->speed);
    const double lowerRate = lowerCadence(*lower, *upper);
    if (v <= stride(*lower) * lowerRate) return {lower, upper, 0.0, 1.0, lowerRate};  // at or below the speed at w = 0
    const double w = weightForSpeed(*lower, *upper, v);
    return {lower, upper, w, 1.0, cadence(*lower, *upper, w)};
}

}  // namespace throng::motion
