// Transitions, events, starting and stopping (issue #12): a crossfade hands a character from
// one clip (or blend) to another over the fade, keeping the gait phase; events schedule them
// per group; a character of a set with an idle slows to stand at its goal, pauses and sets off.
// Phases are read with BakedClip::gaitPhaseAt (the bake's own contacts), not the crowd's clocks.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "project_clips.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng;

using unit_test::projectClips;  // 0 idle, 1 slow walk, 2 walk, 3 run

constexpr double kStep = 1.0 / 60.0;

// An event at `time` for `group`, changed by `edit`.
template <typename Edit>
crowd::CrowdEvent event(double time, std::uint32_t group, Edit edit) {
    crowd::CrowdEvent e;
    e.time = time;
    e.group = group;
    edit(e);
    return e;
}

double phaseGap(double a, double b) { return std::abs(std::remainder(a - b, 1.0)); }

crowd::CrowdSetup oneWalker() {
    crowd::GroupSpec group;
    group.count = 1;
    group.clips = {2};
    group.region = {{0.0F, 0.0F}, {0.5F, 0.5F}};
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.threads = 1;
    return setup;
}

TEST(CrowdTransitions, AnEventCrossfadesToAnotherClipOverItsFadeInStep) {
    const auto& clips = projectClips();
    crowd::CrowdSetup setup = oneWalker();
    setup.events = {event(1.0, 0, [](crowd::CrowdEvent& e) { e.clip = 3U; })};
    crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
    double walkPhase = -1.0;
    float previousWeight = 1.0F;
    int fadingSteps = 0;
    for (int step = 1; step <= 120; ++step) {
        const double phaseBefore = clips[crowd.clip(0)].gaitPhaseAt(crowd.frame(0));
        crowd.step(clips, kStep);
        // The event applies at the start of the first step that begins at or after its time.
        const double t = (step - 1) * kStep;
        if (t < 1.0 - 1e-9) {
            EXPECT_EQ(crowd.fromWeight(0), 0.0F);
            EXPECT_EQ(crowd.clip(0), 2U);
            walkPhase = phaseBefore;
            continue;
        }
        EXPECT_EQ(crowd.clip(0), 3U) << "the run plays from the event on";
        if (crowd.fromWeight(0) > 0) {
            ++fadingSteps;
            EXPECT_EQ(crowd.fromClip(0), 2U);
            EXPECT_LT(crowd.fromWeight(0), previousWeight);
            // The walk keeps step with the run: both at one gait phase throughout the fade.
            EXPECT_LT(phaseGap(clips[2].gaitPhaseAt(crowd.fromFrame(0)), clips[3].gaitPhaseAt(crowd.frame(0))), 0.02) << "at " << t << " s";
            previousWeight = crowd.fromWeight(0);
        }
    }
    EXPECT_GE(walkPhase, 0.0);
    EXPECT_NEAR(fadingSteps, 0.3 / kStep, 1.5) << "the fade lasts its 0.3 s";
    std::vector<crowd::CharacterState> state(1);
    crowd.pack(state);
    EXPECT_EQ(state[0].fromWeight, 0.0F);
}

TEST(CrowdTransitions, TheIncomingGaitStartsAtThePhaseShown) {
    const auto& clips = projectClips();
    crowd::CrowdSetup setup = oneWalker();
    crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
    for (int step = 0; step < 37; ++step) crowd.step(clips, kStep);
    const double shown = clips[2].gaitPhaseAt(crowd.frame(0));
    crowd.playClip(clips, 0, 1, 0.3F);
    EXPECT_LT(phaseGap(clips[1].gaitPhaseAt(crowd.frame(0)), shown), 0.01);
    std::vector<crowd::CharacterState> state(1);
    crowd.pack(state);
    EXPECT_EQ(state[0].fromClip, 2U);
    EXPECT_EQ(state[0].fromWeight, 1.0F);
    EXPECT_EQ(state[0].clip, 1U);
    // A cut: no fade at all.
    crowd.playClip(clips, 0, 3, 0.0F);
    crowd.pack(state);
    EXPECT_EQ(state[0].fromWeight, 0.0F);
    EXPECT_EQ(state[0].clip, 3U);
}

