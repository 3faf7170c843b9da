// Crowd locomotion: the paper's update, time-step independence, goals without foot sliding,
// collision avoidance, determinism across thread counts, and spawning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "throng/crowd/crowd.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng;
using crowd::Crowd;
using crowd::CrowdSetup;
using crowd::Mode;

const motion::BakedClip& walkClip() {
    static const motion::BakedClip clip = motion::bake(motion::loadBvhFile(THRONG_DEFAULT_CLIP).orThrow()).orThrow();
    return clip;
}

CrowdSetup oneGroup(int count, Mode mode, glm::vec2 area, float heading = 0.0F, std::uint64_t seed = 1, unsigned threads = 1) {
    CrowdSetup setup;
    setup.groups.push_back({.count = count, .clips = {}, .region = {glm::vec2(0.0F), area}, .mode = mode,
                            .speedRange = {1.0F, 1.0F}, .heading = heading, .locomotion = std::nullopt, .groundSpeed = {1.0F, 1.5F}});
    setup.area = {glm::vec2(0.0F), area};
    setup.seed = seed;
    setup.threads = threads;
    return setup;
}

// Root position of the clip's track at unwrapped frame x, computed here from the raw per-frame
// ground positions: inside the loop by interpolation, each earlier loop adding the loop's own
// travel. Valid for a loop that doesn't turn, which the project's clip doesn't.
glm::dvec2 unwrappedRoot(const motion::BakedClip& clip, double x) {
    const auto& frames = clip.rootMotion.frames();
    const motion::LoopRange loop = clip.loop();
    const double loops = std::floor((x - loop.first) / loop.length());
    const double inside = x - loops * loop.length();
    const auto lower = static_cast<std::size_t>(std::floor(inside));
    const double t = inside - std::floor(inside);
    const glm::dvec2 p = glm::mix(frames[lower].position, frames[lower + 1].position, t);
    return p + loops * (frames[static_cast<std::size_t>(loop.last)].position - frames[static_cast<std::size_t>(loop.first)].position);
}

TEST(Crowd, GroupModeReproducesThePapersUpdateOverThreeLoops) {
    const motion::BakedClip& clip = walkClip();
    ASSERT_NEAR(clip.rootMotion.loopDisplacement().yaw, 0.0, 1e-6) << "the check below assumes a straight loop";
    const float heading = 0.7F;  // M_o
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), oneGroup(1, Mode::Group, {4, 4}, heading)).orThrow();
    const glm::dvec2 start = crowd.groundFrame(0).position;
    const double x0 = crowd.frame(0);
    const double psi0 = clip.rootMotion.at(x0).yaw;
    const double dt = 1.0 / 30.0;
    const int steps = static_cast<int>(std::ceil(3.0 * clip.loop().length() * clip.frameTime / dt));
    double worst = 0;
    double unwrapped = x0;
    for (int s = 0; s < steps; ++s) {
        crowd.step(std::span(&clip, 1), dt);
        unwrapped += dt / clip.frameTime;
        // C_i = C_0 + M_o (p0^i - p0^0), with the clip's displacement taken in the character's
        // frame at the start (the clip's heading there maps onto M_o), scaled with the body.
        const glm::dvec2 expected =
            start + static_cast<double>(crowd.scale(0)) *
                        rotateGround(unwrappedRoot(clip, unwrapped) - unwrappedRoot(clip, x0), heading - psi0);
        worst = std::max(worst, glm::length(crowd.groundFrame(0).position - expected));
    }
    std::printf("group mode over %d steps (3 loops): worst deviation from the paper's update %.3g m\n", steps, worst);
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(glm::length(crowd.groundFrame(0).position - start), 3.0);  // it did walk
}

TEST(Crowd, GroupModeSharesOneOrientation) {
    const motion::BakedClip& clip = walkClip();
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), oneGroup(30, Mode::Group, {15, 15}, -1.1F)).orThrow();
    std::vector<glm::dvec2> start;
    for (int i = 0; i < crowd.size(); ++i) start.push_back(crowd.groundFrame(i).position);
    for (int s = 0; s < 66; ++s) crowd.step(std::span(&clip, 1), 1.0 / 60.0);  // exactly one loop
    for (int i = 0; i < crowd.size(); ++i) {
        const glm::dvec2 moved = crowd.groundFrame(i).position - start[static_cast<std::size_t>(i)];
        EXPECT_NEAR(std::atan2(moved.x, moved.y), -1.1, 0.02) << i;
    }
}

