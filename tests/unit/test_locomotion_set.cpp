// Locomotion sets: the project's own idle, slow walk, walk and run as one set, gait clocks that
// align clips by phase, the blend that walks at a given speed, and the refusals. The expected
// figures come from the generator's parameters (tools/make_locomotion_set.py), not from the
// code under test: cycles of 1.30, 1.10 and 0.70 s, strides of 1.04, 1.43 and 1.96 m.
#include <gtest/gtest.h>

#include <cmath>

#include "project_clips.h"
#include "throng/motion/locomotion_set.h"

namespace {

using namespace throng::motion;

using unit_test::asset;
using unit_test::bakeFile;

// The project's set in a clip table, in an order that is not by speed.
std::vector<BakedClip> projectClips() {
    return {bakeFile(asset("run.bvh")), bakeFile(asset("idle.bvh")), bakeFile(asset("walk.bvh")), bakeFile(asset("slow_walk.bvh"))};
}

const std::vector<std::uint32_t> kAll{0, 1, 2, 3};

TEST(LocomotionSet, TheProjectsClipsMakeASetOrderedBySpeedWithTheIdleApart) {
    const std::vector<BakedClip> clips = projectClips();
    const LocomotionSet set = makeLocomotionSet(clips, kAll).orThrow();
    ASSERT_TRUE(set.idle.has_value());
    EXPECT_EQ(set.idle->clip, 1U);
    ASSERT_EQ(set.gaits.size(), 3U);
    EXPECT_EQ(set.gaits[0].clip, 3U);  // slow walk
    EXPECT_EQ(set.gaits[1].clip, 2U);  // walk
    EXPECT_EQ(set.gaits[2].clip, 0U);  // run
    const double cycles[] = {1.3, 1.1, 0.7}, speeds[] = {0.8, 1.3, 2.8};
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(set.gaits[k].gait->cycleSeconds(), cycles[k], 1e-5);  // the file's frame time is rounded
        EXPECT_NEAR(set.gaits[k].speed, speeds[k], 0.02 * speeds[k]);
    }
    EXPECT_EQ(set.slowest(), 0.0);
    EXPECT_NEAR(set.fastest(), 1.2 * set.gaits[2].speed, 1e-12);
}

TEST(GaitClock, CountsCyclesFromTheLeftStrikeAndInvertsExactly) {
    const BakedClip walk = bakeFile(asset("walk.bvh"));
    const GaitClock clock = *GaitClock::of(walk);
    const int strike = walk.footContacts[static_cast<std::size_t>(walk.leftLeg)].front().strike;
    EXPECT_NEAR(clock.cyclesAt(strike), std::round(clock.cyclesAt(strike)), 1e-12) << "a left strike is a whole cycle";
    EXPECT_NEAR(clock.cyclesAt(strike + 33.0) - clock.cyclesAt(strike), 0.5, 1e-12) << "66-frame cycle";
    double previous = -1e9;
    for (double frame = -200.0; frame < 400.0; frame += 0.37) {
        const double cycles = clock.cyclesAt(frame);
        EXPECT_GE(cycles, previous);
        EXPECT_NEAR(clock.frameAt(cycles), frame, 1e-9);
        previous = cycles;
    }
    EXPECT_FALSE(GaitClock::of(bakeFile(asset("idle.bvh"))).has_value()) << "standing has no gait";
}