TEST(CrowdTransitions, AnEventHandsAGroupToASetThatBlendsAtTheEventsSpeeds) {
    const auto& clips = projectClips();
    crowd::CrowdSetup setup = oneWalker();
    setup.locomotion = {motion::makeLocomotionSet(clips, std::vector<std::uint32_t>{0, 1, 2, 3}).orThrow()};
    setup.events = {event(0.5, 0, [](crowd::CrowdEvent& e) {
        e.locomotion = 0U;
        e.groundSpeed = glm::vec2(2.0F);
    })};
    crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
    EXPECT_EQ(crowd.locomotion(0), nullptr);
    for (int step = 0; step < 60; ++step) crowd.step(clips, kStep);
    ASSERT_NE(crowd.locomotion(0), nullptr);
    EXPECT_NEAR(crowd.desiredSpeed(0), 2.0F, 1e-6F);
    for (int step = 0; step < 240; ++step) crowd.step(clips, kStep);
    EXPECT_NEAR(crowd.speed(0), 2.0F, 1e-4F) << "it accelerates to the event's speed";
    EXPECT_EQ(crowd.fromWeight(0), 0.0F);
    EXPECT_EQ(crowd.clip(0), 2U);  // walk and run blend at 2 m/s
    EXPECT_EQ(crowd.blendClip(0), 3U);
}

TEST(CrowdTransitions, EventsThatCannotBeShownAreRefused) {
    const auto& clips = projectClips();
    std::vector<motion::BakedClip> withOther = clips;
    // A two-joint skeleton: nothing to crossfade joint by joint with the project's 31.
    constexpr std::string_view kStick = "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                                        " JOINT Head\n {\n  OFFSET 0 50 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n  End Site\n  {\n   OFFSET 0 10 0\n  }\n }\n}\n"
                                        "MOTION\nFrames: 2\nFrame Time: 0.0333333\n0 90 0 0 0 0 0 0 0\n0 90 0 0 0 0 0 0 0\n";
    withOther.push_back(motion::bake(motion::parseBvh(kStick, "stick.bvh").orThrow()).orThrow());
    const auto refusal = [&](crowd::CrowdEvent event) {
        crowd::CrowdSetup setup = oneWalker();
        setup.events = {event};
        auto crowd = crowd::Crowd::spawn(withOther, setup);
        return crowd ? std::string() : crowd.error().message;
    };
    using E = crowd::CrowdEvent;
    const auto refused = [&](crowd::CrowdEvent e, const std::string& says) {
        const std::string message = refusal(e);
        EXPECT_NE(message.find(says), std::string::npos) << message;
    };
    refused(event(1, 1, [](E& e) { e.clip = 3U; }), "names group 1");
    refused(event(1, 0, [](E& e) { e.clip = 9U; }), "names clip 9");
    refused(event(1, 0, [](E& e) { e.locomotion = 0U; }), "locomotion set 0");
    refused(event(-1, 0, [](E& e) { e.clip = 3U; }), "needs a time");
    refused(event(std::nan(""), 0, [](E& e) { e.clip = 3U; }), "needs a time");
    refused(event(1, 0, [](E& e) { e.clip = 3U, e.fade = std::nanf(""); }), "fade");
    refused(event(1, 0, [](E& e) { e.clip = 4U; }), "different skeletons");
    refused(event(1, 0, [](E& e) { e.groundSpeed = glm::vec2(2.0F, 1.0F); }), "ground speed");
    refused(event(1, 0, [](E& e) { e.clip = 3U, e.groundSpeed = glm::vec2(2.0F); }), "own pace");
    EXPECT_EQ(refusal(event(1, 0, [](E& e) { e.clip = 3U; })), "");
}

// One character of the project's set walking between two waypoints 8 m apart.
crowd::Crowd pacer(crowd::Mode mode, glm::vec2 pause) {
    const auto& clips = projectClips();
    crowd::GroupSpec group;
    group.count = 1;
    group.mode = mode;
    group.region = {{0.0F, 4.0F}, {0.5F, 0.5F}};
    group.locomotion = 0;
    group.groundSpeed = glm::vec2(1.4F);
    group.pause = pause;
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.locomotion = {motion::makeLocomotionSet(clips, std::vector<std::uint32_t>{0, 1, 2, 3}).orThrow()};
    setup.waypoints = {{0.0F, 0.0F}, {0.0F, 8.0F}};
    setup.threads = 1;
    return crowd::Crowd::spawn(clips, setup).orThrow();
}

