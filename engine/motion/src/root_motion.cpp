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
    headings_.reserve(frames_.size());
    for (const GroundFrame& frame : frames_) headings_.emplace_back(std::cos(frame.yaw), std::sin(frame.yaw));
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

GroundFrame RootMotionTrack::delta(double from, double to) const {
    const GroundFrame end = at(to);
    if (!(loop_.length() > 0) || !(from >= loop_.first && from < loop_.last)) return at(from).to(end);
    const auto [lower, start, turn] = between(from);
    // Within a quarter radian (any capture at 30 fps or more turning under 7 rad/s) the
    // series below are exact to double precision; a wilder turn takes the library's.
    constexpr double kSeriesTurn = 0.25;
    if (!(std::abs(turn) <= kSeriesTurn)) return start.to(end);
    const double z = turn * turn;
    double cosTurn = 0.0, sinTurn = 0.0;
    if (z <= 1e-4) {
        // The usual case, under a hundredth of a radian: three terms are exact (the next are
        // under 1e-20), and a short chain of multiplications is what this costs.
        cosTurn = 1.0 + z * (-1.0 / 2 + z * (1.0 / 24 + z * (-1.0 / 720)));
        sinTurn = turn * (1.0 + z * (-1.0 / 6 + z * (1.0 / 120 + z * (-1.0 / 5040))));
    } else {
        cosTurn = 1.0 + z * (-1.0 / 2 + z * (1.0 / 24 + z * (-1.0 / 720 + z * (1.0 / 40320 + z * (-1.0 / 3628800 + z / 479001600)))));
        sinTurn = turn * (1.0 + z * (-1.0 / 6 + z * (1.0 / 120 + z * (-1.0 / 5040 + z * (1.0 / 362880 + z * (-1.0 / 39916800))))));
    }
    const glm::dvec2 heading = headings_[lower];  // cos and sin of the yaw of the frame below
    const double c = heading.x * cosTurn - heading.y * sinTurn, s = heading.y * cosTurn + heading.x * sinTurn;
    // rotateGround(d, -yaw): cos(-yaw) = c, sin(-yaw) = -s.
    const glm::dvec2 d = end.position - start.position;
    return {{c * d.x - s * d.y, s * d.x + c * d.y}, end.yaw - start.yaw};
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
