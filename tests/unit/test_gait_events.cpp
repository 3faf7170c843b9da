// Gait events from the bake: each foot's strikes and lifts over the loop, which leg is the left,
// and the gait phase timed from the left foot's strike (what clips blended at different speeds
// are aligned by). The captures' joint names are the known answer for left and right: the bake
// decides from the skeleton's geometry, never from names.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng::motion;

BakedClip bakeFile(const std::string& path) { return bake(loadBvhFile(path).orThrow()).orThrow(); }

std::string ankleName(const BakedClip& clip, int leg) {
    return clip.jointNames[static_cast<std::size_t>(clip.anatomy.legs[static_cast<std::size_t>(leg)].ankle)];
}

const std::vector<FootContact>& contactsOf(const BakedClip& clip, bool left) {
    return clip.footContacts[static_cast<std::size_t>(left ? clip.leftLeg : 1 - clip.leftLeg)];
}

// Frames from `from` to `to` going forward round the loop.
int loopDistance(const BakedClip& clip, int from, int to) {
    const int length = clip.loop().length();
    return ((to - from) % length + length) % length;
}

TEST(GaitEvents, TheProjectsWalkStrikesEachFootOncePerCycleHalfACycleApart) {
    const BakedClip clip = bakeFile(THRONG_DEFAULT_CLIP);
    ASSERT_GE(clip.leftLeg, 0);
    EXPECT_EQ(ankleName(clip, clip.leftLeg), "LeftFoot");
    ASSERT_EQ(contactsOf(clip, true).size(), 1U) << "the loop is one gait cycle";
    ASSERT_EQ(contactsOf(clip, false).size(), 1U);
    const FootContact left = contactsOf(clip, true).front(), right = contactsOf(clip, false).front();
    const int length = clip.loop().length();
    // The generator's walk is symmetric: the right foot strikes half a cycle after the left.
    EXPECT_NEAR(loopDistance(clip, left.strike, right.strike), length / 2.0, 1.0);
    // Each foot is down about 60% of a walking cycle (double support twice), and both feet do alike.
    const double leftDown = loopDistance(clip, left.strike, left.lift) / static_cast<double>(length);
    const double rightDown = loopDistance(clip, right.strike, right.lift) / static_cast<double>(length);
    std::printf("project walk: loop %d frames, left down %.2f of the cycle, right %.2f, right strikes %d frames after the left\n", length,
                leftDown, rightDown, loopDistance(clip, left.strike, right.strike));
    EXPECT_GT(leftDown, 0.5);
    EXPECT_LT(leftDown, 0.75);
    EXPECT_NEAR(rightDown, leftDown, 2.0 / length);
}

TEST(GaitEvents, PhaseIsZeroAtTheLeftStrikeAndRisesEvenlyRoundTheLoop) {
    const BakedClip clip = bakeFile(THRONG_DEFAULT_CLIP);
    const int strike = contactsOf(clip, true).front().strike;
    const LoopRange loop = clip.loop();
    const double length = loop.length();
    EXPECT_DOUBLE_EQ(clip.gaitPhaseAt(strike), 0.0);
    for (int k = 0; k < loop.length(); ++k) {
        // The frame k steps after the strike, wrapped into the loop, at a quarter-frame offset.
        const double frame = loop.first + std::fmod(strike - loop.first + k + 0.25, length);
        EXPECT_NEAR(clip.gaitPhaseAt(frame), (k + 0.25) / length, 1e-9) << "frame " << frame;
    }
}

TEST(GaitEvents, SharedCapturesKnowTheirLeftFootAndAlternateTheirFeet) {
    if (!std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) GTEST_SKIP() << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
    // The walks and the run with a gait cycle found: every one strikes right about half a cycle
    // after left (a limp or a misread foot would not).
    for (const char* file : {"cmu_02_01_walk.bvh", "cmu_07_01_walk.bvh", "cmu_16_45_run.bvh", "bvhtoolbox_walk01_19j_zxy_24fps.bvh"}) {
        SCOPED_TRACE(file);
        const BakedClip clip = bakeFile(std::string(THRONG_SHARED_MOCAP_DIR) + "/" + file);
        ASSERT_GE(clip.leftLeg, 0);
        EXPECT_EQ(ankleName(clip, clip.leftLeg).rfind("Left", 0), 0U) << ankleName(clip, clip.leftLeg);
        ASSERT_GT(clip.gaitPeriodFrames, 0);
        const int cycles = static_cast<int>(std::lround(clip.loop().length() / clip.gaitPeriodFrames));
        EXPECT_EQ(static_cast<int>(contactsOf(clip, true).size()), cycles);
        EXPECT_EQ(static_cast<int>(contactsOf(clip, false).size()), cycles);
        for (const FootContact& right : contactsOf(clip, false)) {
            std::printf("%-38s right strike at phase %.3f\n", file, clip.gaitPhaseAt(right.strike));
            EXPECT_NEAR(clip.gaitPhaseAt(right.strike), 0.5, 0.08);
        }
    }
}

TEST(GaitEvents, AClipWithoutStrikesHasNoPhase) {
    if (!std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) GTEST_SKIP() << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
    const BakedClip still = bakeFile(std::string(THRONG_SHARED_MOCAP_DIR) + "/biovision_example_2frames.bvh");
    EXPECT_TRUE(still.footContacts[0].empty() && still.footContacts[1].empty());
    EXPECT_EQ(still.gaitPhaseAt(0.5), -1.0);
    // The dance's pivot foot never lifts: it has no strike, so no phase is timed from it.
    const BakedClip dance = bakeFile(std::string(THRONG_SHARED_MOCAP_DIR) + "/mocapbank_19j_zxy_crlf.bvh");
    ASSERT_GE(dance.leftLeg, 0);
    EXPECT_TRUE(contactsOf(dance, true).empty());
    EXPECT_EQ(dance.gaitPhaseAt(dance.loop().first + 1.0), -1.0);
}

}  // namespace