TEST(CrowdStartStop, ACharacterOfASetStandsAtEachGoalForItsPauseThenSetsOff) {
    for (crowd::Mode mode : {crowd::Mode::Goals, crowd::Mode::Avoid}) {
        crowd::Crowd crowd = pacer(mode, glm::vec2(1.0F));
        const auto& clips = projectClips();
        int stands = 0, completed = 0, countedSteps = 0, standingSteps = 0;
        glm::dvec2 standingAt(0.0);
        std::vector<crowd::CharacterState> state(1);
        std::array<glm::vec3, 2> ankles{};
        for (int step = 0; step < 30 * 60; ++step) {
            const bool wasPausing = crowd.pausing(0) > 0;
            crowd.step(clips, kStep);
            const glm::dvec2 at = crowd.groundFrame(0).position;
            EXPECT_GE(crowd.playback(0), 0.85F - 1e-6F) << "never slow motion";
            EXPECT_LE(crowd.playback(0), 1.2F + 1e-6F);
            if (wasPausing && crowd.pausing(0) <= 0) ++completed, standingSteps = countedSteps;
            if (crowd.pausing(0) > 0) {
                if (!wasPausing) {
                    ++stands;
                    standingAt = at;
                    // It stood close to one of the waypoints.
                    EXPECT_LT(std::min(glm::length(at), glm::length(at - glm::dvec2(0.0, 8.0))), 1.0) << crowd::modeName(mode);
                }
                ++countedSteps;
                // Its feet stay where they stood (the body may turn over them toward the next goal).
                crowd.pack(state);
                for (int l = 0; l < 2; ++l) {
                    const glm::vec3 ankle = crowd::sampleJointWorld(clips, state[0], clips[0].anatomy.legs[static_cast<std::size_t>(l)].ankle).position;
                    if (!wasPausing) ankles[l] = ankle;
                    EXPECT_LT(glm::length(glm::vec2(ankle.x - ankles[l].x, ankle.z - ankles[l].z)), 0.02) << "a standing foot stays put";
                }
                EXPECT_LT(glm::length(at - standingAt), 0.1) << "it stands";
                EXPECT_EQ(crowd.clip(0), 0U) << "the idle";
                EXPECT_EQ(crowd.blendWeight(0), 0.0F);
            }
        }
        EXPECT_GE(stands, 3) << crowd::modeName(mode) << ": 8 m at 1.4 m/s, 1 s pauses, in 30 s";
        EXPECT_NEAR(static_cast<double>(standingSteps) / completed, 60.0, 1.0) << "each pause lasts its second";
        EXPECT_GT(crowd.speed(0) + crowd.pausing(0), 0.0F);
    }
}

TEST(CrowdStartStop, AZeroPauseStillStopsAndTheSlowdownIsGradual) {
    crowd::Crowd crowd = pacer(crowd::Mode::Goals, glm::vec2(0.0F));
    const auto& clips = projectClips();
    float previous = crowd.speed(0);
    int stops = 0;
    bool moving = true;
    for (int step = 0; step < 20 * 60; ++step) {
        crowd.step(clips, kStep);
        if (moving && crowd.speed(0) == 0.0F) ++stops;
        moving = crowd.speed(0) > 0.0F;
        EXPECT_LE(std::abs(crowd.speed(0) - previous), 1.5F * kStep + 1e-5F) << "bounded acceleration";
        previous = crowd.speed(0);
    }
    EXPECT_GE(stops, 2) << "it stands at one goal, sets off, and stands at the next";
}

TEST(CrowdTransitions, AnEventNamingAnUnusableSetIsRefusedBeforeAnythingReadsIt) {
    const auto& clips = projectClips();
    crowd::CrowdSetup setup = oneWalker();
    setup.locomotion = {motion::LocomotionSet{}};  // no gaits: not one makeLocomotionSet made
    setup.events = {event(1.0, 0, [](crowd::CrowdEvent& e) { e.locomotion = 0U; })};
    auto crowd = crowd::Crowd::spawn(clips, setup);
    ASSERT_FALSE(crowd);
    EXPECT_NE(crowd.error().message.find("event 0"), std::string::npos) << crowd.error().message;
}

