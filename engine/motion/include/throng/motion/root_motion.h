#pragma once
// The root-motion track: where the character's ground frame is at every frame of a clip,
// so that baked poses can be stored in place and the crowd moves characters by exactly the
// stretch of clip they played (the paper's C_{i+1} = C_i + M_o (p0^i - p0^{i-1})).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "throng/core/math.h"

namespace throng::motion {

/// A rigid transform of the ground plane: rotate by `yaw` about +Y, then translate by
/// `position` (x, z). Lengths in metres, yaw in radians (0 faces +Z, see core/math.h).
struct GroundFrame {
    glm::dvec2 position{0.0};  ///< (x, z) in metres.
    double yaw = 0.0;          ///< Radians, not wrapped (tracks are unwrapped, so yaw interpolates).

    /// This frame followed by `local` expressed in it: (this ∘ local).
    [[nodiscard]] GroundFrame then(const GroundFrame& local) const {
        return {position + rotateGround(local.position, yaw), yaw + local.yaw};
    }
    [[nodiscard]] GroundFrame inverse() const { return {-rotateGround(position, -yaw), -yaw}; }
    /// `other` expressed in this frame: inverse().then(other), with one rotation instead of two
    /// (the crowd step takes a few of these per character).
    [[nodiscard]] GroundFrame to(const GroundFrame& other) const {
        return {rotateGround(other.position - position, -yaw), other.yaw - yaw};
    }
    /// Maps a ground point (x, z) from this frame's local coordinates to its parent's.
    [[nodiscard]] glm::dvec2 apply(glm::dvec2 local) const { return position + rotateGround(local, yaw); }
    /// As a 3D matrix (Y untouched).
    [[nodiscard]] glm::dmat4 matrix() const;
};

/// Inclusive frame pair [first, last] whose poses match: playback covers frames
/// first .. last-1 and then continues at `first`, which stands in for `last`.
struct LoopRange {
    int first = 0;
    int last = 0;  ///< > first when the clip has two frames or more.
    [[nodiscard]] int length() const { return last - first; }
};

/// Per-frame ground frames of a clip plus its loop, giving a ground frame for any
/// *unwrapped* frame position: playing past `last` continues from `first` transformed by the
/// loop's own displacement, so motion across the wrap is a continuation, never a jump back.
class RootMotionTrack {
public:
    RootMotionTrack() = default;
    RootMotionTrack(std::vector<GroundFrame> frames, LoopRange loop);

    /// Ground frame at unwrapped frame position `x` (frames; fractional allowed). Inside
    /// [first, last] it interpolates the track; outside, it repeats the loop.
    [[nodiscard]] GroundFrame at(double x) const {
        // Inline for the common case, a position inside the loop's first pass (the crowd step
        // reads a few per character); atLoop() repeats the loop for the rest.
        const double length = loop_.length();
        if (!(length > 0) || !(x >= loop_.first && x < loop_.last)) return atLoop(x);
        return interpolate(x);
    }
    /// Motion from position `from` to position `to`, expressed in the ground frame at `from`:
    /// at(from).to(at(to)), to within 1e-15 of a metre. The crowd step takes two per blending
    /// character, so the rotation's cosine and sine come without a libm call where it can
    /// (`from` inside the loop's first pass, as wrapped positions are): from the stored ones of
    /// the frame before and a short series for the little turn since.
    [[nodiscard]] GroundFrame delta(double from, double to) const;
    /// Folds `x` into [first, last): the frame whose pose is shown at unwrapped position x.
    [[nodiscard]] double wrap(double x) const;

    /// The transform one loop adds: at(x + length) = loopDisplacement ∘ ... (see at()).
    [[nodiscard]] const GroundFrame& loopDisplacement() const { return loopDisplacement_; }
    [[nodiscard]] const LoopRange& loop() const { return loop_; }
    [[nodiscard]] const std::vector<GroundFrame>& frames() const { return frames_; }

private:
    [[nodiscard]] GroundFrame atLoop(double x) const;
    /// Where position x falls on the track: the frame below it and how far (0..1) toward the
    /// next; the ground frame there, and the turn since the frame below.
    struct Between {
        std::size_t lower = 0;
        GroundFrame frame;
        double turn = 0.0;
    };
    [[nodiscard]] Between between(double x) const {
        const std::size_t last = frames_.size() - 1;
        const auto lower = clampedFloor<std::size_t>(x, 0, last);  // NaN reads as frame 0
        const std::size_t upper = std::min(lower + 1, last);
        const double fraction = x - static_cast<double>(lower);
        const double t = fraction > 0.0 ? std::min(fraction, 1.0) : 0.0;
        const GroundFrame& a = frames_[lower];
        const GroundFrame& b = frames_[upper];
        const double turn = (b.yaw - a.yaw) * t;
        return {lower, {glm::mix(a.position, b.position, t), a.yaw + turn}, turn};
    }
    [[nodiscard]] GroundFrame interpolate(double x) const { return between(x).frame; }

    std::vector<GroundFrame> frames_;
    std::vector<glm::dvec2> headings_;  ///< Per frame: cos and sin of its yaw.
    LoopRange loop_;
    GroundFrame loopDisplacement_;  ///< frames_[last] ∘ frames_[first]^-1, in world terms.
};

}  // namespace throng::motion
