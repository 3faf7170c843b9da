// The bake: from a parsed BVH to the flat runtime clip. The steps live in bake_steps.h; this
// file runs them in order and says, in the clip's warnings, what it had to guess.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>

#include "bake_steps.h"
#include "throng/core/supported_range.h"
#include "throng/motion/clip_analysis.h"
#include "throng/motion/forward_kinematics.h"

namespace throng::motion {
namespace {

using bake_steps::PoseTable;

std::string format(const char* pattern, auto... values) {
    char text[320];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

// Global transforms of every frame and joint in file units, frame-major, above the roots the
// turn that makes the file Y-up.
Result<std::vector<glm::dmat4>> globalTable(const RawMotion& motion, const std::vector<int>& parents, PositionChannels positionChannels,
                                            const glm::dmat4& toYUp) {
    const int frames = motion.frameCount, joints = motion.jointCount();
    std::vector<glm::dmat4> globals(static_cast<std::size_t>(frames) * joints);
    std::vector<glm::dmat4> locals(static_cast<std::size_t>(joints));
    for (int f = 0; f < frames; ++f) {
        const auto row = motion.frame(f);
        for (int j = 0; j < joints; ++j)
            locals[static_cast<std::size_t>(j)] = localTransform(motion.joints[static_cast<std::size_t>(j)], row, positionChannels);
        const std::span<glm::dmat4> out(globals.data() + static_cast<std::size_t>(f) * joints, static_cast<std::size_t>(joints));
        // The parser guarantees depth-first parents, so this holds for any parsed file; a
        // RawMotion built by hand might not, and must not bake into garbage.
        if (!LocalToGlobalJob{parents, locals, out, &toYUp}.run())
            return Error{Error::Kind::BadInput, "the skeleton's parents are not in depth-first order", {motion.sourceName, 0, 0}};
    }
    return globals;
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

// Joints on the way from a ROOT down to the travel joint, the travel joint included.
std::vector<char> travelChain(const std::vector<int>& parents, int travelJoint) {
    std::vector<char> chain(parents.size(), 0);
    for (int j = travelJoint; j >= 0; j = parents[static_cast<std::size_t>(j)]) chain[static_cast<std::size_t>(j)] = 1;
    return chain;
}

// The skeleton's frame of reference: body parts, the joint that carries the travel, which
// way is up, how tall the body stands and in which unit. Everything here may be guessed.
struct Reference {
    Anatomy anatomy;
    int travelJoint = 0;
    UpAxis up = UpAxis::PlusY;
    std::vector<glm::dmat4> globals;  // Y-up, file units
    double statureUnits = 0.0;
};

Result<Reference> findReference(const RawMotion& motion, const std::vector<int>& parents, const BakeOptions& options,
                                BakedClip& clip) {
    Reference ref;
    ref.anatomy = findAnatomy(motion);
    const SourceLocation where{motion.sourceName, 0, 0};
    if (!options.travelJoint.empty()) {
        const auto named = std::find_if(motion.joints.begin(), motion.joints.end(),
                                        [&](const RawJoint& joint) { return joint.name == options.travelJoint; });
        if (named == motion.joints.end())
            return Error{Error::Kind::BadInput, "no joint is named '" + options.travelJoint + "' (asked as the travel joint, root=)", where};
        ref.travelJoint = static_cast<int>(named - motion.joints.begin());
    } else if (ref.anatomy.biped()) {
        ref.travelJoint = ref.anatomy.pelvis;
        if (ref.travelJoint != 0)
            clip.warnings.push_back(format("the ROOT '%s' is not the body: travel follows '%s', found by the skeleton's shape (override: root=JOINT)",
                                           motion.joints[0].name.c_str(), motion.joints[static_cast<std::size_t>(ref.travelJoint)].name.c_str()));
    }
    auto fileAxes = globalTable(motion, parents, options.positionChannels, glm::dmat4(1.0));
    if (!fileAxes) return fileAxes.error();
    const std::optional<UpAxis> detected = options.upAxis ? options.upAxis : bake_steps::detectUpAxis(fileAxes.value(), motion.jointCount(), ref.anatomy);
    ref.up = detected.value_or(UpAxis::PlusY);
    if (!options.upAxis && !ref.anatomy.biped())
        clip.warnings.push_back("no legs and spine recognised: assuming Y up, travel from the ROOT and stature from the vertical extent");
    if (!options.upAxis && ref.up != UpAxis::PlusY)
        clip.warnings.push_back(format("the file's up axis is %s (the legs hang that way from the spine): turned to Y up (override: up=AXIS)",
                                       upAxisName(ref.up)));
    if (ref.up == UpAxis::PlusY) {
        ref.globals = std::move(fileAxes.value());
    } else {
        const glm::dmat4 turn = bake_steps::toYUp(ref.up);
        ref.globals = std::move(fileAxes.value());
        for (glm::dmat4& g : ref.globals) g = turn * g;
    }
    ref.statureUnits = bake_steps::uprightStature(ref.globals, motion, ref.anatomy);
    return ref;
}

// Poses as floats for the GPU, each joint's quaternion kept on the previous frame's
// hemisphere so interpolating neighbours never takes the long way round.
std::vector<JointPose> toFloatPoses(const PoseTable& poses) {
    std::vector<JointPose> out(poses.rotation.size());
    for (int f = 0; f < poses.frames; ++f)
        for (int j = 0; j < poses.joints; ++j) {
            const std::size_t index = poses.index(f, j);
            glm::quat rotation(glm::normalize(poses.rotation[index]));
            if (f > 0 && glm::dot(rotation, out[index - static_cast<std::size_t>(poses.joints)].rotation) < 0) rotation = -rotation;
            out[index] = {rotation, glm::vec3(poses.position[index]), 0.0F};
        }
    return out;
}

std::vector<glm::vec3> floatPositions(const PoseTable& poses) {
    std::vector<glm::vec3> out(poses.position.size());
    std::transform(poses.position.begin(), poses.position.end(), out.begin(), [](const glm::dvec3& p) { return glm::vec3(p); });
    return out;
}

// Per leg, the steering one stance takes back as twist (BakedClip::stanceTurnSeconds). A stance
// begins where the hold rises through one half.
glm::dvec2 stanceTurnSeconds(const BakedClip& clip, LoopRange loop) {
    glm::dvec2 out(0.0);
    if (clip.footHold.empty() || loop.length() < 2) return out;
    for (int l = 0; l < 2; ++l) {
        const auto hold = [&](int f) { return static_cast<double>(clip.footHold[static_cast<std::size_t>(f)][l]); };
        int stances = 0;
        double taken = 0.0;
        for (int f = loop.first; f < loop.last; ++f) {
            const int previous = f > loop.first ? f - 1 : loop.last - 1;
            if (hold(f) >= 0.5 && hold(previous) < 0.5) ++stances;
            taken += hold(f) * clip.turnGainAt(f) * clip.frameTime;
        }
        out[l] = stances > 0 ? taken / stances : 0.0;
    }
    return out;
}

// Gait and loop: found in the travelling frames, or given. A static clip loops over all of it.
Result<LoopRange> chooseLoop(const PoseTable& poses, const std::vector<GroundFrame>& path, const BakeOptions& options, int firstFrame,
                             BakedClip& clip) {
    const std::vector<glm::vec3> positions = floatPositions(poses);
    const PoseSeries series{positions, poses.frames, poses.joints};
    std::vector<glm::dvec2> ground(path.size());
    std::transform(path.begin(), path.end(), ground.begin(), [](const GroundFrame& g) { return g.position; });
    const TravelMask mask = travelMask(ground, clip.frameTime, firstFrame);
    clip.locomotion = mask.locomotion && !clip.isStatic;
    clip.gaitPeriodFrames = clip.isStatic ? 0.0 : estimateGaitPeriod(series, clip.frameTime, mask);
    LoopRange loop = clip.isStatic ? LoopRange{firstFrame, std::max(firstFrame, poses.frames - 1)}
                                   : detectLoop(series, clip.gaitPeriodFrames, firstFrame, mask);
    if (!options.loop) {
        if (clip.locomotion && clip.gaitPeriodFrames <= 0)
            clip.warnings.push_back(format("the clip travels but no gait cycle was found: it loops over frames %d..%d (override: loop=FIRST-LAST)",
                                           loop.first, loop.last));
        return loop;
    }
    loop = *options.loop;
    if (loop.first < 0 || loop.last >= poses.frames || loop.last <= loop.first)
        return Error{Error::Kind::BadInput,
                     "loop range " + std::to_string(loop.first) + ".." + std::to_string(loop.last) +
                         " must satisfy 0 <= first < last < " + std::to_string(poses.frames),
                     {clip.name, 0, 0}};
    // The skipped first frame is a T-pose, not motion: a loop through it plays the T-pose.
    if (loop.first < firstFrame)
        return Error{Error::Kind::BadInput,
                     "loop range " + std::to_string(loop.first) + ".." + std::to_string(loop.last) + " starts at frame " +
                         std::to_string(loop.first) + ", the synthetic first frame that is skipped: start it at " +
                         std::to_string(firstFrame) + " or later, or keep the first frame (keep_first_frame, --keep-first-frame)",
                     {clip.name, 0, 0}};
    return loop;
}

void addShapeWarnings(BakedClip& clip, const BakeOptions& options, double floor) {
    const LoopRange loop = clip.loop();
    if (clip.unitInferred && (clip.stature < 1.2 || clip.stature > 2.3))
        clip.warnings.push_back(format("the body stands %.2f m tall read as %s: the unit may be wrong (override: units=METRES_PER_UNIT)",
                                       clip.stature, clip.unitName.c_str()));
    if (std::abs(floor) > 0.05 * clip.stature)
        clip.warnings.push_back(format("the capture's floor is at %.1f cm: the body is moved onto the ground", floor * 100.0));
    if (clip.isStatic)
        clip.warnings.push_back(format("the clip is too short for a cycle (%d frames, %.3f s): it plays as a still pose without root motion",
                                       clip.frameCount, clip.frameCount * clip.frameTime));
    const double turnDegrees = glm::degrees(clip.turnRate * loop.length() * clip.frameTime);
    if (!options.straighten && std::abs(glm::degrees(clip.turnRate)) > 5.0)
        clip.warnings.push_back(format("the clip turns %.0f deg/s (%.0f deg over its loop): group mode follows the curve (straighten=1 walks it straight)",
                                       glm::degrees(clip.turnRate), turnDegrees));
    if (clip.seamMismatch > 0.1 * clip.stature)
        clip.warnings.push_back(format("the loop's ends differ by %.0f cm: closing spreads that over frames %d..%d (override: loop=FIRST-LAST)",
                                       clip.seamMismatch * 100.0, loop.first, loop.last));
}

}  // namespace

bake_steps::PoseTable bake_steps::inPlacePoses(std::span<const glm::dmat4> globals, int joints, double scale,
                                               const std::vector<GroundFrame>& path, const std::vector<int>& parents, int travelJoint) {
    const int frames = static_cast<int>(path.size());
    PoseTable poses(frames, joints);
    std::vector<char> above = travelChain(parents, travelJoint);
    above[static_cast<std::size_t>(travelJoint)] = 0;
    for (int f = 0; f < frames; ++f) {
        const glm::dmat4* g = &globals[static_cast<std::size_t>(f) * joints];
        const GroundFrame toLocal = path[static_cast<std::size_t>(f)].inverse();
        const glm::dquat unturn = glm::conjugate(yawQuat(path[static_cast<std::size_t>(f)].yaw));
        for (int j = 0; j < joints; ++j) {
            const glm::dvec3 p = glm::dvec3(g[j][3]) * scale;
            const glm::dvec2 xz = toLocal.apply({p.x, p.z});
            poses.pos(f, j) = {xz.x, p.y, xz.y};
            poses.rot(f, j) = glm::normalize(unturn * glm::quat_cast(glm::dmat3(g[j])));
        }
        for (int j = 0; j < joints; ++j)
            if (above[static_cast<std::size_t>(j)] != 0) {
                poses.pos(f, j) = poses.pos(f, travelJoint);
                poses.rot(f, j) = poses.rot(f, travelJoint);
            }
    }
    return poses;
}

namespace {

Result<bool> checkLimits(const RawMotion& motion, const BakeOptions& options) {
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
    return true;
}

// Where the body is on the ground at every frame (its heading, the first-frame check, the
// still-clip rule), and its poses relative to that.
struct Placement {
    std::vector<GroundFrame> path;
    // The same track smoothed over a quarter second, for the pace: the second-long smoothing
    // that takes the sway out of `path` also cuts the corners of a curving walk (5% short on
    // a 1.2 m radius), while a quarter second keeps the curve and still drops capture jitter.
    std::vector<GroundFrame> pacePath;
    PoseTable poses{0, 0};
    int firstFrame = 0;
};

Placement place(const RawMotion& motion, const Reference& ref, const std::vector<int>& parents, const BakeOptions& options,
                BakedClip& clip) {
    const int frames = motion.frameCount, joints = motion.jointCount();
    const double scale = clip.metresPerUnit;
    const std::vector<double> rawHeading = bake_steps::bodyHeading(ref.globals, joints, ref.anatomy, ref.travelJoint, motion);
    Placement placement;
    // A converter's synthetic T-pose in frame 0 is recognised before it can bend the smoothed path.
    if (!options.skipFirstFrame) {
        const auto raw = bake_steps::groundPath(ref.globals, joints, ref.travelJoint, scale, rawHeading, frames, clip.frameTime);
        const std::vector<glm::vec3> positions = floatPositions(bake_steps::inPlacePoses(ref.globals, joints, scale, raw, parents, ref.travelJoint));
        clip.firstFrameSkipped = looksLikeSyntheticFirstFrame(PoseSeries{positions, frames, joints});
    } else {
        clip.firstFrameSkipped = *options.skipFirstFrame;
    }
    placement.firstFrame = clip.firstFrameSkipped && frames > 1 ? 1 : 0;
    const int usable = frames - placement.firstFrame;
    // Under a quarter second holds no step: root motion from it would glide a frozen pose.
    clip.isStatic = usable < 4 || (usable - 1) * clip.frameTime < 0.25;
    const std::vector<double> heading = bake_steps::smoothed(rawHeading, placement.firstFrame, clip.frameTime, 1.0);
    placement.path = bake_steps::groundPath(ref.globals, joints, ref.travelJoint, scale, heading, placement.firstFrame, clip.frameTime);
    placement.pacePath = bake_steps::groundPath(ref.globals, joints, ref.travelJoint, scale, heading, placement.firstFrame, clip.frameTime, 0.25);
    if (clip.isStatic) {
        std::fill(placement.path.begin(), placement.path.end(), placement.path[static_cast<std::size_t>(placement.firstFrame)]);
        placement.pacePath = placement.path;
    }
    placement.poses = bake_steps::inPlacePoses(ref.globals, joints, scale, placement.path, parents, ref.travelJoint);
    return placement;
}

Result<BakedClip> bakeClip(const RawMotion& motion, const BakeOptions& options) {
    if (auto limits = checkLimits(motion, options); !limits) return limits.error();
    const SourceLocation where{motion.sourceName, 0, 0};
    const std::vector<int> parents = parentIndices(motion);
    BakedClip clip;
    clip.name = motion.sourceName;
    for (const RawJoint& joint : motion.joints) clip.jointNames.push_back(joint.name);
    clip.parents = parents;
    clip.frameCount = motion.frameCount;
    clip.frameTime = motion.frameTime;
    auto reference = findReference(motion, parents, options, clip);
    if (!reference) return reference.error();
    const Reference& ref = reference.value();
    clip.anatomy = ref.anatomy;
    clip.travelJoint = ref.travelJoint;
    clip.upAxis = ref.up;
    clip.upAxisInferred = !options.upAxis;
    const UnitGuess guess = guessUnits(ref.statureUnits);
    clip.unitInferred = !options.metresPerUnit;
    clip.metresPerUnit = options.metresPerUnit.value_or(guess.metresPerUnit);
    clip.unitName = options.metresPerUnit ? "custom" : guess.name;
    clip.stature = ref.statureUnits * clip.metresPerUnit;
    if (auto reach = checkReach(ref.globals, clip.metresPerUnit, clip.unitName, where); !reach) return reach.error();
    if (ref.statureUnits > 0.0 && !(clip.stature >= range::kMinClipStature))
        return Error{Error::Kind::BadInput,
                     format("the body stands %.3g m tall (%.6g file units at %.6g m per unit, %s): at least %g m is supported; check the unit",
                            clip.stature, ref.statureUnits, clip.metresPerUnit, clip.unitName.c_str(), range::kMinClipStature),
                     where};

    Placement placement = place(motion, ref, parents, options, clip);
    PoseTable& poses = placement.poses;
    const double floor = bake_steps::floorHeight(poses, motion, ref.anatomy, clip.metresPerUnit);
    for (glm::dvec3& p : poses.position) p.y -= floor;
    clip.floorHeight = floor;
    auto loop = chooseLoop(poses, placement.path, options, placement.firstFrame, clip);
    if (!loop) return loop.error();
    if (options.straighten) {
        placement.path = bake_steps::straightened(placement.path, loop.value());
        placement.pacePath = bake_steps::straightened(placement.pacePath, loop.value());
    }
    std::vector<char> moving = travelChain(parents, ref.travelJoint);
    for (int j = 0; j < motion.jointCount(); ++j)
        for (Channel c : motion.joints[static_cast<std::size_t>(j)].channels)
            if (!isRotation(c)) moving[static_cast<std::size_t>(j)] = 1;
    const bake_steps::PlantedFeet planted =
        bake_steps::findPlantedFeet(poses, placement.path, ref.anatomy, loop.value(), clip.frameTime, clip.stature);
    if (options.closeLoop && loop.value().length() > 0)
        clip.seamMismatch = bake_steps::closeLoopInJointSpace(poses, parents, moving, loop.value());
    bake_steps::FootPlan feet = bake_steps::planFeet(poses, placement.path, motion, ref.anatomy, planted, clip.metresPerUnit, loop.value(),
                                                     clip.frameTime, clip.stature, options.footLock && !clip.isStatic);
    clip.contacts = std::move(feet.contacts);
    bake_steps::GaitEvents gait = bake_steps::findGaitEvents(poses, ref.anatomy, planted, loop.value());
    clip.footContacts = std::move(gait.contacts);
    clip.leftLeg = gait.leftLeg;
    clip.pivots = std::move(feet.pivots);
    clip.turnFreedom = std::move(feet.turnFreedom);
    if (loop.value().length() > 0) {  // once here, not per character and step
        double sum = 0.0;
        for (int f = loop.value().first; f < loop.value().last; ++f) sum += clip.turnFreedom[static_cast<std::size_t>(f)];
        clip.meanTurnFreedom = sum / loop.value().length();
    }
    clip.footHold = std::move(feet.hold);
    clip.stanceTurnSeconds = stanceTurnSeconds(clip, loop.value());
    clip.footLeg = bake_steps::footLegs(clip.parents, ref.anatomy);
    clip.poses = toFloatPoses(poses);
    clip.ankleGround = bake_steps::ankleGround(clip);
    const double loopSeconds = loop.value().length() * clip.frameTime;
    clip.speed = loopSeconds > 0 ? bake_steps::arcLength(placement.pacePath, loop.value().first, loop.value().last) / loopSeconds : 0.0;
    clip.turnRate = loopSeconds > 0
                        ? (placement.path[static_cast<std::size_t>(loop.value().last)].yaw - placement.path[static_cast<std::size_t>(loop.value().first)].yaw) / loopSeconds
                        : 0.0;
    clip.rootMotion = RootMotionTrack(std::move(placement.path), loop.value());
    clip.jointRadius = bake_steps::jointRadii(motion, clip.metresPerUnit, clip.stature);
    clip.body = findBodyBones(motion, clip.anatomy, clip.metresPerUnit, clip.stature, clip.jointRadius);
    clip.jointDetail = bake_steps::detailJoints(clip, loop.value().first);
    addShapeWarnings(clip, options, floor);
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