TEST(CrowdStartStop, PausesAndEventsGiveTheSameCrowdOnAnyThreadCount) {
    const auto& clips = projectClips();
    std::vector<std::vector<glm::dvec2>> runs;
    for (unsigned threads : {1U, 2U}) {
        crowd::GroupSpec group;
        group.count = 60;
        group.mode = crowd::Mode::Avoid;
        group.region = {{0.0F, 0.0F}, {12.0F, 12.0F}};
        group.locomotion = 0;
        crowd::CrowdSetup setup;
        setup.groups = {group};
        setup.area = {{0.0F, 0.0F}, {12.0F, 12.0F}};
        setup.locomotion = {motion::makeLocomotionSet(clips, std::vector<std::uint32_t>{0, 1, 2, 3}).orThrow()};
        setup.events = {event(2.0, 0, [](crowd::CrowdEvent& e) { e.groundSpeed = glm::vec2(1.8F, 2.4F); })};
        setup.threads = threads;
        crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
        for (int step = 0; step < 8 * 30; ++step) crowd.step(clips, 1.0 / 30.0);
        runs.emplace_back();
        for (int i = 0; i < crowd.size(); ++i) runs.back().push_back(crowd.groundFrame(i).position);
    }
    EXPECT_EQ(runs[0], runs[1]);
}

}  // namespace

TEST(CrowdTransitions, AFadeAskedForMidBlendWaitsForOneClipButACutOrTheSameSetDoesNot) {
    const auto& clips = projectClips();
    crowd::CrowdSetup setup = oneWalker();
    setup.locomotion = {motion::makeLocomotionSet(clips, std::vector<std::uint32_t>{0, 1, 2, 3}).orThrow()};
    setup.groups[0].locomotion = 0;
    setup.groups[0].groundSpeed = glm::vec2(2.0F);  // between the walk and the run
    crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
    for (int step = 0; step < 30; ++step) crowd.step(clips, kStep);
    ASSERT_GT(crowd.blendWeight(0), 0.05F);
    ASSERT_LT(crowd.blendWeight(0), 0.95F);
    // The set it already blends: nothing to do.
    crowd.blendSet(clips, 0, 0, 0.3F);
    EXPECT_FALSE(crowd.transitionWaiting(0));
    EXPECT_EQ(crowd.fromWeight(0), 0.0F);
    // A fade waits, and the blend glides to one clip meanwhile.
    crowd.playClip(clips, 0, 1, 0.3F);
    EXPECT_TRUE(crowd.transitionWaiting(0));
    EXPECT_EQ(crowd.fromWeight(0), 0.0F);
    int waited = 0;
    while (crowd.transitionWaiting(0) && waited < 600) {
        crowd.step(clips, kStep);
        ++waited;
    }
    EXPECT_LT(waited, 120) << "the blend reaches one clip within 2 s";
    EXPECT_EQ(crowd.clip(0), 1U);
    EXPECT_GT(crowd.fromWeight(0), 0.8F) << "the fade has just begun";
    // A cut starts at once, whatever is shown.
    crowd.playClip(clips, 0, 3, 0.0F);
    EXPECT_FALSE(crowd.transitionWaiting(0));
    EXPECT_EQ(crowd.clip(0), 3U);
    EXPECT_EQ(crowd.fromWeight(0), 0.0F);
}

TEST(CrowdTransitions, AnEventsGroundSpeedWaitsWithItsSetAndAppliesWhenItStarts) {
    const auto& clips = projectClips();
    crowd::CrowdSetup setup = oneWalker();
    setup.locomotion = {motion::makeLocomotionSet(clips, std::vector<std::uint32_t>{0, 1, 2, 3}).orThrow()};
    // Walk to run over 0.6 s; 0.2 s into that fade, blend the set at 2 m/s: it must wait for
    // the fade, then start with the event's speed (not the run's pace it walks at).
    setup.events = {event(0.5, 0, [](crowd::CrowdEvent& e) { e.clip = 3U, e.fade = 0.6F; }),
                    event(0.7, 0, [](crowd::CrowdEvent& e) { e.locomotion = 0U, e.groundSpeed = glm::vec2(2.0F), e.fade = 0.3F; })};
    crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
    bool waited = false;
    for (int step = 0; step < 90; ++step) {
        crowd.step(clips, kStep);
        waited = waited || crowd.transitionWaiting(0);
        if (crowd.time() < 1.05) {
            EXPECT_EQ(crowd.locomotion(0), nullptr) << "at " << crowd.time() << " s the run's fade still runs";
        }
    }
    EXPECT_TRUE(waited);
    ASSERT_NE(crowd.locomotion(0), nullptr) << "the set started once the fade ended";
    EXPECT_FLOAT_EQ(crowd.desiredSpeed(0), 2.0F);
}