TEST(SpeedBlend, NeighbouringClipsAndAWeightWhoseStrideTimesCadenceIsTheSpeed) {
    const std::vector<BakedClip> clips = projectClips();
    const LocomotionSet set = makeLocomotionSet(clips, kAll).orThrow();
    // Strides and cadences from the generator: 1.04 m per 1.3 s, 1.43 m per 1.1 s.
    for (double v : {1.0, 1.1, 1.2}) {
        const SpeedBlend blend = blendForSpeed(set, v);
        ASSERT_EQ(blend.lower->clip, 3U);
        ASSERT_EQ(blend.upper->clip, 2U);
        const double w = blend.weight;
        const double lowerCycle = blend.lower->gait->cycleSeconds(), upperCycle = blend.upper->gait->cycleSeconds();
        EXPECT_NEAR(lowerCycle, 1.3, 1e-5);
        EXPECT_NEAR(upperCycle, 1.1, 1e-5);
        const double stride = (1 - w) * blend.lower->speed * lowerCycle + w * blend.upper->speed * upperCycle;
        const double cadence = (1 - w) / lowerCycle + w / upperCycle;
        EXPECT_NEAR(stride * cadence, v, 1e-6);
        EXPECT_NEAR(blend.cyclesPerSecond, cadence, 1e-9);
        EXPECT_EQ(blend.playback, 1.0) << "inside the set's range, no stretching";
    }
    // Between idle and the slow walk the slow walk's steps shorten; standing, the idle alone.
    const SpeedBlend standing = blendForSpeed(set, 0.0);
    EXPECT_EQ(standing.lower->clip, 1U);
    EXPECT_EQ(standing.weight, 0.0);
    EXPECT_NEAR(blendForSpeed(set, 0.4).weight, 0.5, 0.15);
    // Past the run: the run, stretched at most 1.2x; the speed is clamped there.
    const SpeedBlend fast = blendForSpeed(set, 50.0);
    EXPECT_EQ(fast.lower->clip, 0U);
    EXPECT_EQ(fast.upper->clip, 0U);
    EXPECT_NEAR(fast.playback, 1.2, 1e-12);
    EXPECT_NEAR(blendForSpeed(set, std::nan("")).weight, 0.0, 1e-12);
}

TEST(SpeedBlend, TheWeightRisesSmoothlyAcrossTheSetsSpeeds) {
    const std::vector<BakedClip> clips = projectClips();
    const LocomotionSet set = makeLocomotionSet(clips, kAll).orThrow();
    // The shown speed (natural speed x playback) is continuous and rising: at a clip's own
    // speed the pair changes, with all the weight on the shared clip.
    double previous = -1.0;
    for (double v = 0.0; v <= set.fastest(); v += 0.01) {
        const SpeedBlend b = blendForSpeed(set, v);
        const double lowerStride = b.lower->gait ? b.lower->speed * b.lower->gait->cycleSeconds() : 0.0;
        const double stride = (1 - b.weight) * lowerStride + b.weight * b.upper->speed * b.upper->gait->cycleSeconds();
        const double shown = stride * b.cyclesPerSecond;
        EXPECT_NEAR(shown, v, 1e-9) << "at " << v;
        EXPECT_GT(shown, previous);
        previous = shown;
    }
}

TEST(LocomotionSet, RefusesMismatchedSkeletonsTwoIdlesAndNoGait) {
    std::vector<BakedClip> clips = projectClips();
    clips.push_back(clips[2]);  // the walk with one joint renamed: another skeleton
    clips.back().jointNames[5] = "LeftAnkle";
    clips.push_back(clips[1]);  // a second idle
    const auto refused = [&](std::vector<std::uint32_t> members, const std::string& words) {
        auto set = makeLocomotionSet(clips, members);
        ASSERT_FALSE(set.ok()) << words;
        EXPECT_NE(set.error().message.find(words), std::string::npos) << set.error().message;
        EXPECT_EQ(set.error().message.find('\n'), std::string::npos) << "one line";
    };
    refused({2, 4}, "different skeleton");
    refused({1, 2, 5}, "at most one idle");
    refused({1}, "no clip shows a gait");
    refused({2, 2}, "nearly the same speed");
    refused({}, "at least one clip");
    refused({2, 9}, "doesn't exist");
}

// The clock reads through stored reciprocals: at every whole cycle, however far from the clip's
// own loop (where a product can round across a loop's edge), it must still invert exactly,
// also with more than one cycle in a loop.
TEST(GaitClock, InvertsAtEveryWholeCycleFarFromTheLoop) {
    BakeOptions twoCycles;
    twoCycles.loop = LoopRange{0, 132};  // walk.bvh: two 66-frame cycles
    const BakedClip walk = bake(loadBvhFile(asset("walk.bvh")).orThrow(), twoCycles).orThrow();
    const GaitClock clock = *GaitClock::of(walk);
    ASSERT_EQ(clock.cycles(), 2);
    for (const double base : {0.0, 1e3, 1e6, -1e6, 123457.0}) {
        double previous = -1e300;
        for (int k = -7; k <= 7; ++k) {
            const double cycles = base + k;
            const double frame = clock.frameAt(cycles);
            EXPECT_GT(frame, previous) << cycles;
            EXPECT_NEAR(clock.cyclesAt(frame), cycles, 1e-7) << cycles;
            for (const double part : {0.25, 0.5, 0.999}) EXPECT_NEAR(clock.cyclesAt(clock.frameAt(cycles + part)), cycles + part, 1e-7);
            previous = frame;
        }
    }
}

}  // namespace
