// Baking real captures: in-place poses plus the root-motion track must rebuild the raw
// forward kinematics; loops must be seamless; units, height and T-pose must be recognised.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"
#include "throng/motion/forward_kinematics.h"

namespace {

using namespace throng::motion;

std::string sharedClip(const std::string& name) { return std::string(THRONG_SHARED_MOCAP_DIR) + "/" + name; }

// The shared captures sit beside the project (../shared/mocap); a checkout without them
// reports these tests as skipped, saying why, as the other shared-capture tests do.
bool haveSharedCaptures() { return std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR); }
#define REQUIRE_SHARED_CAPTURES() \
    if (!haveSharedCaptures()) GTEST_SKIP() << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR

struct Loaded {
    RawMotion raw;
    BakedClip clip;
};

Loaded load(const std::string& path, const BakeOptions& options = {}) {
    auto raw = loadBvhFile(path);
    if (!raw) throw std::runtime_error(raw.error().describe());
    auto clip = bake(raw.value(), options);
    if (!clip) throw std::runtime_error(clip.error().describe());
    return {std::move(raw.value()), std::move(clip.value())};
}

const std::vector<std::string>& allClips() {
    static const std::vector<std::string> clips = [] {
        std::vector<std::string> paths{THRONG_DEFAULT_CLIP};
        if (!haveSharedCaptures()) return paths;
        for (const char* name : {"biovision_example_2frames.bvh", "bvhtoolbox_walk01_19j_zxy_24fps.bvh",
                                 "cmu_02_01_walk.bvh", "cmu_07_01_walk.bvh", "cmu_131_01_walk_3dsmax.bvh",
                                 "cmu_131_02_walk_3dsmax_scaled_m.bvh", "cmu_16_45_run.bvh",
                                 "mocapbank_19j_zxy_crlf.bvh"})
            paths.push_back(sharedClip(name));
        return paths;
    }();
    return clips;
}

// World position of a joint as the engine would draw it at integer frame f: the ground
// frame from the track times the in-place pose.
glm::dvec3 drawnPosition(const BakedClip& clip, const GroundFrame& ground, int frame, int joint) {
    return glm::dvec3(ground.matrix() * glm::dvec4(glm::dvec3(clip.pose(frame, joint).translation), 1.0));
}

// The capture as it is: no loop closing and no foot lock.
BakeOptions unclosed() {
    BakeOptions options;
    options.closeLoop = false;
    options.footLock = false;
    return options;
}

BakeOptions closedWithoutFootLock() {
    BakeOptions options;
    options.footLock = false;
    return options;
}

TEST(Bake, InPlacePosesAndTrackRebuildTheRawCapture) {
    for (const std::string& path : allClips()) {
        SCOPED_TRACE(path);
        const Loaded l = load(path, unclosed());
        double worst = 0;
        for (int f = 0; f < l.raw.frameCount; ++f) {
            const std::vector<glm::dmat4> raw = globalTransforms(l.raw, f, PositionChannels::Replace);
            const GroundFrame ground = l.clip.rootMotion.frames()[static_cast<std::size_t>(f)];
            for (int j = 0; j < l.clip.jointCount(); ++j) {
                const glm::dvec3 expected =
                    glm::dvec3(raw[static_cast<std::size_t>(j)][3]) * l.clip.metresPerUnit - glm::dvec3(0.0, l.clip.floorHeight, 0.0);
                worst = std::max(worst, glm::length(drawnPosition(l.clip, ground, f, j) - expected));
            }
        }
        EXPECT_LT(worst, 1e-4 * l.clip.stature);
    }
    REQUIRE_SHARED_CAPTURES() << " (only the default clip was checked)";
}

