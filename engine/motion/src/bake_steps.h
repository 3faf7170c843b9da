#pragma once
// The bake's steps, private to the motion module. bake.cpp runs them in order:
//   globals (file units) → up axis → stature and units → ground path (pelvis, heading)
//   → in-place poses → loop → joint-space loop closing → contacts, foot lock and pivots.
// Poses between steps are double precision, in metres, relative to each frame's ground frame.

#include <array>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "throng/motion/baked_clip.h"

namespace throng::motion::bake_steps {

/// Every joint's global orientation and position per frame, frame-major.
struct PoseTable {
    int frames = 0;
    int joints = 0;
    std::vector<glm::dquat> rotation;
    std::vector<glm::dvec3> position;

    PoseTable(int frameCount, int jointCount)
        : frames(frameCount), joints(jointCount),
          rotation(static_cast<std::size_t>(frameCount) * static_cast<std::size_t>(jointCount)),
          position(rotation.size()) {}
    [[nodiscard]] std::size_t index(int f, int j) const {
        return static_cast<std::size_t>(f) * static_cast<std::size_t>(joints) + static_cast<std::size_t>(j);
    }
    glm::dquat& rot(int f, int j) { return rotation[index(f, j)]; }
    glm::dvec3& pos(int f, int j) { return position[index(f, j)]; }
    [[nodiscard]] const glm::dquat& rot(int f, int j) const { return rotation[index(f, j)]; }
    [[nodiscard]] const glm::dvec3& pos(int f, int j) const { return position[index(f, j)]; }
};

// ---- up axis (up_axis.cpp) ----

/// Where a skeleton point is in one frame's globals (`frame` holds every joint): a joint
/// (`point.second` < 0) or the End Site `point.second` below joint `point.first`.
[[nodiscard]] glm::dvec3 pointAt(const glm::dmat4* frame, const RawMotion& motion, std::pair<int, int> point);

/// The value at `fraction` (0..1) of the sorted values, 0 for none: the rank rounded down
/// (a low percentile stays at or below its fraction) or to the nearest (of two frames, the
/// 90th percentile is the higher).
enum class Rank : std::uint8_t { Below, Nearest };
[[nodiscard]] double percentile(std::vector<double> values, double fraction, Rank rank = Rank::Below);

/// The rotation that turns a file whose up is `axis` into Throng's +Y up.
[[nodiscard]] glm::dmat4 toYUp(UpAxis axis);
/// Up axis from gravity: over the clip, the spine's joints sit above the legs' joints. Reads
/// `globals` (file axes); nullopt when the skeleton is no biped.
[[nodiscard]] std::optional<UpAxis> detectUpAxis(std::span<const glm::dmat4> globals, int joints, const Anatomy& anatomy);

/// Stature in file units (globals already Y-up): head-top minus the lowest sole as the body
/// stands upright (the 90th percentile over frames), or the same of the whole skeleton's
/// vertical extent when no biped was recognised.
[[nodiscard]] double uprightStature(std::span<const glm::dmat4> globals, const RawMotion& motion, const Anatomy& anatomy);

// ---- ground path (ground_path.cpp) ----

/// The ground path: the travel joint's track, smoothed over about a second, with the body's
/// smoothed heading. Positions in metres.
struct GroundPath {
    std::vector<GroundFrame> frames;
};

/// Raw per-frame heading of the body (unwrapped radians): from the hips' left-right axis when
/// the skeleton is a biped (the sign chosen once so the feet point forward), else from the
/// travel joint's +Z axis.
[[nodiscard]] std::vector<double> bodyHeading(std::span<const glm::dmat4> globals, int joints, const Anatomy& anatomy,
                                              int travelJoint, const RawMotion& motion);
/// Centred moving average over `seconds`, from `begin` on (earlier frames keep their value).
[[nodiscard]] std::vector<double> smoothed(const std::vector<double>& values, int begin, double frameTime, double seconds);
/// The path: travel joint (x, z) × scale, smoothed over `seconds` (about a gait cycle by
/// default, which drops the body's sway), with the given heading.
[[nodiscard]] std::vector<GroundFrame> groundPath(std::span<const glm::dmat4> globals, int joints, int travelJoint, double scale,
                                                  const std::vector<double>& heading, int begin, double frameTime, double seconds = 1.0);
/// The same path bent straight: heading held at the loop's start, positions advanced along it
/// by the path's own arc length.
[[nodiscard]] std::vector<GroundFrame> straightened(const std::vector<GroundFrame>& path, LoopRange loop);
/// Arc length of `path` over frames [first, last], metres.
[[nodiscard]] double arcLength(const std::vector<GroundFrame>& path, int first, int last);

// ---- poses (bake.cpp) ----

/// Joints above the travel joint (a static exporter ROOT) ride on it: they get its pose, so
/// no sphere is left behind at the origin and no bone stretches between them.
[[nodiscard]] PoseTable inPlacePoses(std::span<const glm::dmat4> globals, int joints, double scale,
                                     const std::vector<GroundFrame>& path, const std::vector<int>& parents, int travelJoint);

// ---- loop closing (loop_closing.cpp) ----

/// Closes the loop in joint space: each joint's local rotation (and the local translation of
/// joints whose translation moves, the travel joint's above all) is corrected by a share of
/// its seam mismatch that grows over the loop, and forward kinematics recomposes the poses,
/// so every bone keeps its length. Returns the largest joint distance it had to absorb.
double closeLoopInJointSpace(PoseTable& poses, const std::vector<int>& parents, const std::vector<char>& movingTranslation,
                             LoopRange loop);

// ---- feet (foot_lock.cpp) ----

/// The runs of a cycle of `length` steps where `down(k)` holds, each as (first, last) unrolled
/// from a step where it doesn't, so a run across the cycle's end is one run: first <= last, and
/// steps past the end wrap (take them modulo `length`). `down` is asked for k in [0, 2 length).
/// nullopt when `down` holds on every step: such a cycle has no run with ends.
template <typename Down>
[[nodiscard]] std::optional<std::vector<std::pair<int, int>>> cyclicRuns(int length, const Down& down) {
    int start = 0;  // a step outside every run to unroll the cycle from
    while (start < length && down(start)) ++start;
    if (start == length) return std::nullopt;
    std::vector<std::pair<int, int>> runs;
    for (int k = start; k < start + length; ++k) {
        if (!down(k)) continue;
        int end = k;
        while (end + 1 < start + length && down(end + 1)) ++end;
        runs.emplace_back(k, end);
        k = end;
    }
    return runs;
}

struct FootPlan {
    std::vector<std::uint8_t> contacts;  ///< Per frame, bit per leg.
    std::vector<glm::vec2> pivots;       ///< Per frame, ground-frame (x, z).
    std::vector<float> turnFreedom;      ///< Per frame, 0..1 (BakedClip::turnFreedom).
    std::vector<glm::vec2> hold;         ///< Per frame, how firmly each leg's foot is held, 0..1 (BakedClip::footHold).
};

/// Per leg and loop step (frame first + k), whether the ankle and the toe are planted: near
/// their lowest and slower than 0.2 statures per second. Read from the capture before loop
/// closing, whose drift would otherwise hide contacts. Empty where there is no such joint.
struct PlantedFeet {
    std::array<std::vector<char>, 2> ankle;
    std::array<std::vector<char>, 2> toe;
};
[[nodiscard]] PlantedFeet findPlantedFeet(const PoseTable& poses, const std::vector<GroundFrame>& path, const Anatomy& anatomy,
                                          LoopRange loop, double frameTime, double stature);

/// Over the loop (played as a cycle: the seam continues by the loop's displacement), holds
/// each planted foot at one spot with two-bone IK on the leg when `lock` is set (the ankle
/// while the heel is down, then the foot through its toe), and records every frame's
/// contacts, the point the body can turn about and how freely.
FootPlan planFeet(PoseTable& poses, const std::vector<GroundFrame>& path, const RawMotion& motion, const Anatomy& anatomy,
                  const PlantedFeet& planted, double scale, LoopRange loop, double frameTime, double stature, bool lock);

// ---- gait events (gait_events.cpp) ----

struct GaitEvents {
    std::array<std::vector<FootContact>, 2> contacts;  ///< Per leg (anatomy.legs), by strike frame.
    int leftLeg = -1;                                  ///< BakedClip::leftLeg.
};
/// Each leg's contacts over the loop (heel or toe planted, as `planted` reads them) as strike
/// and lift frames, and which leg is the body's left (its hip further along the ground frame's
/// +X). Empty contacts and leftLeg -1 without a biped or a loop of 4 frames.
[[nodiscard]] GaitEvents findGaitEvents(const PoseTable& poses, const Anatomy& anatomy, const PlantedFeet& planted, LoopRange loop);

/// Height of the floor the capture walks on (file's up axis already +Y, metres): a low
/// percentile of each frame's lowest sole (lowest point when no biped was recognised).
[[nodiscard]] double floorHeight(const PoseTable& poses, const RawMotion& motion, const Anatomy& anatomy, double scale);

// ---- sizes (baked_clip.cpp) ----

/// Sphere radius per joint: a fraction of the shortest bone that touches it, within a range
/// of the stature.
[[nodiscard]] std::vector<float> jointRadii(const RawMotion& motion, double metresPerUnit, double stature);
/// Per joint, 0, or 1 + the leg whose foot (its ankle and everything below) the joint is in
/// (BakedClip::footLeg).
[[nodiscard]] std::vector<std::uint8_t> footLegs(const std::vector<int>& parents, const Anatomy& anatomy);
/// Level of detail: 1 for joints a distant character may leave out (BakedClip::jointDetail).
[[nodiscard]] std::vector<std::uint8_t> detailJoints(const BakedClip& clip, int frame);
/// BakedClip::ankleGround from the clip's (float) poses and anatomy.
[[nodiscard]] std::vector<std::array<glm::vec2, 2>> ankleGround(const BakedClip& clip);

}  // namespace throng::motion::bake_steps
