// The yardsticks of playback_measures on inputs with known answers: a ruler that is wrong
// would pass or fail the root-motion work for the wrong reason.
#include <gtest/gtest.h>

#include <cmath>

#include "playback_measures.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng;

constexpr double kStature = 1.7;
constexpr double kFrameTime = 0.01;

// A foot that stands for 60 frames, then swings for 40 at 1.5 m/s, `cycles` times. The swing
// stays `swingLift` above the stance height; during stance it drifts at `drift` m/s along x.
std::vector<glm::dvec3> steppingFoot(int cycles, double swingLift, double drift) {
    std::vector<glm::dvec3> foot;
    glm::dvec3 p(0.0, 0.05, 0.0);
    for (int c = 0; c < cycles; ++c) {
        for (int f = 0; f < 60; ++f, p.x += drift * kFrameTime) foot.push_back(p);
        for (int f = 0; f < 40; ++f, p.z += 1.5 * kFrameTime) foot.push_back(p + glm::dvec3(0.0, swingLift, 0.0));
    }
    return foot;
}

TEST(PlantedSlide, AStillStanceFootDoesNotSlide) {
    const auto foot = steppingFoot(5, 0.15, 0.0);
    const quality::Slide slide = quality::plantedSlide(foot, kFrameTime, kStature);
    EXPECT_EQ(slide.contacts, 5);
    EXPECT_NEAR(slide.cmPerSecond, 0.0, 1e-9);
    EXPECT_NEAR(slide.cmPerContact, 0.0, 1e-9);
}

TEST(PlantedSlide, DriftDuringStanceIsMeasuredInCentimetres) {
    const auto foot = steppingFoot(5, 0.15, 0.10);  // 10 cm/s, below the contact speed gate
    const quality::Slide slide = quality::plantedSlide(foot, kFrameTime, kStature);
    EXPECT_EQ(slide.contacts, 5);
    EXPECT_NEAR(slide.cmPerSecond, 10.0, 1e-6);
    // 0.1 cm per frame step inside each contact. The speed window (±3 frames here) may trim a
    // contact's ends where it reaches into the swing, so a contact holds 54 to 60 frames.
    EXPECT_GE(slide.plantedFrames, 5 * 54);
    EXPECT_LE(slide.plantedFrames, 5 * 60);
    EXPECT_NEAR(slide.cmPerContact, 0.1 * (slide.plantedFrames - slide.contacts) / slide.contacts, 1e-6);
}

TEST(PlantedSlide, ALowFastSwingIsNotAContact) {
    // The swing passes 1 cm above the stance height: inside the height band, but at 1.5 m/s.
    const auto foot = steppingFoot(5, 0.01, 0.0);
    const quality::Slide slide = quality::plantedSlide(foot, kFrameTime, kStature);
    EXPECT_EQ(slide.contacts, 5);
    EXPECT_LT(slide.cmPerSecond, 1.0);
    // The height band alone takes the swing for stance: that is why the rule has a speed gate.
    const quality::Slide bandOnly = quality::plantedSlide(foot, kFrameTime, kStature, {}, {0.03, 1e300});
    EXPECT_GT(bandOnly.cmPerSecond, 50.0);
}

TEST(PlantedSlide, IncludeRestrictsTheSpeedSample) {
    const auto foot = steppingFoot(2, 0.15, 0.10);
    std::vector<char> include(foot.size(), 0);
    const quality::Slide none = quality::plantedSlide(foot, kFrameTime, kStature, include);
    EXPECT_EQ(none.measuredFrames, 0);
    EXPECT_EQ(none.contacts, 2);  // contacts don't depend on the speed sample
}

TEST(PlantedAtClipFrames, TheNearestClipFrameDecides) {
    const std::vector<char> clip = {0, 1, 1, 1, 0, 0};
    const std::vector<double> steps = {0.4, 0.6, 1.0, 2.2, 3.4, 3.6, 4.5, 5.2};
    const std::vector<char> planted = quality::plantedAtClipFrames(clip, steps);
    EXPECT_EQ(planted, (std::vector<char>{0, 1, 1, 1, 1, 0, 0, 0}));
    // A lone planted step is not a contact, as in the capture.
    EXPECT_EQ(quality::plantedAtClipFrames(clip, std::vector<double>{0.0, 2.0, 4.0}), (std::vector<char>{0, 0, 0}));
}