TEST(Crowd, AnyStepSizeGivesTheSamePathInGroupMode) {
    const motion::BakedClip& clip = walkClip();
    const CrowdSetup setup = oneGroup(20, Mode::Group, {10, 10}, 0.3F);
    Crowd coarse = Crowd::spawn(std::span(&clip, 1), setup).orThrow();
    Crowd fine = Crowd::spawn(std::span(&clip, 1), setup).orThrow();
    coarse.step(std::span(&clip, 1), 2.5);  // crosses the loop seam twice
    for (int s = 0; s < 7; ++s) fine.step(std::span(&clip, 1), 2.5 / 7.0);
    for (int i = 0; i < coarse.size(); ++i) {
        EXPECT_LT(glm::length(coarse.groundFrame(i).position - fine.groundFrame(i).position), 1e-9);
        EXPECT_NEAR(coarse.groundFrame(i).yaw, fine.groundFrame(i).yaw, 1e-9);
        EXPECT_NEAR(coarse.frame(i), fine.frame(i), 1e-9);
    }
}

TEST(Crowd, GoalsModePlaybackMatchesGroundSpeed) {
    const motion::BakedClip& clip = walkClip();
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), oneGroup(40, Mode::Goals, {30, 30})).orThrow();
    const double dt = 1.0 / 30.0, window = 2.0;
    const int windowSteps = static_cast<int>(window / dt);
    double worst = 0;
    for (int w = 0; w < 10; ++w) {
        std::vector<double> path(static_cast<std::size_t>(crowd.size()), 0.0), played(path.size(), 0.0);
        for (int s = 0; s < windowSteps; ++s) {
            std::vector<glm::dvec2> before;
            for (int i = 0; i < crowd.size(); ++i) before.push_back(crowd.groundFrame(i).position);
            crowd.step(std::span(&clip, 1), dt);
            for (int i = 0; i < crowd.size(); ++i) {
                path[static_cast<std::size_t>(i)] += glm::length(crowd.groundFrame(i).position - before[static_cast<std::size_t>(i)]);
                played[static_cast<std::size_t>(i)] += Crowd::clipSpeed(clip) * crowd.scale(i) * crowd.playback(i) * dt;
            }
        }
        for (std::size_t i = 0; i < path.size(); ++i) worst = std::max(worst, std::abs(path[i] / played[i] - 1.0));
    }
    std::printf("goals mode: worst ground-speed / playback-speed mismatch over 2 s windows %.2f%%\n", worst * 100);
    EXPECT_LT(worst, 0.10);
}

TEST(Crowd, GoalsModeReachesGoals) {
    const motion::BakedClip& clip = walkClip();
    CrowdSetup setup = oneGroup(5, Mode::Goals, {10, 10});
    setup.waypoints = {{-8, 0}, {8, 0}};
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), setup).orThrow();
    int switches = 0;
    std::vector<glm::vec2> goals;
    for (int i = 0; i < crowd.size(); ++i) goals.push_back(crowd.goal(i));
    for (int s = 0; s < 30 * 40; ++s) {
        crowd.step(std::span(&clip, 1), 1.0 / 30.0);
        for (int i = 0; i < crowd.size(); ++i)
            if (crowd.goal(i) != goals[static_cast<std::size_t>(i)]) {
                ++switches;
                goals[static_cast<std::size_t>(i)] = crowd.goal(i);
            }
    }
    EXPECT_GE(switches, 5 * 3);  // 16 m legs at 1.3 m/s: several arrivals each in 40 s
}