TEST(Bake, RootPathRebuiltFromDeltasOverALoopAndAcrossTheWrap) {
    for (const std::string& path : allClips()) {
        SCOPED_TRACE(path);
        const Loaded l = load(path);
        const LoopRange loop = l.clip.loop();
        if (loop.length() < 2) continue;  // the 2-frame example has nothing to walk
        // Integrate per-frame deltas as the crowd does, for two loops, starting on the capture.
        GroundFrame ground = l.clip.rootMotion.frames()[static_cast<std::size_t>(loop.first)];
        const GroundFrame perLoop = l.clip.rootMotion.loopDisplacement();
        double worst = 0;
        for (int step = 0; step <= 2 * loop.length(); ++step) {
            const int frame = loop.first + step % loop.length();
            const int loopsDone = step / loop.length();
            // The raw capture's root, moved on by the loops already walked.
            const std::vector<glm::dmat4> raw = globalTransforms(l.raw, frame, PositionChannels::Replace);
            GroundFrame shift;
            for (int n = 0; n < loopsDone; ++n) shift = shift.then(perLoop);
            const glm::dvec3 rawRoot = glm::dvec3(raw[0][3]) * l.clip.metresPerUnit;
            const glm::dvec2 expected = shift.apply({rawRoot.x, rawRoot.z});
            const glm::dvec3 rebuilt = drawnPosition(l.clip, ground, frame, 0);
            worst = std::max(worst, glm::length(glm::dvec2(rebuilt.x, rebuilt.z) - expected));
            ground = ground.then(l.clip.rootMotion.delta(loop.first + step, loop.first + step + 1));
        }
        // Closing moves the root by its share of the seam's mismatch, no more.
        const double travelled = 2.0 * glm::length(perLoop.position);
        EXPECT_LE(worst, std::max(0.01 * travelled, l.clip.seamMismatch)) << "travelled " << travelled << " m";
    }
    REQUIRE_SHARED_CAPTURES() << " (only the default clip was checked)";
}

// Largest world-space joint step between consecutive drawn frames in [first, last), and the
// jump across the wrap (frame last-1 to frame first, one loop on).
struct SeamFigures {
    double largestStep = 0;
    double wrapJump = 0;
};

SeamFigures seam(const BakedClip& clip) {
    const LoopRange loop = clip.loop();
    const RootMotionTrack& track = clip.rootMotion;
    SeamFigures figures;
    for (int f = loop.first; f + 1 < loop.last; ++f)
        for (int j = 0; j < clip.jointCount(); ++j)
            figures.largestStep = std::max(figures.largestStep,
                                           glm::length(drawnPosition(clip, track.at(f + 1), f + 1, j) -
                                                       drawnPosition(clip, track.at(f), f, j)));
    for (int j = 0; j < clip.jointCount(); ++j)
        figures.wrapJump = std::max(figures.wrapJump,
                                    glm::length(drawnPosition(clip, track.at(loop.last), loop.first, j) -
                                                drawnPosition(clip, track.at(loop.last - 1), loop.last - 1, j)));
    return figures;
}

TEST(Bake, LoopSeamOfCmuWalksIsNoLargerThanAnOrdinaryFrameStep) {
    REQUIRE_SHARED_CAPTURES();
    for (const char* name : {"cmu_02_01_walk.bvh", "cmu_07_01_walk.bvh", "cmu_131_01_walk_3dsmax.bvh"}) {
        SCOPED_TRACE(name);
        const Loaded l = load(sharedClip(name));
        const SeamFigures figures = seam(l.clip);
        std::printf("%s: loop %d..%d, wrap jump %.4f m, largest step %.4f m\n", name, l.clip.loop().first,
                    l.clip.loop().last, figures.wrapJump, figures.largestStep);
        EXPECT_LE(figures.wrapJump, figures.largestStep);
        EXPECT_GT(figures.largestStep, 0.0);
    }
}

TEST(Bake, WithoutLoopClosingTheSeamIsWhatTheCaptureGives) {
    REQUIRE_SHARED_CAPTURES();
    // The reason closing exists: raw captures do not end where they start.
    const Loaded l = load(sharedClip("cmu_07_01_walk.bvh"), unclosed());
    const SeamFigures figures = seam(l.clip);
    EXPECT_GT(figures.wrapJump, figures.largestStep);
}

