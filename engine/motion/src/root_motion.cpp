#include "throng/motion/root_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace throng::motion {

glm::dmat4 GroundFrame::matrix() const {
    glm::dmat4 m = glm::mat4_cast(yawQuat(yaw));
    m[3] = glm::dvec4(position.x, 0.0, position.y, 1.0);
    return m;
}

RootMotionTrack::RootMotionTrack(std::vector<GroundFrame> frames, LoopRange loop)
    : frames_(std::move(frames)), loop_(loop) {
    if (!frames_.empty())
        loopDisplacement_ = frames_[static_cast<std::size_t>(loop_.last)].then(
            frames_[static_cast<std::size_t>(loop_.first)].inverse());
}

double RootMotionTrack::wrap(double x) const {
    const double length = loop_.length();
    if (length <= 0 || !std::isfinite(x)) return loop_.first;
    // offset - floor(offset / length) * length rather than std::fmod (a slow libm call, and
    // the crowd step wraps every character's frames): rounding may land it a hair outside
    // [0, length), where one step folds it back; far from the loop (a huge x) the exact fmod.
    const double offset = x - loop_.first;
    double shifted = offset - fastFloor(offset / length) * length;
    if (shifted < 0.0) shifted += length;
    else if (shifted >= length) shifted -= length;
    if (!(shifted >= 0.0 && shifted < length)) {
        shifted = std::fmod(offset, length);
        if (shifted < 0.0) shifted += length;
    }
    return loop_.first + shifted;
}

GroundFrame RootMotionTrack::atLoop(double x) const {
    if (frames_.empty()) return {};
    const double length = loop_.length();
    // A frame position that is not finite has no place on the track (and converting it to a
    // loop count below would be undefined behaviour): it reads as the loop's start.
    if (!std::isfinite(x)) return frames_[static_cast<std::size_t>(loop_.first)];
    if (length <= 0) return interpolate(x);
    // x = first + loops · length + r with r in [0, length); each whole loop adds the loop
    // displacement on the world side, so at(x) = D^loops ∘ interpolate(first + r).
    const double loops = fastFloor((x - loop_.first) / length);
    const double inside = x - loops * length;
    GroundFrame result = interpolate(inside);
    if (loops == 0) return result;  // the common case, with no rotation to compose
    // |loops| <= |x| < 2^63 for any finite double x up to 9e18; beyond that it saturates.
    const auto count = clampedFloor<long long>(std::abs(loops), 0, std::numeric_limits<long long>::max());
    const GroundFrame step = loops >= 0 ? loopDisplacement_ : loopDisplacement_.inverse();
    // Compose by squaring so a huge jump costs O(log n), not O(n).
    GroundFrame power;  // identity
    GroundFrame base = step;
    for (long long n = count; n > 0; n >>= 1) {
        if (n & 1) power = power.then(base);
        base = base.then(base);
    }
    return power.then(result);
}

}  // namespace throng::motion