// While steering turns a walker round a square, a foot in the air turns ahead, toward the
// heading its stance will turn the body to, and the stance takes that twist back: feet land
// twisted the way the body turns and leave the ground less twisted than they landed. (A foot
// that lifts twisted slides its toe as the heel comes up. Without turning ahead, feet land
// straight and lift twisted: 0.30 rad on average here.)
TEST(Crowd, TurningFeetLandTurnedAheadAndLeaveTheGroundLessTwisted) {
    const motion::BakedClip& clip = walkClip();
    CrowdSetup setup = oneGroup(1, Mode::Goals, {1, 1});
    setup.waypoints = {{3, 3}, {-3, 3}, {-3, -3}, {3, -3}};
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), setup).orThrow();
    std::vector<crowd::CharacterState> state(1);
    const double dt = 1.0 / 30.0;
    glm::dvec2 previousHold = clip.footHoldAt(crowd.frame(0));
    double landingTwist = 0.0, liftTwist = 0.0;
    int landings = 0, lifts = 0, landingsAhead = 0;
    // The body turns in the gait's turning windows, not while both feet are down, so "while
    // turning" is judged over the last half second.
    const int window = 15;
    std::vector<double> yaws;
    for (int s = 0; s < 30 * 60; ++s) {
        yaws.push_back(crowd.groundFrame(0).yaw);
        crowd.step(std::span(&clip, 1), dt);
        crowd.pack(state);
        const double back = yaws[yaws.size() > window ? yaws.size() - window : 0];
        const double turning = std::remainder(crowd.groundFrame(0).yaw - back, 2.0 * std::numbers::pi) / (window * dt);
        const glm::dvec2 hold = clip.footHoldAt(crowd.frame(0));
        for (int l = 0; l < 2; ++l) {
            const double twist = state[0].footTwist[l];
            if (previousHold[l] < 0.5 && hold[l] >= 0.5 && std::abs(turning) > 0.35) {
                landingTwist += std::abs(twist), ++landings;
                landingsAhead += twist * turning > 0 ? 1 : 0;
            }
            if (previousHold[l] >= 0.5 && hold[l] < 0.5 && std::abs(turning) > 0.35) liftTwist += std::abs(twist), ++lifts;
        }
        previousHold = hold;
    }
    ASSERT_GT(landings, 10);
    ASSERT_GT(lifts, 10);
    landingTwist /= landings, liftTwist /= lifts;
    std::printf("turning round a square: %d landings while turning, mean |twist| %.3f rad, %d of them turned the way the body "
                "turns; %d lift-offs while turning, mean |twist| %.3f rad\n",
                landings, landingTwist, landingsAhead, lifts, liftTwist);
    EXPECT_GT(landingTwist, 0.05);
    EXPECT_GE(landingsAhead, landings * 9 / 10);
    EXPECT_LT(liftTwist, landingTwist);
}

// Fraction of (character, step) samples whose nearest neighbour is closer than 90% of the sum
// of their radii; the smallest such ratio seen.
struct Separation {
    double violatingFraction = 0;
    double smallestRatio = 1e9;
};

Separation measureAvoidance(Crowd& crowd, const motion::BakedClip& clip, double seconds) {
    const double dt = 1.0 / 30.0;
    long long samples = 0, violating = 0;
    Separation result;
    for (int s = 0; s < static_cast<int>(seconds / dt); ++s) {
        crowd.step(std::span(&clip, 1), dt);
        for (int i = 0; i < crowd.size(); ++i) {
            double nearest = 1e9;
            for (int j = 0; j < crowd.size(); ++j) {
                if (j == i) continue;
                const double ratio = glm::length(crowd.groundFrame(i).position - crowd.groundFrame(j).position) /
                                     (crowd.radius(i) + crowd.radius(j));
                nearest = std::min(nearest, ratio);
            }
            result.smallestRatio = std::min(result.smallestRatio, nearest);
            violating += nearest < 0.9 ? 1 : 0;
            ++samples;
        }
    }
    result.violatingFraction = static_cast<double>(violating) / static_cast<double>(samples);
    return result;
}

TEST(Crowd, AvoidModeKeepsFiveHundredCharactersApartFor60Seconds) {
    const motion::BakedClip& clip = walkClip();
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), oneGroup(500, Mode::Avoid, {20, 20}, 0.0F, 3, 2)).orThrow();
    const Separation separation = measureAvoidance(crowd, clip, 60.0);
    std::printf("avoid mode, 500 characters in 20 x 20 m for 60 s: %.4f%% of samples closer than 90%% of the radii sum; "
                "closest %.2f of the radii sum\n",
                separation.violatingFraction * 100, separation.smallestRatio);
    EXPECT_LE(separation.violatingFraction, 0.001);
}