// Loop closing works in joint space: each local rotation (and the root's translation) takes a
// growing share of the seam's correction, then forward kinematics rebuilds the frame. A joint
// far from the root may then move further than the seam mismatch in mid-loop; what closing
// guarantees is that only frames (first, last] change, that frame `last` becomes frame
// `first`, and that no bone changes length.
TEST(Bake, LoopClosingChangesOnlyTheLoopMakesItsEndsMeetAndKeepsBonesRigid) {
    for (const std::string& path : allClips()) {
        SCOPED_TRACE(path);
        const Loaded closed = load(path, closedWithoutFootLock()), open = load(path, unclosed());
        const LoopRange loop = closed.clip.loop();
        ASSERT_EQ(loop.first, open.clip.loop().first);
        ASSERT_EQ(loop.last, open.clip.loop().last);
        const double stature = closed.clip.stature;
        double worstBone = 0.0;
        for (int f = 0; f < closed.clip.frameCount; ++f)
            for (int j = 0; j < closed.clip.jointCount(); ++j) {
                if (f <= loop.first || f > loop.last) {
                    EXPECT_EQ(closed.clip.pose(f, j).translation, open.clip.pose(f, j).translation) << "frame " << f << " joint " << j;
                    EXPECT_EQ(closed.clip.pose(f, j).rotation, open.clip.pose(f, j).rotation) << "frame " << f << " joint " << j;
                }
                const int parent = closed.clip.parents[static_cast<std::size_t>(j)];
                if (parent < 0) continue;
                const auto length = [&](const BakedClip& clip) {
                    return glm::length(glm::dvec3(clip.pose(f, j).translation) - glm::dvec3(clip.pose(f, parent).translation));
                };
                worstBone = std::max(worstBone, std::abs(length(closed.clip) - length(open.clip)));
            }
        EXPECT_LE(worstBone, 1e-4 * stature);
        for (int j = 0; loop.length() > 0 && j < closed.clip.jointCount(); ++j) {
            const JointPose& a = closed.clip.pose(loop.last, j);
            const JointPose& b = closed.clip.pose(loop.first, j);
            EXPECT_LT(glm::length(a.translation - b.translation), 1e-5F) << "joint " << j;
            EXPECT_GT(std::abs(glm::dot(a.rotation, b.rotation)), 1.0F - 1e-5F) << "joint " << j;
        }
        std::printf("%s: seam mismatch %.4f m, bones change by at most %.2e m (stature %.3f m)\n", path.c_str(),
                    closed.clip.seamMismatch, worstBone, stature);
    }
    REQUIRE_SHARED_CAPTURES() << " (only the default clip was checked)";
}

TEST(Bake, LocomotionLoopsSpanAtLeastOneGaitCycleAndTravel) {
    REQUIRE_SHARED_CAPTURES();
    for (const char* name : {"cmu_02_01_walk.bvh", "cmu_07_01_walk.bvh", "bvhtoolbox_walk01_19j_zxy_24fps.bvh",
                             "cmu_16_45_run.bvh"}) {
        SCOPED_TRACE(name);
        const Loaded l = load(sharedClip(name));
        ASSERT_GT(l.clip.gaitPeriodFrames, 0.0);
        EXPECT_GE(l.clip.loop().length(), 0.9 * l.clip.gaitPeriodFrames);
        const double seconds = l.clip.loop().length() * l.clip.frameTime;
        // Human gait cycles last 0.6-1.4 s; walking and running speeds are 0.8-6 m/s.
        EXPECT_GT(seconds, 0.6);
        EXPECT_LT(seconds, 1.4 * 2);
        const double speed = glm::length(l.clip.rootMotion.loopDisplacement().position) / seconds;
        EXPECT_GT(speed, 0.8);
        EXPECT_LT(speed, 6.0);
    }
}

TEST(Bake, StartWalkStopClipLoopsWhileWalkingNotWhileStanding) {
    REQUIRE_SHARED_CAPTURES();
    const Loaded l = load(sharedClip("cmu_131_01_walk_3dsmax.bvh"));
    const double seconds = l.clip.loop().length() * l.clip.frameTime;
    EXPECT_GT(glm::length(l.clip.rootMotion.loopDisplacement().position) / seconds, 0.8);
}

