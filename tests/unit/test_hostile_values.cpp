// Below the validation layer: NaN, infinities and huge values that reach the engine anyway
// (a library caller, a future bug) must give defined results, never undefined behaviour. At
// -O3 a NaN frame position converted to an integer loop count made RootMotionTrack::at()
// loop for ever; these run in the Release build, under ctest's timeout.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "throng/core/math.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/crowd.h"
#include "throng/crowd/spatial_hash.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

const motion::BakedClip& walkClip() {
    static const motion::BakedClip clip = motion::bake(motion::loadBvhFile(THRONG_DEFAULT_CLIP).orThrow()).orThrow();
    return clip;
}

bool finite(const motion::GroundFrame& g) { return std::isfinite(g.position.x) && std::isfinite(g.position.y) && std::isfinite(g.yaw); }

TEST(HostileValues, ClampedFloorHandlesEverything) {
    EXPECT_EQ(clampedFloor(kNaN, 0, 10), 0);
    EXPECT_EQ(clampedFloor(kInf, 0, 10), 10);
    EXPECT_EQ(clampedFloor(-kInf, 0, 10), 0);
    EXPECT_EQ(clampedFloor(1e300, -5, 5), 5);
    EXPECT_EQ(clampedFloor(3.7, 0, 10), 3);
    EXPECT_EQ(clampedFloor(-0.5, -10, 10), -1);
    EXPECT_EQ(clampedFloor<long long>(1e19, 0, std::numeric_limits<long long>::max()), std::numeric_limits<long long>::max());
    EXPECT_EQ(clampedFloor<std::size_t>(kNaN, 0, 7), 0U);
}

TEST(HostileValues, FastFloorIsStdFloorForEveryKindOfDouble) {
    // Compared with std::floor itself, over the awkward cases and a sweep across magnitudes.
    std::vector<double> values = {kNaN, kInf, -kInf, 0.0, 0.5, -0.5, 1.0, -1.0, 2.5, -2.5, 1e-300, -1e-300,
                                  4503599627370495.5, -4503599627370495.5, 4503599627370496.0, 9.3e18, -9.3e18, 1e300, -1e300,
                                  std::nextafter(1.0, 0.0), std::nextafter(-1.0, 0.0), std::numeric_limits<double>::max()};
    for (double x = 1e-3; x < 1e20; x *= 1.37) {
        values.push_back(x);
        values.push_back(-x);
    }
    for (const double x : values) {
        if (std::isnan(x)) {
            EXPECT_TRUE(std::isnan(fastFloor(x)));
            continue;
        }
        EXPECT_EQ(fastFloor(x), std::floor(x)) << x;  // -0.0 == +0.0: the documented difference
    }
}

TEST(HostileValues, RootMotionTrackWrapStaysInsideTheLoopForAnyPosition) {
    const motion::RootMotionTrack& track = walkClip().rootMotion;
    const motion::LoopRange loop = track.loop();
    for (const double x : {1e300, -1e300, 1e18, -1e18, 9.3e18, 123456.789, -0.0, static_cast<double>(loop.last),
                           std::nextafter(static_cast<double>(loop.last), 0.0), static_cast<double>(loop.first) - 1e-12}) {
        const double wrapped = track.wrap(x);
        EXPECT_GE(wrapped, loop.first) << x;
        EXPECT_LE(wrapped, loop.last) << x;
    }
    EXPECT_EQ(track.wrap(kNaN), loop.first);
}

TEST(HostileValues, RootMotionTrackAtNonFiniteOrHugePositionsReturnsFinite) {
    const motion::RootMotionTrack& track = walkClip().rootMotion;
    for (const double x : {kNaN, kInf, -kInf, 1e300, -1e300, 1e18, 9.3e18, -9.3e18})
        EXPECT_TRUE(std::isfinite(track.at(x).yaw)) << x;  // returns at all: the bug was a hang
    EXPECT_TRUE(finite(track.at(kNaN)));
    EXPECT_TRUE(finite(track.delta(0.0, kNaN)));
    for (const double x : {kNaN, kInf, -kInf}) {
        const double wrapped = track.wrap(x);
        EXPECT_TRUE(std::isfinite(wrapped));
        EXPECT_GE(wrapped, walkClip().loop().first);
        EXPECT_LE(wrapped, walkClip().loop().last);
    }
}

TEST(HostileValues, SampleAtNonFiniteFrameIsAFramePose) {
    const motion::BakedClip& clip = walkClip();
    for (const double frame : {kNaN, kInf, -kInf, 1e300}) {
        const motion::JointPose pose = clip.sample(frame, 3);
        EXPECT_TRUE(std::isfinite(pose.translation.x) && std::isfinite(pose.rotation.w)) << frame;
    }
    EXPECT_EQ(clip.sample(kNaN, 3).translation, clip.pose(0, 3).translation);
}

