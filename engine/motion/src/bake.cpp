#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>

#include "throng/core/supported_range.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/clip_analysis.h"
#include "throng/motion/forward_kinematics.h"

namespace throng::motion {
namespace {

// Heading of the root: where its local +Z points on the ground. A root whose +Z is nearly
// vertical (a Z-up rig) has no usable heading from +Z, so its +X, turned a quarter, stands in.
double rootYaw(const glm::dmat4& root) {
    const glm::dvec3 forward(root[2]);
    if (std::hypot(forward.x, forward.z) > 0.3) return yawOf(forward);
    const glm::dvec3 side(root[0]);
    return yawOf(side) - 1.5707963267948966;
}

// Per-frame root yaw follows the pelvis's sway within each step; the character's heading
// should not. A centred moving average over about one second keeps the turn, drops the sway.
// (The choice of heading only changes how the pose is split between track and in-place pose;
// their composition is exact either way.)
std::vector<double> smoothHeading(const std::vector<double>& yaw, int begin, double frameTime) {
    std::vector<double> smoothed = yaw;
    const int count = static_cast<int>(yaw.size());
    const int half = clampedFloor(0.5 / frameTime + 0.5, 0, std::max(count, 1));  // lround, bounded by the clip
    // Window sums from prefix sums: linear in frames whatever the window (a 1e-6 s frame time
    // makes it a million frames wide).
    std::vector<double> prefix(yaw.size() + 1, 0.0);
    for (std::size_t f = 0; f < yaw.size(); ++f) prefix[f + 1] = prefix[f] + yaw[f];
    for (int f = begin; f < count; ++f) {
        const int lo = std::max(begin, f - half), hi = std::min(count - 1, f + half);
        smoothed[static_cast<std::size_t>(f)] =
            (prefix[static_cast<std::size_t>(hi) + 1] - prefix[static_cast<std::size_t>(lo)]) / (hi - lo + 1);
    }
    return smoothed;
}

std::vector<double> unwrapped(std::vector<double> yaw) {
    for (std::size_t f = 1; f < yaw.size(); ++f) yaw[f] = yaw[f - 1] + wrapAngle(yaw[f] - yaw[f - 1]);
    return yaw;
}

// Sphere size per joint: a fraction of the shortest bone that touches it, so fingers get
// small spheres and hips big ones, clamped to the skeleton's height.
std::vector<float> jointRadii(const RawMotion& motion, double metresPerUnit, double height) {
    const int joints = motion.jointCount();
    std::vector<double> shortest(static_cast<std::size_t>(joints), 1e300);
    auto touch = [&](int joint, double length) {
        if (joint >= 0 && length > 1e-9) shortest[static_cast<std::size_t>(joint)] = std::min(shortest[static_cast<std::size_t>(joint)], length);
    };
    for (int j = 0; j < joints; ++j) {
        const double length = glm::length(motion.joints[static_cast<std::size_t>(j)].offset) * metresPerUnit;
        touch(j, length);
        touch(motion.joints[static_cast<std::size_t>(j)].parent, length);
    }
    for (const RawEndSite& site : motion.endSites) touch(site.parent, glm::length(site.offset) * metresPerUnit);
    std::vector<float> radius;
    for (double length : shortest) {
        // Fairly even beads read best as a figure; the clamp keeps fingers visible and knees modest.
        const double r = length > 1e299 ? 0.03 * height : 0.22 * length;
        radius.push_back(static_cast<float>(std::clamp(r, 0.022 * height, 0.04 * height)));
    }
    return radius;
}

// Spreads the difference between frame `last` and frame `first` over the loop so that the
// table wraps exactly. Returns the largest joint distance it had to absorb.
double closeLoop(std::vector<JointPose>& poses, int joints, LoopRange loop) {
    const auto at = [&](int f, int j) -> JointPose& { return poses[static_cast<std::size_t>(f) * joints + j]; };
    double mismatch = 0;
    for (int j = 0; j < joints; ++j) {
        const JointPose start = at(loop.first, j), end = at(loop.last, j);
        mismatch = std::max(mismatch, static_cast<double>(glm::length(start.translation - end.translation)));
        const glm::vec3 moveBy = start.translation - end.translation;
        glm::quat turnBy = start.rotation * glm::inverse(end.rotation);
        if (turnBy.w < 0) turnBy = -turnBy;  // the short way round
        for (int f = loop.first + 1; f <= loop.last; ++f) {
            const float s = static_cast<float>(f - loop.first) / static_cast<float>(loop.length());
            JointPose& p = at(f, j);
            p.translation += s * moveBy;
            p.rotation = glm::normalize(glm::slerp(glm::quat(1, 0, 0, 0), turnBy, s) * p.rotation);
        }
    }
    // Restore hemisphere continuity, which the corrections may have broken.
    for (int f = loop.first + 1; f <= loop.last; ++f)
        for (int j = 0; j < joints; ++j)
            if (glm::dot(at(f, j).rotation, at(f - 1, j).rotation) < 0) at(f, j).rotation = -at(f, j).rotation;
    return mismatch;
}

// Level of detail: which joints a distant character may leave out because another joint
// stands (almost) where it does. Within 7% of the height counts as the same spot. A link with
// a child that close is represented by that child (so chains end at the head, the hip, the
// hand); a link sitting on its parent by the parent (CMU's zero-length hip and neck links); a
// short leaf beside a sibling by the sibling (the thumb beside the fingers).
std::vector<std::uint8_t> detailJoints(const BakedClip& clip, int frame) {
    const int joints = clip.jointCount();
    const float near = 0.07F * static_cast<float>(clip.stature);
    const auto gap = [&](int a, int b) { return glm::length(clip.pose(frame, a).translation - clip.pose(frame, b).translation); };
    std::vector<std::vector<int>> children(static_cast<std::size_t>(joints));
    for (int j = 1; j < joints; ++j)
        if (clip.parents[static_cast<std::size_t>(j)] >= 0) children[static_cast<std::size_t>(clip.parents[static_cast<std::size_t>(j)])].push_back(j);
    std::vector<std::uint8_t> detail(static_cast<std::size_t>(joints), 0);
    for (int j = 0; j < joints; ++j) {
        const int parent = clip.parents[static_cast<std::size_t>(j)];
        if (parent < 0) continue;  // roots always stay
        const auto& kids = children[static_cast<std::size_t>(j)];
        const bool childClose = std::any_of(kids.begin(), kids.end(), [&](int c) { return gap(c, j) < near; });
        // Only a parent that stays can stand in (depth-first order decides parents first).
        const bool onParent = !kids.empty() && gap(j, parent) < near && detail[static_cast<std::size_t>(parent)] == 0;
        const bool besideSibling = kids.empty() && gap(j, parent) < near && children[static_cast<std::size_t>(parent)].size() > 1 &&
                                   children[static_cast<std::size_t>(parent)].front() != j;
        detail[static_cast<std::size_t>(j)] = childClose || onParent || besideSibling ? 1 : 0;
    }
    return detail;
}

}  // namespace

const char* upAxisName(UpAxis axis) {
    static constexpr const char* kNames[] = {"y", "-y", "z", "-z", "x", "-x"};
    return kNames[static_cast<int>(axis)];
}

std::optional<UpAxis> upAxisFromName(std::string_view name) {
    for (UpAxis axis : {UpAxis::PlusY, UpAxis::MinusY, UpAxis::PlusZ, UpAxis::MinusZ, UpAxis::PlusX, UpAxis::MinusX})
        if (name == upAxisName(axis)) return axis;
    return std::nullopt;
}

glm::dvec2 BakedClip::pivotAt(double frame) const {
    if (pivots.empty()) return glm::dvec2(0.0);
    const int last = static_cast<int>(pivots.size()) - 1;
    const int lower = clampedFloor(frame, 0, last);
    const int upper = std::min(lower + 1, last);
    const double fraction = frame - lower;
    const double t = fraction > 0.0 ? std::min(fraction, 1.0) : 0.0;
    return glm::mix(glm::dvec2(pivots[static_cast<std::size_t>(lower)]), glm::dvec2(pivots[static_cast<std::size_t>(upper)]), t);
}

glm::mat4 BakedClip::matrix(int frame, int joint) const {
    const JointPose& p = pose(frame, joint);
    glm::mat4 m = glm::mat4_cast(p.rotation);
    m[3] = glm::vec4(p.translation, 1.0F);
    return m;
}

JointPose BakedClip::sample(double frame, int joint) const {
    const int lower = clampedFloor(frame, 0, frameCount - 1);  // NaN reads as frame 0
    const int upper = std::min(lower + 1, frameCount - 1);
    const double fraction = frame - lower;
    const auto t = static_cast<float>(fraction > 0.0 ? std::min(fraction, 1.0) : 0.0);
    const JointPose& a = pose(lower, joint);
    const JointPose& b = pose(upper, joint);
    // nlerp along the shorter arc; neighbouring frames are close, so it matches slerp closely.
    const glm::quat bq = glm::dot(a.rotation, b.rotation) < 0 ? -b.rotation : b.rotation;
    JointPose out;
    out.rotation = glm::normalize(a.rotation * (1.0F - t) + bq * t);
    out.translation = glm::mix(a.translation, b.translation, t);
    return out;
}

glm::dvec3 BakedClip::worldPosition(const GroundFrame& ground, double frame, int joint) const {
    return glm::dvec3(ground.matrix() * glm::dvec4(glm::dvec3(sample(frame, joint).translation), 1.0));
}

namespace {

// Global transforms of every frame and joint in file units, frame-major, and the standing
// height: the largest vertical extent of joints and End Sites over all frames.
struct GlobalTable {
    std::vector<glm::dmat4> globals;
    double heightUnits = 0.0;
};

Result<GlobalTable> globalTable(const RawMotion& motion, const std::vector<int>& parents, PositionChannels positionChannels) {
    const int frames = motion.frameCount, joints = motion.jointCount();
    GlobalTable table{std::vector<glm::dmat4>(static_cast<std::size_t>(frames) * joints), 0.0};
    std::vector<glm::dmat4> locals(static_cast<std::size_t>(joints));
    for (int f = 0; f < frames; ++f) {
        const auto row = motion.frame(f);
        for (int j = 0; j < joints; ++j)
            locals[static_cast<std::size_t>(j)] = localTransform(motion.joints[static_cast<std::size_t>(j)], row, positionChannels);
        const std::span<glm::dmat4> out(table.globals.data() + static_cast<std::size_t>(f) * joints, static_cast<std::size_t>(joints));
        // The parser guarantees depth-first parents, so this holds for any parsed file; a
        // RawMotion built by hand might not, and must not bake into garbage.
        if (!LocalToGlobalJob{parents, locals, out}.run())
            return Error{Error::Kind::BadInput, "the skeleton's parents are not in depth-first order", {motion.sourceName, 0, 0}};
        double lo = 1e300, hi = -1e300;
        for (const glm::dmat4& g : out) lo = std::min(lo, g[3].y), hi = std::max(hi, g[3].y);
        for (const RawEndSite& site : motion.endSites) {
            const double y = (out[static_cast<std::size_t>(site.parent)] * glm::dvec4(site.offset, 1.0)).y;
            lo = std::min(lo, y), hi = std::max(hi, y);
        }
        table.heightUnits = std::max(table.heightUnits, hi - lo);
    }
    return table;
}

// Every joint's position relative to its frame's ground frame (the root on the ground, turned
// by `yaw`), in metres.
std::vector<glm::vec3> inPlacePositions(const std::vector<glm::dmat4>& globals, int frames, int joints, double scale,
                                        const std::vector<double>& yaw) {
    std::vector<glm::vec3> inPlace(globals.size());
    for (int f = 0; f < frames; ++f) {
        const glm::dmat4* g = &globals[static_cast<std::size_t>(f) * joints];
        const glm::dvec2 ground(g[0][3].x * scale, g[0][3].z * scale);
        const GroundFrame toLocal = GroundFrame{ground, yaw[static_cast<std::size_t>(f)]}.inverse();
        for (int j = 0; j < joints; ++j) {
            const glm::dvec3 p = glm::dvec3(g[j][3]) * scale;
            const glm::dvec2 xz = toLocal.apply({p.x, p.z});
            inPlace[static_cast<std::size_t>(f) * joints + j] = glm::vec3(glm::dvec3(xz.x, p.y, xz.y));
        }
    }
    return inPlace;
}

// The in-place poses: rotations turned into each frame's ground frame, positions from `inPlace`.
std::vector<JointPose> inPlacePoses(const std::vector<glm::dmat4>& globals, const std::vector<glm::vec3>& inPlace, int frames,
                                    int joints, const std::vector<double>& yaw) {
    std::vector<JointPose> poses(globals.size());
    for (int f = 0; f < frames; ++f) {
        const glm::dmat4* g = &globals[static_cast<std::size_t>(f) * joints];
        const glm::dquat toLocal = glm::inverse(yawQuat(yaw[static_cast<std::size_t>(f)]));
        for (int j = 0; j < joints; ++j) {
            const std::size_t index = static_cast<std::size_t>(f) * joints + j;
            glm::quat rotation(glm::normalize(toLocal * glm::quat_cast(glm::dmat3(g[j]))));
            // Keep each joint's quaternion on the same hemisphere as the previous frame's, so
            // interpolating neighbours never takes the long way round.
            if (f > 0 && glm::dot(rotation, poses[index - static_cast<std::size_t>(joints)].rotation) < 0) rotation = -rotation;
            poses[index] = {rotation, inPlace[index], 0.0F};
        }
    }
    return poses;
}

// Every baked position must lie in the supported world (throng/core/supported_range.h): the
// parser bounds each value, but a deep skeleton or a large unit scale multiplies them.
Result<bool> checkReach(const std::vector<glm::dmat4>& globals, double scale, const std::string& unitName, const SourceLocation& where) {
    double reach = 0.0;
    for (const glm::dmat4& g : globals)
        reach = std::max({reach, std::abs(g[3].x), std::abs(g[3].y), std::abs(g[3].z)});
    reach *= scale;
    if (range::within(reach, 0.0, range::kMaxClipReach)) return true;
    char message[200];
    std::snprintf(message, sizeof message, "joints reach %.3g m from the origin (%s, %.6g m per unit); at most %.0f m is supported",
                  reach, unitName.c_str(), scale, range::kMaxClipReach);
    return Error{Error::Kind::BadInput, message, where};
}

Result<BakedClip> bakeClip(const RawMotion& motion, const BakeOptions& options) {
    const int frames = motion.frameCount, joints = motion.jointCount();
    const SourceLocation where{motion.sourceName, 0, 0};
    if (frames < 1) return Error{Error::Kind::BadInput, "the clip has no frames to bake (Frames: 0)", where};
    if (joints < 1) return Error{Error::Kind::BadInput, "the clip has no joints", where};
    if (std::int64_t{frames} * joints > range::kMaxBakedJointFrames)
        return Error{Error::Kind::BadInput,
                     std::to_string(frames) + " frames x " + std::to_string(joints) + " joints is over the " +
                         std::to_string(range::kMaxBakedJointFrames) + " poses a clip may bake into",
                     where};
    if (options.metresPerUnit && !(*options.metresPerUnit > 0 && std::isfinite(*options.metresPerUnit)))
        return Error{Error::Kind::BadInput, "the unit scale must be a positive number", where};
    const std::vector<int> parents = parentIndices(motion);
    auto table = globalTable(motion, parents, options.positionChannels);
    if (!table) return table.error();
    const std::vector<glm::dmat4>& globals = table.value().globals;

    BakedClip clip;
    clip.name = motion.sourceName;
    for (const RawJoint& joint : motion.joints) clip.jointNames.push_back(joint.name);
    clip.parents = parents;
    clip.frameCount = frames;
    clip.frameTime = motion.frameTime;
    const UnitGuess guess = guessUnits(table.value().heightUnits);
    clip.unitInferred = !options.metresPerUnit;
    clip.metresPerUnit = options.metresPerUnit.value_or(guess.metresPerUnit);
    clip.unitName = options.metresPerUnit ? "custom" : guess.name;
    const double scale = clip.metresPerUnit;
    clip.stature = table.value().heightUnits * scale;
    if (auto reach = checkReach(globals, scale, clip.unitName, where); !reach) return reach.error();

    // Ground frame per frame; poses relative to it. First with the raw yaw, to recognise a
    // synthetic first frame before it can bend the smoothed heading.
    std::vector<double> rawYaw(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) rawYaw[static_cast<std::size_t>(f)] = rootYaw(globals[static_cast<std::size_t>(f) * joints]);
    rawYaw = unwrapped(rawYaw);
    clip.firstFrameSkipped = options.skipFirstFrame.value_or(
        looksLikeSyntheticFirstFrame(PoseSeries{inPlacePositions(globals, frames, joints, scale, rawYaw), frames, joints}));
    const int firstFrame = clip.firstFrameSkipped && frames > 1 ? 1 : 0;

    const std::vector<double> yaw = smoothHeading(rawYaw, firstFrame, motion.frameTime);
    const std::vector<glm::vec3> inPlace = inPlacePositions(globals, frames, joints, scale, yaw);
    const PoseSeries series{inPlace, frames, joints};
    std::vector<glm::dvec2> ground(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) {
        const glm::dmat4& root = globals[static_cast<std::size_t>(f) * joints];
        ground[static_cast<std::size_t>(f)] = glm::dvec2(root[3].x, root[3].z) * scale;
    }
    const TravelMask mask = travelMask(ground, motion.frameTime, firstFrame);
    clip.gaitPeriodFrames = estimateGaitPeriod(series, motion.frameTime, mask);
    LoopRange loop = detectLoop(series, clip.gaitPeriodFrames, firstFrame, mask);
    if (options.loop) {
        loop = *options.loop;
        if (loop.first < 0 || loop.last >= frames || loop.last <= loop.first)
            return Error{Error::Kind::BadInput,
                         "loop range " + std::to_string(loop.first) + ".." + std::to_string(loop.last) +
                             " must satisfy 0 <= first < last < " + std::to_string(frames),
                         where};
    }

    std::vector<GroundFrame> track(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) track[static_cast<std::size_t>(f)] = {ground[static_cast<std::size_t>(f)], yaw[static_cast<std::size_t>(f)]};
    clip.poses = inPlacePoses(globals, inPlace, frames, joints, yaw);
    if (options.closeLoop && loop.length() > 0) clip.seamMismatch = closeLoop(clip.poses, joints, loop);
    clip.rootMotion = RootMotionTrack(std::move(track), loop);
    clip.jointRadius = jointRadii(motion, scale, clip.stature);
    clip.jointDetail = detailJoints(clip, loop.first);
    return clip;
}

}  // namespace

Result<BakedClip> bake(const RawMotion& motion, const BakeOptions& options) {
    // A clip within the limits fits in a few GB; a machine with less says so for the file.
    try {
        return bakeClip(motion, options);
    } catch (const std::bad_alloc&) {
        return Error{Error::Kind::Runtime, "not enough memory to bake this clip", {motion.sourceName, 0, 0}};
    }
}

}  // namespace throng::motion