TEST(Crowd, WithoutAvoidanceTheSameCrowdCollides) {
    // The control for the test above: goals mode walks through people.
    const motion::BakedClip& clip = walkClip();
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), oneGroup(500, Mode::Goals, {20, 20}, 0.0F, 3, 2)).orThrow();
    EXPECT_GT(measureAvoidance(crowd, clip, 10.0).violatingFraction, 0.01);
}

TEST(Crowd, ResultsDoNotDependOnTheThreadCount) {
    const motion::BakedClip& clip = walkClip();
    Crowd one = Crowd::spawn(std::span(&clip, 1), oneGroup(300, Mode::Avoid, {15, 15}, 0.0F, 5, 1)).orThrow();
    Crowd two = Crowd::spawn(std::span(&clip, 1), oneGroup(300, Mode::Avoid, {15, 15}, 0.0F, 5, 2)).orThrow();
    ASSERT_EQ(two.threadCount(), 2U);
    for (int s = 0; s < 120; ++s) {
        one.step(std::span(&clip, 1), 1.0 / 30.0);
        two.step(std::span(&clip, 1), 1.0 / 30.0);
    }
    for (int i = 0; i < one.size(); ++i) {
        ASSERT_EQ(one.groundFrame(i).position, two.groundFrame(i).position) << i;
        ASSERT_EQ(one.frame(i), two.frame(i)) << i;
    }
}

TEST(Crowd, APackOnTheStepsThreadsWritesWhatOneThreadWrites) {
    // Past kParallelPackCharacters the pack runs on the step's threads: every character's
    // record written, and the same bytes as one thread writes.
    const motion::BakedClip& clip = walkClip();
    const int count = static_cast<int>(Crowd::kParallelPackCharacters) + 1001;
    Crowd one = Crowd::spawn(std::span(&clip, 1), oneGroup(count, Mode::Group, {600, 600}, 0.0F, 4, 1)).orThrow();
    Crowd two = Crowd::spawn(std::span(&clip, 1), oneGroup(count, Mode::Group, {600, 600}, 0.0F, 4, 2)).orThrow();
    ASSERT_EQ(two.threadCount(), 2U);
    for (int s = 0; s < 3; ++s) {
        one.step(std::span(&clip, 1), 1.0 / 30.0);
        two.step(std::span(&clip, 1), 1.0 / 30.0);
    }
    crowd::CharacterState unwritten;
    unwritten.frame = std::numeric_limits<float>::quiet_NaN();
    std::vector<crowd::CharacterState> packedByOne(static_cast<std::size_t>(count), unwritten), packedByTwo(packedByOne.size(), unwritten);
    one.pack(packedByOne);
    two.pack(packedByTwo);
    for (int i = 0; i < count; ++i) {
        ASSERT_EQ(packedByTwo[static_cast<std::size_t>(i)].groundFrame.x, static_cast<float>(two.groundFrame(i).position.x)) << i;
        ASSERT_EQ(packedByTwo[static_cast<std::size_t>(i)].frame, static_cast<float>(two.frame(i))) << i;
    }
    EXPECT_EQ(std::memcmp(packedByOne.data(), packedByTwo.data(), packedByOne.size() * sizeof(crowd::CharacterState)), 0);
}

