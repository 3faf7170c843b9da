// Issue #15's acceptance for following trajectories, on the project's own set: hand-written
// tracks are read as a user's file would be (crowd::parseTrajectories), one character follows
// each (Mode::Follow), and its joints are sampled as the GPU and `simulate --joints-out` sample
// them. The yardsticks are blend_support's, which know nothing of the following: slide over
// the raw captures' own contacts, joint steps per frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "blend_support.h"
#include "throng/crowd/trajectories.h"

namespace {

using namespace throng;
using namespace throng::blendtest;

// id 1 walking along +x (the file's x,y plane) at `speed` m/s, sampled `rate` times a second.
std::string straightTrack(double speed, double rate, double seconds) {
    std::string text = "id,time,x,y\n";
    const int samples = static_cast<int>(std::lround(seconds * rate));
    for (int k = 0; k <= samples; ++k) {
        char row[96];
        std::snprintf(row, sizeof row, "1,%.6f,%.6f,0\n", k / rate, speed * k / rate);
        text += row;
    }
    return text;
}

crowd::Crowd followerCrowd(const Set& s, const std::string& text) {
    auto tracks = std::make_shared<const crowd::Trajectories>(crowd::parseTrajectories(text, "test.csv", {}).orThrow());
    crowd::GroupSpec group;
    group.count = static_cast<int>(tracks->tracks.size());
    group.mode = crowd::Mode::Follow;
    group.locomotion = 0;
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.locomotion = {s.set};
    setup.trajectories = tracks;
    setup.threads = 1;
    return crowd::Crowd::spawn(s.clips, setup).orThrow();
}

// Character 0 of a crowd following `text`, stepped at 60 Hz for `seconds`.
Walked follow(const Set& s, const std::string& text, double seconds) {
    crowd::Crowd crowd = followerCrowd(s, text);
    const motion::BakedClip& any = s.clips[0];
    Walked out;
    out.joints = {0, any.jointCount(), any.jointCount(), kFrame, any.parents, {}};
    out.scale = crowd.scale(0);
    const int steps = static_cast<int>(std::lround(seconds / kFrame));
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) crowd.step(s.clips, kFrame);
        record(crowd, s.clips, out);
    }
    return out;
}

TEST(TrajectoryFollowing, PlantedFeetSlideNoMoreThanTheClipsOwnAtConstantSpeeds) {
    const Set s = projectSet();
    const RawContacts raw = rawContacts(s);
    double rawSlide = 0;
    for (const motion::LocomotionClip& gait : s.set.gaits)
        rawSlide = std::max(rawSlide, worstBlendSlide(walk(s, 4.0, [&](double) { return gait.speed; }), s, raw));
    for (double rate : {10.0, 25.0})
        for (double v : {0.6, 1.05, 1.5, 2.4}) {
            const double slide = worstBlendSlide(follow(s, straightTrack(v, rate, 7.0), 7.0), s, raw);
            std::printf("track at %.2f m/s sampled at %.0f Hz: worst slide %.2f cm per contact (raw clips %.2f)\n", v, rate, slide, rawSlide);
            EXPECT_LE(slide, rawSlide + 1.0) << "at " << v << " m/s, " << rate << " Hz";
        }
}

TEST(TrajectoryFollowing, TheBodyIsWhereTheTrackIsAtEverySampleAndFacesAlongIt) {
    const Set s = projectSet();
    // A right-angle turn: 4 m along +x, then 4 m along the file's +y (Throng's -z), 10 Hz.
    std::string text = "id,time,x,y\n";
    for (int k = 0; k <= 60; ++k) {
        const double t = k * 0.1, along = std::min(t, 3.0) * 4.0 / 3.0, side = std::max(t - 3.0, 0.0) * 4.0 / 3.0;
        char row[96];
        std::snprintf(row, sizeof row, "7,%.3f,%.6f,%.6f\n", t, along, side);
        text += row;
    }
    crowd::Crowd crowd = followerCrowd(s, text);
    for (int k = 0; k <= 60; ++k) {
        const double t = k * 0.1;
        while (crowd.time() < t - 1e-9) crowd.step(s.clips, std::min(kFrame, t - crowd.time()));
        const glm::dvec2 expected(std::min(t, 3.0) * 4.0 / 3.0, -std::max(t - 3.0, 0.0) * 4.0 / 3.0);
        EXPECT_LT(glm::length(crowd.groundFrame(0).position - expected), 1e-6) << "at " << t << " s";
    }
    // Well before and after the corner, the body faces along the path (+x is yaw pi/2, -z is
    // pi), give or take the capture's own sway of the body about its direction of travel (2°).
    crowd::Crowd again = followerCrowd(s, text);
    while (again.time() < 1.5 - 1e-9) again.step(s.clips, kFrame);
    EXPECT_NEAR(wrapAngle(again.groundFrame(0).yaw - 0.5 * M_PI), 0.0, 0.035);
    while (again.time() < 5.0 - 1e-9) again.step(s.clips, kFrame);
    EXPECT_NEAR(std::abs(wrapAngle(again.groundFrame(0).yaw)), M_PI, 0.035);
}

TEST(TrajectoryFollowing, PeopleAppearWhenTheirTrackStartsLeaveWhenItEndsAndIdleWhileStanding) {
    const Set s = projectSet();
    ASSERT_TRUE(s.set.idle.has_value());
    // id 1 walks from 0 s to 4 s; id 2 appears at 1 s, stands still, and leaves at 3 s.
    std::string text = "id,time,x,y\n";
    for (int k = 0; k <= 40; ++k) text += "1," + std::to_string(k * 0.1) + "," + std::to_string(k * 0.1 * 1.2) + ",0\n";
    for (int k = 10; k <= 30; ++k) text += "2," + std::to_string(k * 0.1) + ",5,5\n";
    crowd::Crowd crowd = followerCrowd(s, text);
    std::vector<crowd::CharacterState> packed(2);
    const auto at = [&](double t) {
        while (crowd.time() < t - 1e-9) crowd.step(s.clips, std::min(kFrame, t - crowd.time()));
        crowd.pack(packed);
    };
    at(0.5);
    EXPECT_TRUE(crowd.present(0));
    EXPECT_FALSE(crowd.present(1));
    EXPECT_EQ(packed[1].scale, 0.0F);
    at(2.0);
    EXPECT_TRUE(crowd.present(1));
    EXPECT_GT(packed[1].scale, 0.9F);
    // Standing: the idle alone (the blend's lower clip at weight 0).
    EXPECT_EQ(crowd.clip(1), s.set.idle->clip);
    EXPECT_FLOAT_EQ(crowd.blendWeight(1), 0.0F);
    EXPECT_NE(crowd.clip(0), s.set.idle->clip);
    at(3.5);
    EXPECT_FALSE(crowd.present(1));
    EXPECT_EQ(packed[1].scale, 0.0F);
}

}  // namespace
