#pragma once
// Yardsticks for root-motion quality (issue #11), shared by tests and throng_motion_report:
// where a capture's joints really are (raw forward kinematics), where one character's joints
// are when the crowd plays the baked clip, and the figures that compare the two (planted-foot
// slide, bone-length spread, arc speed, stature). They are written apart from the bake on
// purpose: a figure that reused the bake's own contact or speed analysis could not catch that
// analysis being wrong.

#include <cstdint>
#include <span>
#include <vector>

#include "throng/core/error.h"
#include "throng/core/math.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/raw_motion.h"
#include "throng/motion/skeleton_anatomy.h"

namespace throng::quality {

/// Points (joints, optionally followed by End Sites) per frame, in metres, +Y up.
struct PointSeries {
    int frames = 0;
    int points = 0;                     ///< Per frame: joints, then End Sites when included.
    int joints = 0;                     ///< How many of the points are joints (the first ones); End Site i is point joints + i.
    double frameTime = 0.0;             ///< Seconds between frames.
    std::vector<int> parents;           ///< Per point, the point its bone hangs from; -1 for a root.
    std::vector<glm::dvec3> positions;  ///< frames × points, frame-major.

    [[nodiscard]] const glm::dvec3& at(int frame, int point) const {
        return positions[static_cast<std::size_t>(frame) * static_cast<std::size_t>(points) + static_cast<std::size_t>(point)];
    }
    /// One point's positions over frames [first, last] (last < 0: to the end).
    [[nodiscard]] std::vector<glm::dvec3> track(int point, int first = 0, int last = -1) const;
};

/// The capture's own forward kinematics (replace reading of position channels), scaled by
/// `metresPerUnit` and turned so that the file's `up` axis becomes +Y. With `endSites`, every
/// End Site follows the joints as point jointCount() + its index.
[[nodiscard]] PointSeries rawWorldPositions(const motion::RawMotion& motion, double metresPerUnit,
                                            motion::UpAxis up = motion::UpAxis::PlusY, bool endSites = false);

/// The same series with its End Sites left out (the joints alone, as baked clips have them).
[[nodiscard]] PointSeries withoutEndSites(const PointSeries& points);

/// The baked in-place table (BakedClip::poses translations), bones between baked joints only.
[[nodiscard]] PointSeries bakedInPlacePositions(const motion::BakedClip& clip);

/// One character played through crowd::Crowd.
struct Playback {
    PointSeries joints;                     ///< World joint positions, one frame per step (the spawn state first).
    std::vector<motion::GroundFrame> ground;  ///< The character's ground frame at the same instants.
    std::vector<double> clipFrames;         ///< The clip frame shown at each instant (fractional, inside the loop).
    double scale = 1.0;                     ///< The body scale the crowd drew (±5%): every length played is this times the clip's.
};

/// Plays one character of `clip` for `seconds` in steps of `dt` (<= 0: the clip's frame time),
/// spawned at the origin with a fixed seed, and samples every joint with crowd::sampleJointWorld
/// after each step. `mode` Group follows the clip's root motion (the paper's update); Goals walks
/// between waypoints: with `turning` the corners of a 6 m square (a 90° turn every few
/// seconds), else two points 500 m either side (a straight walk). Avoid plays as Goals would
/// with no one to avoid. Fails only if the crowd cannot spawn.
[[nodiscard]] Result<Playback> playback(const motion::BakedClip& clip, crowd::Mode mode, double seconds, double dt,
                                        bool turning);

/// When a foot point counts as planted, in fractions of stature. A height band alone is not
/// enough: a walking foot swings within 2-3 cm of its stance height just before heel strike
/// (toe clearance is about 2 cm), at 1-4 m/s, and those frames would swamp any slide.
struct ContactRule {
    double band = 0.03;   ///< Height within band × stature of the point's 5th-percentile height (about 5 cm).
    double speed = 0.2;   ///< And horizontal speed (over about 50 ms) below speed × stature per second (about 30 cm/s).
};

/// Per frame, 1 where the foot point is planted by `rule`, in runs of two frames or more.
[[nodiscard]] std::vector<char> plantedFrames(std::span<const glm::dvec3> foot, double frameTime, double stature,
                                              const ContactRule& rule = {});

/// Per playback step, 1 where the clip frame nearest the one it shows (`clipFrames`,
/// fractional) is planted in `clipPlanted` (per clip frame): the capture's own contacts, so
/// that slide the engine adds is measured in full rather than gated away by speed.
[[nodiscard]] std::vector<char> plantedAtClipFrames(std::span<const char> clipPlanted, std::span<const double> clipFrames);

/// How much a planted foot point moves over the ground.
struct Slide {
    double cmPerSecond = 0.0;    ///< Mean horizontal speed over the measured planted frames, cm/s.
    int contacts = 0;            ///< Runs of consecutive planted frames.
    double cmPerContact = 0.0;   ///< Mean horizontal path length within one contact, cm.
    int plantedFrames = 0;       ///< Frames in contact.
    int measuredFrames = 0;      ///< Planted frames with both neighbours planted (and included): the speed's sample.
};

/// Slide of one foot point whose positions per frame are `foot`, over the frames `planted`
/// marks. Speed is by central differences, over frames whose neighbours are both planted and,
/// when `include` is given (one entry per frame), that it marks nonzero.
[[nodiscard]] Slide slideOver(std::span<const glm::dvec3> foot, double frameTime, std::span<const char> planted,
                              std::span<const char> include = {});

/// Per frame, the horizontal speed (m/s, central difference) of a planted frame whose
/// neighbours are planted too, as slideOver() samples it; NaN on every other frame.
[[nodiscard]] std::vector<double> plantedSpeeds(std::span<const glm::dvec3> foot, double frameTime, std::span<const char> planted);

/// slideOver() with the frames plantedFrames() finds on `foot` itself.
[[nodiscard]] Slide plantedSlide(std::span<const glm::dvec3> foot, double frameTime, double stature,
                                 std::span<const char> include = {}, const ContactRule& rule = {});

/// The worst bone-length change over the sequence, two ways: against stature (what a tolerance
/// on the whole body wants) and against the bone's own length (what the eye sees on a short
/// bone such as foot-toe).
struct BoneSpread {
    double metres = 0.0;    ///< max − min length of the worst bone over frames.
    double fraction = 0.0;  ///< `metres` over the stature passed in.
    int point = -1;         ///< The worst bone's lower point (its parent is the other end); -1 if none.
    double relative = 0.0;  ///< The largest (max − min) / mean length among bones of at least 2% of stature.
    int relativePoint = -1; ///< That bone's lower point; -1 if none.
};
[[nodiscard]] BoneSpread boneLengthSpread(const PointSeries& points, double stature);

/// Horizontal speed along a ground path (x, z per frame, metres): the path is smoothed with a
/// centred 1 s moving average (shorter at the ends), and its length over frames [first, last]
/// (last < 0: to the end) is divided by their duration. m/s; 0 for fewer than two frames.
[[nodiscard]] double arcSpeed(std::span<const glm::dvec2> path, double frameTime, int first = 0, int last = -1);

/// One point's ground path (x, z) over frames [first, last] (last < 0: to the end).
[[nodiscard]] std::vector<glm::dvec2> groundPath(const PointSeries& points, int point, int first = 0, int last = -1);

/// Stature measured on raw positions that include End Sites: a quantile over frames [first,
/// last] of the head's top (its End Site, else the head joint) minus the lowest sole; without a
/// recognised biped, of each frame's vertical extent. The median (0.5) is issue #11's
/// definition; a higher quantile reads nearer the upright height on clips that crouch.
[[nodiscard]] double measuredStature(const PointSeries& withEndSites, const motion::Anatomy& anatomy, double quantile = 0.5,
                                     int first = 0, int last = -1);

/// Fraction of all point samples whose height is below `height` (metres).
[[nodiscard]] double fractionBelow(const PointSeries& points, double height);

/// Per frame, 1 where the ground frame turns faster than `radiansPerSecond` (central differences).
[[nodiscard]] std::vector<char> turningFrames(std::span<const motion::GroundFrame> ground, double frameTime,
                                              double radiansPerSecond);

/// The foot points whose slide the report gives: each leg's ankle and toe (when it has one).
[[nodiscard]] std::vector<int> footPoints(const motion::Anatomy& anatomy);

}  // namespace throng::quality