TEST(Crowd, APackOfARunWritesThoseCharactersAsTheWholePackDoes) {
    // A renderer's batches are packed run by run, straight into its memory: each run (past the
    // parallel threshold on two threads, and short ones on one) holds the whole pack's records.
    const motion::BakedClip& clip = walkClip();
    const int count = static_cast<int>(Crowd::kParallelPackCharacters) * 2 + 77;
    Crowd crowd = Crowd::spawn(std::span(&clip, 1), oneGroup(count, Mode::Group, {800, 800}, 0.0F, 4, 2)).orThrow();
    crowd.step(std::span(&clip, 1), 1.0 / 30.0);
    std::vector<crowd::CharacterState> whole(static_cast<std::size_t>(count));
    crowd.pack(whole);
    const std::size_t runs[][2] = {{0, Crowd::kParallelPackCharacters + 5}, {Crowd::kParallelPackCharacters + 5, Crowd::kParallelPackCharacters + 72},
                                   {static_cast<std::size_t>(count) - 3, 3}, {17, 1}, {static_cast<std::size_t>(count), 0}};
    for (const auto& [first, size] : runs) {
        crowd::CharacterState unwritten;
        unwritten.frame = std::numeric_limits<float>::quiet_NaN();
        std::vector<crowd::CharacterState> run(size, unwritten);
        crowd.pack(first, run);
        // Compared as bytes with std::ranges::equal: memcmp may not be given the empty run's null data.
        EXPECT_TRUE(std::ranges::equal(std::as_bytes(std::span(run)), std::as_bytes(std::span(whole).subspan(first, size)))) << first << " + " << size;
    }
    std::vector<crowd::CharacterState> pastTheEnd(2);
    EXPECT_THROW(crowd.pack(static_cast<std::size_t>(count) - 1, pastTheEnd), std::out_of_range);
    EXPECT_THROW(crowd.pack(static_cast<std::size_t>(count) + 1, std::span(pastTheEnd.data(), 0)), std::out_of_range);
}

TEST(Crowd, SpawnPlacesBodiesWithoutOverlapAndTheSeedMatters) {
    const motion::BakedClip& clip = walkClip();
    const Crowd a = Crowd::spawn(std::span(&clip, 1), oneGroup(400, Mode::Group, {20, 20}, 0.0F, 1)).orThrow();
    const Crowd b = Crowd::spawn(std::span(&clip, 1), oneGroup(400, Mode::Group, {20, 20}, 0.0F, 2)).orThrow();
    int same = 0;
    for (int i = 0; i < a.size(); ++i) {
        const glm::dvec2 p = a.groundFrame(i).position;
        EXPECT_LE(std::abs(p.x), 10.0);
        EXPECT_LE(std::abs(p.y), 10.0);
        for (int j = i + 1; j < a.size(); ++j)
            ASSERT_GE(glm::length(p - a.groundFrame(j).position), a.radius(i) + a.radius(j)) << i << " " << j;
        same += p == b.groundFrame(i).position ? 1 : 0;
    }
    EXPECT_EQ(same, 0);
}

TEST(Crowd, SpawnRefusesBadSetups) {
    const motion::BakedClip& clip = walkClip();
    auto overfull = Crowd::spawn(std::span(&clip, 1), oneGroup(500, Mode::Group, {3, 3}));
    ASSERT_FALSE(overfull);
    EXPECT_NE(overfull.error().message.find("too small"), std::string::npos);
    EXPECT_FALSE(Crowd::spawn(std::span(&clip, 1), oneGroup(0, Mode::Group, {3, 3})));
    CrowdSetup badClip = oneGroup(2, Mode::Group, {3, 3});
    badClip.groups[0].clips = {4};
    EXPECT_FALSE(Crowd::spawn(std::span(&clip, 1), badClip));
    EXPECT_FALSE(Crowd::spawn({}, oneGroup(2, Mode::Group, {3, 3})));
}

TEST(Crowd, ModeNamesRoundTrip) {
    for (Mode mode : {Mode::Group, Mode::Goals, Mode::Avoid}) EXPECT_EQ(crowd::modeFromName(crowd::modeName(mode)), mode);
    EXPECT_FALSE(crowd::modeFromName("flock"));
}

TEST(Crowd, ABadThrongThreadsComesBackAsSpawnsError) {
    // The pool's size comes from THRONG_THREADS when the setup leaves it to the machine:
    // refused through spawn's Result, which its callers report, never thrown past it.
    const motion::BakedClip& clip = walkClip();
    ::setenv("THRONG_THREADS", "abc", 1);
    auto refused = Crowd::spawn(std::span(&clip, 1), oneGroup(3, Mode::Group, {5, 5}, 0.0F, 1, 0));
    auto given = Crowd::spawn(std::span(&clip, 1), oneGroup(3, Mode::Group, {5, 5}, 0.0F, 1, 2));  // --threads wins
    ::unsetenv("THRONG_THREADS");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("THRONG_THREADS: expected a thread count from 1 to 256, found 'abc'"), std::string::npos)
        << refused.error().describe();
    EXPECT_TRUE(given.ok());
}

}  // namespace