TEST(BoneLengthSpread, FindsTheStretchedBone) {
    quality::PointSeries points{3, 3, 3, kFrameTime, {-1, 0, 1}, {}};
    for (double stretch : {0.0, 0.1, 0.05}) {
        points.positions.push_back({0, 1, 0});
        points.positions.push_back({0, 0.5, 0});                // a rigid 0.5 m bone
        points.positions.push_back({0.3 + stretch, 0.5, 0.0});  // 0.3 m, stretched by up to 0.1 m
    }
    const quality::BoneSpread spread = quality::boneLengthSpread(points, kStature);
    EXPECT_EQ(spread.point, 2);
    EXPECT_NEAR(spread.metres, 0.1, 1e-12);
    EXPECT_NEAR(spread.fraction, 0.1 / kStature, 1e-12);
    EXPECT_EQ(spread.relativePoint, 2);
    EXPECT_NEAR(spread.relative, 0.1 / 0.35, 1e-12);
}

TEST(ArcSpeed, ASwayingStraightWalkIsRatedAtItsForwardSpeed) {
    std::vector<glm::dvec2> path;
    for (int f = 0; f < 400; ++f) {
        const double t = f * kFrameTime;
        path.emplace_back(0.04 * std::sin(2.0 * 3.14159265358979 * t / 1.0), 1.3 * t);  // one sway cycle per second
    }
    EXPECT_NEAR(quality::arcSpeed(path, kFrameTime), 1.3, 0.013);
    EXPECT_NEAR(quality::arcSpeed(path, kFrameTime, 100, 300), 1.3, 0.013);
}

TEST(ArcSpeed, ACurvingWalkIsRatedAlongItsArc) {
    // 1.5 m/s on a 3 m circle, three quarters round: net displacement says far less.
    std::vector<glm::dvec2> path;
    const double omega = 1.5 / 3.0;
    for (int f = 0; f <= 942; ++f) path.emplace_back(3.0 * std::sin(omega * f * kFrameTime), 3.0 * std::cos(omega * f * kFrameTime));
    // A 1 s average pulls a 3 m circle in by sin(0.25)/0.25 at most: under 1.1%.
    EXPECT_NEAR(quality::arcSpeed(path, kFrameTime), 1.5, 0.02);
}

constexpr const char* kZUpBvh =
    "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "  JOINT Head\n  {\n    OFFSET 0 0 100\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
    "    End Site\n    {\n      OFFSET 0 0 10\n    }\n  }\n}\n"
    "MOTION\nFrames: 2\nFrame Time: 0.5\n0 0 90 0 0 0 0 0 0\n0 50 90 0 0 0 0 0 0\n";

TEST(RawWorldPositions, ScalesAndTurnsTheFileUpAxisToY) {
    const motion::RawMotion raw = motion::parseBvh(kZUpBvh, "zup.bvh").orThrow();
    const quality::PointSeries points = quality::rawWorldPositions(raw, 0.01, motion::UpAxis::PlusZ, true);
    ASSERT_EQ(points.points, 3);
    ASSERT_EQ(points.joints, 2);
    EXPECT_EQ(points.parents, (std::vector<int>{-1, 0, 1}));
    // The file's +Z is up: the head stands 1 m above the hips, the End Site 0.1 m above that.
    EXPECT_NEAR(points.at(0, 1).y - points.at(0, 0).y, 1.0, 1e-12);
    EXPECT_NEAR(points.at(0, 2).y, 0.9 + 1.0 + 0.1, 1e-12);
    // The file's +Y (its forward) becomes −Z, keeping the axes right-handed.
    EXPECT_NEAR(points.at(1, 0).z, -0.5, 1e-12);
    EXPECT_EQ(quality::withoutEndSites(points).points, 2);
}

TEST(Playback, RecordsEveryStepOfOneCharacter) {
    const motion::RawMotion raw = motion::loadBvhFile(THRONG_DEFAULT_CLIP).orThrow();
    const motion::BakedClip clip = motion::bake(raw).orThrow();
    const auto played = quality::playback(clip, crowd::Mode::Goals, 2.0, 0.05, false).orThrow();
    ASSERT_EQ(played.joints.frames, 41);
    EXPECT_EQ(played.joints.points, clip.jointCount());
    EXPECT_EQ(played.ground.size(), 41U);
    EXPECT_EQ(played.clipFrames.size(), 41U);
    for (double frame : played.clipFrames) {
        EXPECT_GE(frame, clip.loop().first);
        EXPECT_LT(frame, clip.loop().last);
    }
    // Walking to a waypoint 500 m away along z: it covers ground and never turns. Steering
    // corrects the heading only while the feet can take a turn, so the clip's own sway of a
    // degree or two per second shows in between; a turn is ten times that.
    EXPECT_GT(std::abs(played.ground.back().position.y - played.ground.front().position.y), 1.0);
    EXPECT_TRUE(std::ranges::none_of(quality::turningFrames(played.ground, 0.05, 0.1), [](char c) { return c != 0; }));
}

}  // namespace