TEST(Bake, SyntheticTPoseIsSkippedOnlyWhereThereIsOne) {
    REQUIRE_SHARED_CAPTURES();
    for (const char* name : {"cmu_02_01_walk.bvh", "cmu_07_01_walk.bvh", "cmu_16_45_run.bvh"}) {
        const Loaded l = load(sharedClip(name));
        EXPECT_TRUE(l.clip.firstFrameSkipped) << name;
        EXPECT_GE(l.clip.loop().first, 1) << name;
    }
    for (const char* name : {"cmu_131_01_walk_3dsmax.bvh", "bvhtoolbox_walk01_19j_zxy_24fps.bvh",
                             "mocapbank_19j_zxy_crlf.bvh"})
        EXPECT_FALSE(load(sharedClip(name)).clip.firstFrameSkipped) << name;
    EXPECT_FALSE(load(THRONG_DEFAULT_CLIP).clip.firstFrameSkipped);
}

TEST(Bake, UnitsAreInferredFromTheSkeletonAndHeightsAreHuman) {
    REQUIRE_SHARED_CAPTURES();
    const std::pair<const char*, const char*> expected[] = {
        {"cmu_02_01_walk.bvh", "CMU units"},          {"cmu_16_45_run.bvh", "CMU units"},
        {"cmu_131_02_walk_3dsmax_scaled_m.bvh", "metres"}, {"mocapbank_19j_zxy_crlf.bvh", "centimetres"},
        {"bvhtoolbox_walk01_19j_zxy_24fps.bvh", "centimetres"}, {"biovision_example_2frames.bvh", "inches"},
    };
    for (const auto& [name, unit] : expected) {
        const Loaded l = load(sharedClip(name));
        EXPECT_EQ(l.clip.unitName, unit) << name;
        EXPECT_GT(l.clip.stature, 1.3) << name;
        EXPECT_LT(l.clip.stature, 2.0) << name;
    }
}

TEST(Bake, OverridesAreHonouredAndValidated) {
    auto raw = loadBvhFile(THRONG_DEFAULT_CLIP);
    ASSERT_TRUE(raw);
    BakeOptions options;
    options.metresPerUnit = 0.02;
    options.loop = LoopRange{5, 40};
    auto clip = bake(raw.value(), options);
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip.value().loop().first, 5);
    EXPECT_EQ(clip.value().loop().last, 40);
    EXPECT_EQ(clip.value().unitName, "custom");
    EXPECT_NEAR(clip.value().stature, 2.0 * load(THRONG_DEFAULT_CLIP).clip.stature, 1e-6);

    options.loop = LoopRange{5, 100000};
    auto bad = bake(raw.value(), options);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("loop range"), std::string::npos);
    // A loop through a skipped first frame (a T-pose) would play it: refused, saying why.
    options.skipFirstFrame = true;
    options.loop = LoopRange{0, 40};
    auto throughTPose = bake(raw.value(), options);
    ASSERT_FALSE(throughTPose);
    EXPECT_NE(throughTPose.error().message.find("the synthetic first frame that is skipped: start it at 1"), std::string::npos)
        << throughTPose.error().message;
    options.loop = LoopRange{1, 40};
    EXPECT_TRUE(bake(raw.value(), options));
    options.skipFirstFrame = false;  // kept: frame 0 is motion and may start the loop
    options.loop = LoopRange{0, 40};
    EXPECT_TRUE(bake(raw.value(), options));
    options.skipFirstFrame.reset();
    options.loop.reset();
    options.metresPerUnit = -1.0;
    EXPECT_FALSE(bake(raw.value(), options));
}