TEST(HostileValues, SpatialHashPlacesNonFiniteAndHugePositions) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<glm::vec2> positions{{0, 0}, {inf, 1}, {nan, nan}, {-3e38F, 3e38F}, {1e10F, -1e10F}, {1, 1}};
    crowd::SpatialHash hash;
    hash.build(positions, 1.0F);
    EXPECT_EQ(hash.sorted().size(), positions.size());
    int near = 0;
    hash.forEachWithin({0, 0}, 2.0F, [&](std::uint32_t) { ++near; });
    EXPECT_EQ(near, 2);  // (0, 0) and (1, 1)
    hash.forEachCellRange({nan, inf}, 1e30F, [](std::uint32_t, std::uint32_t) {});
}

// A clip that crosses a million metres every two frames of a microsecond: 5e11 m/s.
motion::BakedClip warpClip() {
    const std::string text =
        "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
        " End Site\n {\n  OFFSET 0 1.7 0\n }\n}\nMOTION\nFrames: 3\nFrame Time: 0.000001\n"
        "-1000000 1 0 0 0 0\n0 1 0 0 0 0\n1000000 1 0 0 0 0\n";
    motion::BakeOptions options;
    options.loop = motion::LoopRange{0, 2};
    return motion::bake(motion::parseBvh(text, "warp.bvh").orThrow(), options).orThrow();
}

TEST(HostileValues, CharactersThatOutrunTheWorldStayFiniteAtItsEdge) {
    const std::vector<motion::BakedClip> clips{warpClip(), walkClip()};
    for (const crowd::Mode mode : {crowd::Mode::Group, crowd::Mode::Goals, crowd::Mode::Avoid}) {
        crowd::CrowdSetup setup;
        setup.groups.push_back({.count = 12, .clips = {}, .region = {glm::vec2(0.0F), glm::vec2(40.0F)}, .mode = mode,
                                .speedRange = {1.0F, 4.0F}, .heading = 0.7F, .locomotion = std::nullopt, .groundSpeed = {1.0F, 1.5F}});
        setup.area = {glm::vec2(0.0F), glm::vec2(40.0F)};
        setup.waypoints = {{range::kMaxCoordinate, -range::kMaxCoordinate}, {-range::kMaxCoordinate, range::kMaxCoordinate}};
        setup.threads = 1;
        auto spawned = crowd::Crowd::spawn(clips, setup);
        ASSERT_TRUE(spawned.ok()) << spawned.error().describe();
        crowd::Crowd& crowd = spawned.value();
        for (const double step : {1.0 / 30.0, 0.5, 600.0, 1e300, kNaN, kInf, 1.0 / 30.0}) crowd.step(clips, step);
        for (int i = 0; i < crowd.size(); ++i) {
            EXPECT_TRUE(finite(crowd.groundFrame(i))) << crowd::modeName(mode) << " character " << i;
            EXPECT_LE(std::abs(crowd.groundFrame(i).position.x), range::kWorldEdge);
            EXPECT_LE(std::abs(crowd.groundFrame(i).position.y), range::kWorldEdge);
            EXPECT_TRUE(std::isfinite(crowd.frame(i)));
        }
    }
}

TEST(HostileValues, BakeRefusesClipsBeyondTheSupportedReach) {
    // Each value is within the parser's bounds; the metre scale puts the joints 1e7 m out.
    const std::string text =
        "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n End Site\n {\n  OFFSET 0 1 0\n }\n}\n"
        "MOTION\nFrames: 1\nFrame Time: 0.01\n1000000 0 0\n";
    motion::BakeOptions options;
    options.metresPerUnit = 10.0;
    auto far = motion::bake(motion::parseBvh(text, "far.bvh").orThrow(), options);
    ASSERT_FALSE(far.ok());
    EXPECT_NE(far.error().message.find("joints reach 1e+07 m"), std::string::npos) << far.error().message;
    EXPECT_EQ(far.error().location.file, "far.bvh");
}

TEST(HostileValues, ParserRefusesValuesOutsideTheSupportedRangeWithALocation) {
    const std::string text =
        "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n End Site\n {\n  OFFSET 0 1 0\n }\n}\n"
        "MOTION\nFrames: 1\nFrame Time: 0.01\n0 1000001 0\n";
    auto parsed = motion::parseBvh(text, "big.bvh");
    ASSERT_FALSE(parsed.ok());
    EXPECT_EQ(parsed.error().location.line, 14);
    EXPECT_EQ(parsed.error().location.column, 3);
    EXPECT_TRUE(motion::parseBvh(std::string(text).replace(text.find("1000001"), 7, "1000000"), "edge.bvh").ok());
}

TEST(HostileValues, HeadingsReduceExactlyModulo360) {
    EXPECT_DOUBLE_EQ(range::reduceDegrees(720.0 + 30.0), 30.0);
    EXPECT_DOUBLE_EQ(range::reduceDegrees(-190.0), 170.0);
    EXPECT_TRUE(std::isfinite(range::reduceDegrees(1e300)));
    EXPECT_LE(std::abs(range::reduceDegrees(1e300)), 180.0);
    EXPECT_TRUE(std::isnan(range::reduceDegrees(kNaN)));
}

}  // namespace
