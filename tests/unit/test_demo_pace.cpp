// The demo's walking pace (Up/Down, issue #12) and the HUD's blend summary (demo_pace.h), on a
// real crowd of the project's set: a press shifts every set character's own desired speed by
// kPaceStep, clamped by the crowd; presses back give each its own speed again; characters
// that play one clip are left alone; and the blend the summary reports follows to a run.
#include <gtest/gtest.h>

#include <string>

#include "demo_pace.h"
#include "project_clips.h"
#include "scene_file.h"

namespace {

using namespace throng;
using app::CrowdPace;
using app::PaceChange;

using unit_test::asset;
using unit_test::projectClips;  // 0 idle, 1 slow walk, 2 walk, 3 run

constexpr int kBlending = 20;  // the demo's default crowd: the set at 1.0 to 1.6 m/s
constexpr int kSingle = 5;     // and, after them, characters that play the walk alone

crowd::CrowdSetup paceSetup(bool withSet = true) {
    crowd::CrowdSetup setup;
    const std::vector<std::uint32_t> members{0, 1, 2, 3};
    setup.locomotion = {motion::makeLocomotionSet(projectClips(), members).orThrow()};
    crowd::GroupSpec blending;
    blending.count = kBlending;
    blending.region = {{0.0F, 0.0F}, {12.0F, 12.0F}};
    blending.locomotion = 0U;
    blending.groundSpeed = {1.0F, 1.6F};
    if (withSet) setup.groups.push_back(blending);
    crowd::GroupSpec single;
    single.count = kSingle;
    single.clips = {2};
    single.region = {{20.0F, 0.0F}, {8.0F, 8.0F}};
    setup.groups.push_back(single);
    setup.threads = 1;
    return setup;
}

crowd::Crowd spawn(const crowd::CrowdSetup& setup) { return crowd::Crowd::spawn(projectClips(), setup).orThrow(); }

void run(crowd::Crowd& crowd, CrowdPace& pace, double seconds) {
    for (int s = 0; s < static_cast<int>(seconds * 60.0); ++s) {
        crowd.step(projectClips(), 1.0 / 60.0);
        pace.keep(crowd);
    }
}

std::vector<float> desiredSpeeds(const crowd::Crowd& crowd) {
    std::vector<float> speeds;
    for (int i = 0; i < crowd.size(); ++i) speeds.push_back(crowd.desiredSpeed(i));
    return speeds;
}

double fastest(const crowd::Crowd& crowd, int i) { return crowd.locomotion(i)->fastest() * crowd.scale(i); }

double shareOf(const app::PaceSummary& summary, std::uint32_t clip) {
    for (const app::ClipShare& share : summary.shares)
        if (share.clip == clip) return share.weight;
    return 0.0;
}

TEST(DemoPace, APressShiftsEverySetCharacterByTheStepAndLeavesSingleClipsAlone) {
    crowd::Crowd crowd = spawn(paceSetup());
    CrowdPace pace;
    pace.adopt(crowd);
    const std::vector<float> before = desiredSpeeds(crowd);
    EXPECT_EQ(pace.shift(crowd, +1), PaceChange::Changed);
    EXPECT_EQ(pace.offset(), app::kPaceStep);
    for (int i = 0; i < kBlending; ++i)
        EXPECT_FLOAT_EQ(crowd.desiredSpeed(i), std::min(before[static_cast<std::size_t>(i)] + app::kPaceStep, static_cast<float>(fastest(crowd, i))));
    for (int i = kBlending; i < crowd.size(); ++i) {
        EXPECT_EQ(crowd.desiredSpeed(i), 0.0F) << "a single clip has no desired speed";
        EXPECT_EQ(crowd.clip(i), 2U);
    }
}

TEST(DemoPace, FourPressesUpRunAndTheBlendFollowsThreeDownStand) {
    crowd::Crowd crowd = spawn(paceSetup());
    CrowdPace pace;
    pace.adopt(crowd);
    run(crowd, pace, 1.0);
    const app::PaceSummary walking = app::summarizePace(crowd);
    EXPECT_EQ(walking.blending, kBlending);
    EXPECT_EQ(walking.characters, kBlending + kSingle);
    EXPECT_NEAR(walking.desired, 1.3, 0.15);
    EXPECT_LT(shareOf(walking, 3), 0.2) << "the default crowd walks";
    for (int press = 0; press < 4; ++press) EXPECT_EQ(pace.shift(crowd, +1), PaceChange::Changed);
    EXPECT_NEAR(app::summarizePace(crowd).desired, walking.desired + 2.0, 0.15) << "a few clamp at the set's fastest";
    run(crowd, pace, 3.0);  // 1.5 m/s² from ~1.3 to ~3.3 m/s: under 1.5 s
    const app::PaceSummary running = app::summarizePace(crowd);
    EXPECT_NEAR(running.actual, running.desired, 0.01) << "group mode walks at the speed wanted";
    EXPECT_GT(shareOf(running, 3), 0.9) << "the blend moved to the run";
    for (int press = 0; press < 7; ++press) pace.shift(crowd, -1);  // back four, then three more
    EXPECT_FLOAT_EQ(pace.offset(), -3.0F * app::kPaceStep);
    run(crowd, pace, 4.0);
    const app::PaceSummary standing = app::summarizePace(crowd);
    EXPECT_LT(standing.actual, 0.1);
    EXPECT_GT(shareOf(standing, 0), 0.9) << "the blend moved to the idle";
}

TEST(DemoPace, PressesBackGiveEveryCharacterItsOwnSpeedAgain) {
    crowd::Crowd crowd = spawn(paceSetup());
    CrowdPace pace;
    pace.adopt(crowd);
    const std::vector<float> own = desiredSpeeds(crowd);
    for (int press = 0; press < 5; ++press) pace.shift(crowd, +1);  // past the fastest for most
    run(crowd, pace, 0.5);
    for (int press = 0; press < 5; ++press) pace.shift(crowd, -1);
    EXPECT_EQ(pace.offset(), 0.0F);
    EXPECT_EQ(desiredSpeeds(crowd), own) << "the variety comes back, not one clamped speed for all";
}

TEST(DemoPace, APressPastEveryCharactersLimitIsRefusedAndNotCounted) {
    crowd::Crowd crowd = spawn(paceSetup());
    CrowdPace pace;
    pace.adopt(crowd);
    int presses = 0;
    while (pace.shift(crowd, +1) == PaceChange::Changed) ASSERT_LT(++presses, 20);
    const float top = pace.offset();
    EXPECT_EQ(pace.shift(crowd, +1), PaceChange::AtLimit);
    EXPECT_EQ(pace.offset(), top) << "presses that change nothing would only have to be undone";
    for (int i = 0; i < kBlending; ++i) EXPECT_FLOAT_EQ(crowd.desiredSpeed(i), static_cast<float>(fastest(crowd, i)));
    EXPECT_EQ(pace.shift(crowd, -1), PaceChange::Changed) << "one press down slows someone at once";
    while (pace.shift(crowd, -1) == PaceChange::Changed) ASSERT_LT(++presses, 40);
    for (int i = 0; i < kBlending; ++i) EXPECT_EQ(crowd.desiredSpeed(i), 0.0F) << "the set's idle: standing";
}

TEST(DemoPace, WithoutASetThePaceKeysSayTheyChangeNothing) {
    crowd::Crowd crowd = spawn(paceSetup(false));
    CrowdPace pace;
    pace.adopt(crowd);
    EXPECT_EQ(pace.shift(crowd, +1), PaceChange::NoSet);
    EXPECT_EQ(pace.offset(), 0.0F);
    const app::PaceSummary summary = app::summarizePace(crowd);
    EXPECT_EQ(summary.blending, 0);
    EXPECT_TRUE(summary.shares.empty());
    const std::vector<std::string> lines = app::describePace(summary, {}, pace.offset());
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_NE(lines[0].find("changes nothing"), std::string::npos) << lines[0];
}

TEST(DemoPace, ARespawnedCrowdKeepsThePaceChosen) {
    const crowd::CrowdSetup setup = paceSetup();
    crowd::Crowd first = spawn(setup);
    CrowdPace pace;
    pace.adopt(first);
    pace.shift(first, -1);
    pace.shift(first, -1);
    crowd::Crowd again = spawn(setup);  // the same seed: the same own speeds
    const std::vector<float> own = desiredSpeeds(again);
    pace.adopt(again);
    for (int i = 0; i < kBlending; ++i) EXPECT_FLOAT_EQ(again.desiredSpeed(i), std::max(own[static_cast<std::size_t>(i)] - 1.0F, 0.0F));
}

TEST(DemoPace, AnEventsNewSpeedsTakeThePaceToo) {
    crowd::CrowdSetup setup = paceSetup();
    crowd::CrowdEvent slowDown;
    slowDown.time = 1.0;
    slowDown.groundSpeed = glm::vec2(0.8F, 0.8F);
    setup.events.push_back(slowDown);
    crowd::Crowd crowd = spawn(setup);
    CrowdPace pace;
    pace.adopt(crowd);
    pace.shift(crowd, +1);
    run(crowd, pace, 1.5);
    for (int i = 0; i < kBlending; ++i) EXPECT_FLOAT_EQ(crowd.desiredSpeed(i), 0.8F + app::kPaceStep);
    pace.shift(crowd, -1);
    for (int i = 0; i < kBlending; ++i) EXPECT_FLOAT_EQ(crowd.desiredSpeed(i), 0.8F) << "the event's speed is the character's own now";
}

TEST(DemoPace, OneCharactersSummaryIsItsPoseWeights) {
    crowd::Crowd crowd = spawn(paceSetup());
    CrowdPace pace;
    run(crowd, pace, 0.5);
    const app::PaceSummary one = app::summarizePace(crowd, 3);
    EXPECT_EQ(one.characters, 1);
    EXPECT_EQ(one.blending, 1);
    EXPECT_EQ(one.desired, crowd.desiredSpeed(3));
    EXPECT_EQ(one.actual, crowd.speed(3));
    double total = 0.0;
    for (const app::ClipShare& share : one.shares) total += share.weight;
    EXPECT_NEAR(total, 1.0, 1e-9);
    if (crowd.clip(3) != crowd.blendClip(3)) {
        EXPECT_NEAR(shareOf(one, crowd.blendClip(3)), crowd.blendWeight(3), 1e-6);
    }
    const app::PaceSummary single = app::summarizePace(crowd, kBlending);  // plays the walk alone
    EXPECT_EQ(single.blending, 0);
    ASSERT_EQ(single.shares.size(), 1U);
    EXPECT_EQ(single.shares[0].clip, 2U);
    const std::vector<std::string> names{"idle", "slow_walk", "walk", "run"};
    EXPECT_EQ(app::describePace(single, names, 0.0F, kBlending),
              (std::vector<std::string>{"character 20 plays one clip at its own pace", "walk 100%"}));
}

TEST(DemoPace, TheHudLinesNameTheClipsAndLeaveOutTraces) {
    app::PaceSummary summary{.blending = 2, .characters = 3, .desired = 1.8, .actual = 1.25,
                             .shares = {{1, 0.004}, {2, 0.396}, {3, 0.6}}};
    const std::vector<std::string> names{"idle", "slow_walk", "walk"};  // no name for clip 3
    EXPECT_EQ(app::describePace(summary, names, 0.5F),
              (std::vector<std::string>{"pace +0.5 m/s: wants 1.80, walks 1.25 m/s (2 of 3 blend)", "walk 40% / clip 3 60%"}));
    summary.characters = 2;
    EXPECT_EQ(app::describePace(summary, names, -1.0F, 7).front(), "character 7, pace -1.0 m/s: wants 1.80, walks 1.25 m/s");
}

TEST(DemoPace, SceneClipsAreNamedAsTheSceneNamesThem) {
    const std::string path = asset("test-pace-scene.json");
    auto scene = app::parseScene(R"({"clips": [{"name": "stroll", "path": "walk.bvh"}, "run.bvh"],
                                     "groups": [{"count": 1, "clips": ["stroll"], "region": {"centre": [0, 0], "size": [4, 4]}}]})",
                                 path);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    EXPECT_EQ(scene.value().clipNames, (std::vector<std::string>{"stroll", "run"}));
}

}  // namespace