TEST(Bake, SampleInterpolatesBetweenFramesAndMatrixMatchesPose) {
    const Loaded l = load(THRONG_DEFAULT_CLIP);
    for (int j = 0; j < l.clip.jointCount(); ++j) {
        const JointPose mid = l.clip.sample(10.5, j);
        const glm::vec3 expected = 0.5F * (l.clip.pose(10, j).translation + l.clip.pose(11, j).translation);
        EXPECT_LT(glm::length(mid.translation - expected), 1e-6F);
        EXPECT_NEAR(glm::length(mid.rotation), 1.0F, 1e-6F);
        const glm::mat4 m = l.clip.matrix(10, j);
        EXPECT_LT(glm::length(glm::vec3(m[3]) - l.clip.pose(10, j).translation), 1e-6F);
        // Neighbouring quaternions share a hemisphere, so interpolation takes the short way.
        EXPECT_GE(glm::dot(l.clip.pose(10, j).rotation, l.clip.pose(11, j).rotation), 0.0F);
    }
}

TEST(Bake, AnkleTableGivesTheAnklesThePosesGiveToTheBit) {
    // The crowd step reads the ankles from their own table; the ankle joints' poses are the
    // reference, interpolated as positionAt does, and so is a clip without the table.
    BakedClip clip = load(THRONG_DEFAULT_CLIP).clip;
    ASSERT_EQ(clip.ankleGround.size(), static_cast<std::size_t>(clip.frameCount));
    BakedClip withoutTable = clip;
    withoutTable.ankleGround.clear();
    int checked = 0;
    for (double frame : {0.0, 3.25, 10.5, 17.875, clip.frameCount - 1.0, clip.frameCount + 4.0, -2.0})
        for (std::size_t l = 0; l < 2; ++l) {
            const int ankle = clip.anatomy.legs[l].ankle;
            ASSERT_GE(ankle, 0);
            const glm::vec3 expected = clip.positionAt(frame, ankle);
            const glm::dvec2 fromTable = clip.anklesAt(frame)[l], fromPoses = withoutTable.anklesAt(frame)[l];
            EXPECT_EQ(fromTable.x, static_cast<double>(expected.x)) << "frame " << frame << ", leg " << l;
            EXPECT_EQ(fromTable.y, static_cast<double>(expected.z)) << "frame " << frame << ", leg " << l;
            EXPECT_EQ(fromPoses, fromTable) << "frame " << frame << ", leg " << l;
            ++checked;
        }
    EXPECT_EQ(checked, 14);
}

TEST(Bake, EmptyClipIsRefused) {
    auto raw = parseBvh("HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n}\n"
                        "MOTION\nFrames: 0\nFrame Time: 0.1\n",
                        "empty.bvh");
    ASSERT_TRUE(raw) << raw.error().describe();
    auto clip = bake(raw.value());
    ASSERT_FALSE(clip);
    EXPECT_NE(clip.error().message.find("no frames"), std::string::npos);
}

}  // namespace

namespace {

TEST(Bake, LevelOfDetailDropsSmallJointsAndKeepsTheLimbs) {
    const Loaded l = load(THRONG_DEFAULT_CLIP);
    ASSERT_EQ(l.clip.jointDetail.size(), static_cast<std::size_t>(l.clip.jointCount()));
    std::set<std::string> dropped, kept;
    for (int j = 0; j < l.clip.jointCount(); ++j)
        (l.clip.jointDetail[static_cast<std::size_t>(j)] ? dropped : kept).insert(l.clip.jointNames[static_cast<std::size_t>(j)]);
    // The figure's landmarks stay: hips, knees, feet, head, shoulders, elbows, one hand sphere.
    for (const char* limb : {"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightLeg", "Head", "LeftArm", "LeftForeArm",
                             "LeftHandIndex1", "RightHandIndex1"})
        EXPECT_TRUE(kept.count(limb)) << limb;
    // Links that overlap a neighbour go: hip links, neck links, the hand's inner joints, thumbs.
    for (const char* small : {"LHipJoint", "Neck1", "LeftHand", "LeftFingerBase", "LThumb", "RThumb"})
        EXPECT_TRUE(dropped.count(small)) << small;
    EXPECT_LE(kept.size(), 21U);
}

}  // namespace
