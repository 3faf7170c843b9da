// Issue #12's acceptance for speed blending, on the project's own set (idle, slow walk, walk,
// run). One character of the set walks in group mode; its joints are sampled as the GPU samples
// them (crowd::sampleJointWorld) and measured with the yardsticks of playback_measures, which
// know nothing of the blend: strides from where the left ankle plants, ground speed from the
// pelvis's path, slide from planted foot points, jumps from joint steps per frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>

#include "blend_support.h"
#include "playback_measures.h"
#include "throng/motion/bvh_parser.h"
#include "throng/motion/locomotion_set.h"

namespace {

using namespace throng;
using namespace throng::blendtest;

TEST(SpeedBlendingAcceptance, StrideGrowsWithSpeedAndGroundSpeedTracksTheWantedOne) {
    const Set s = projectSet();
    const motion::BakedClip& pelvisClip = s.clips[2];
    double slowestStride = 0, fastestStride = 0;
    for (double v : {0.8, 1.0, 1.3, 1.6, 2.2, 2.8}) {
        const Walked w = walk(s, 8.0, [v](double) { return v; });
        const double stride = strideLength(w, pelvisClip);
        const std::vector<glm::dvec2> path = quality::groundPath(w.joints, pelvisClip.anatomy.pelvis, 60);
        const double speed = quality::arcSpeed(path, kFrame) / w.scale;
        std::printf("speed %.2f m/s: stride %.3f m, ground speed %.3f m/s (%.1f%% off)\n", v, stride, speed, 100.0 * (speed / v - 1.0));
        EXPECT_NEAR(speed / v, 1.0, 0.05) << "at " << v << " m/s";
        if (v == 0.8) slowestStride = stride;
        if (v == 1.6) fastestStride = stride;
    }
    // Stretching one clip's playback would keep its stride; the blend lengthens it.
    EXPECT_GE(fastestStride, 1.3 * slowestStride);
}

TEST(SpeedBlendingAcceptance, BlendsAddNoFootSlideAtConstantSpeedsOrAcceleratingFromIdleToRun) {
    const Set s = projectSet();
    // The clips' own slide and largest joint step, each played alone at its natural speed
    // (where the blend is that clip alone), over the same contacts.
    const RawContacts raw = rawContacts(s);
    double rawSlide = 0, rawStep = 0;
    for (const motion::LocomotionClip& gait : s.set.gaits) {
        const Walked alone = walk(s, 4.0, [&](double) { return gait.speed; });
        rawSlide = std::max(rawSlide, worstBlendSlide(alone, s, raw));
        rawStep = std::max(rawStep, largestStep(alone.joints));
    }
    for (double v : {0.4, 1.05, 1.8, 2.4}) {
        const Walked w = walk(s, 6.0, [v](double) { return v; });
        const double slide = worstBlendSlide(w, s, raw);
        std::printf("constant %.2f m/s: worst slide %.2f cm per contact (raw clips %.2f)\n", v, slide, rawSlide);
        EXPECT_LE(slide, rawSlide + 1.0) << "at " << v << " m/s";
    }
    // Idle to run over 3 s, then running on: no added slide, and no joint jumps.
    const Walked w = walk(s, 5.0, [](double t) { return std::min(1.0, t / 3.0) * 2.8; });
    const double slide = worstBlendSlide(w, s, raw);
    const double step = largestStep(w.joints);
    std::printf("idle to run in 3 s: worst slide %.2f cm per contact, largest joint step %.2f cm (clips alone: %.2f cm)\n", slide,
                100 * step, 100 * rawStep);
    EXPECT_LE(slide, rawSlide + 1.0);
    EXPECT_LE(step, 1.5 * rawStep);
}

// The joints of the one character of `setup` over `seconds`, as the GPU samples them.
quality::PointSeries jointsOverTime(const Set& s, const crowd::CrowdSetup& setup, double seconds) {
    crowd::Crowd crowd = crowd::Crowd::spawn(s.clips, setup).orThrow();
    const int steps = static_cast<int>(std::lround(seconds / kFrame));
    const motion::BakedClip& any = s.clips[crowd.clip(0)];
    quality::PointSeries joints{steps + 1, any.jointCount(), any.jointCount(), kFrame, any.parents, {}};
    std::vector<crowd::CharacterState> state(1);
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) crowd.step(s.clips, kFrame);
        crowd.pack(state);
        for (int j = 0; j < any.jointCount(); ++j) joints.positions.emplace_back(crowd::sampleJointWorld(s.clips, state[0], j).position);
    }
    return joints;
}

crowd::CrowdEvent eventAt(double time, std::optional<std::uint32_t> clip, std::optional<std::uint32_t> set, float fade) {
    crowd::CrowdEvent event;
    event.time = time;
    event.clip = clip;
    event.locomotion = set;
    event.fade = fade;
    return event;
}

// One character playing clip `from` alone, crossfading at 1 s to clip `to` over 0.3 s.
quality::PointSeries crossfaded(const Set& s, std::uint32_t from, std::uint32_t to, double seconds) {
    crowd::GroupSpec group;
    group.count = 1;
    group.region = {{0.0F, 0.0F}, {0.5F, 0.5F}};
    group.clips = {from};
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.events = {eventAt(1.0, to, std::nullopt, 0.3F)};
    setup.threads = 1;
    return jointsOverTime(s, setup, seconds);
}

TEST(SpeedBlendingAcceptance, CrossfadesBetweenAnyTwoClipsOfTheSetKeepEveryJointContinuous) {
    const Set s = projectSet();
    // Each clip's own largest joint step, played alone.
    std::vector<double> ownStep(s.clips.size());
    for (std::uint32_t c = 0; c < s.clips.size(); ++c) ownStep[c] = largestStep(crossfaded(s, c, c, 3.0));
    for (std::uint32_t from = 0; from < s.clips.size(); ++from)
        for (std::uint32_t to = 0; to < s.clips.size(); ++to) {
            if (from == to) continue;
            const double step = largestStep(crossfaded(s, from, to, 2.5));
            const double bound = 1.5 * std::max(ownStep[from], ownStep[to]);
            std::printf("%s -> %s in 0.3 s: largest joint step %.2f cm (clips alone %.2f, %.2f)\n", kSetFiles[from], kSetFiles[to], 100 * step,
                        100 * ownStep[from], 100 * ownStep[to]);
            EXPECT_LE(step, bound) << kSetFiles[from] << " -> " << kSetFiles[to];
        }
}

TEST(SpeedBlendingAcceptance, TransitionsAskedForMidBlendOrMidFadeKeepEveryJointContinuous) {
    const Set s = projectSet();
    double ownStep = 0;  // the largest joint step of any clip of the set, played alone
    for (std::uint32_t c = 0; c < s.clips.size(); ++c) ownStep = std::max(ownStep, largestStep(crossfaded(s, c, c, 3.0)));
    // Blending the walk and the run about half and half, it is asked to play the walk alone;
    // then to blend the set again, and before that fade ends, to play the run: overlapping.
    crowd::GroupSpec group;
    group.count = 1;
    group.region = {{0.0F, 0.0F}, {0.5F, 0.5F}};
    group.locomotion = 0;
    const double walkSpeed = s.set.gaits[1].speed, runSpeed = s.set.gaits[2].speed;
    group.groundSpeed = glm::vec2(static_cast<float>(0.5 * (walkSpeed + runSpeed)));
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.locomotion = {s.set};
    setup.events = {eventAt(1.0, 2U, std::nullopt, 0.3F), eventAt(2.5, std::nullopt, 0U, 0.6F), eventAt(2.7, 3U, std::nullopt, 0.3F)};
    setup.threads = 1;
    crowd::Crowd crowd = crowd::Crowd::spawn(s.clips, setup).orThrow();
    for (int step = 0; step < 60; ++step) crowd.step(s.clips, kFrame);
    ASSERT_GT(crowd.blendWeight(0), 0.2F) << "the character must be mid-blend when the first event comes";
    ASSERT_LT(crowd.blendWeight(0), 0.8F);
    crowd.step(s.clips, kFrame);
    EXPECT_TRUE(crowd.transitionWaiting(0)) << "a fade from two clips waits for the pose to be one";
    const double step = largestStep(jointsOverTime(s, setup, 4.5));
    std::printf("mid-blend and overlapping transitions: largest joint step %.2f cm (clips alone %.2f)\n", 100 * step, 100 * ownStep);
    EXPECT_LE(step, 1.5 * ownStep);
    for (int k = 0; k < 240; ++k) crowd.step(s.clips, kFrame);
    EXPECT_FALSE(crowd.transitionWaiting(0));
    EXPECT_EQ(crowd.clip(0), 3U) << "the last event's run plays in the end";
    EXPECT_EQ(crowd.fromWeight(0), 0.0F);
}

TEST(SpeedBlendingAcceptance, TheSharedCmuWalksAndRunBlendAsASet) {
    if (!std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) GTEST_SKIP() << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
    std::vector<std::string> paths;
    for (const char* name : kCmuFiles) paths.push_back(shared(name));
    const Set s = loadSet(paths);
    const motion::BakedClip& pelvisClip = s.clips[s.set.gaits.front().clip];
    const RawContacts raw = rawContacts(s);
    double rawSlide = 0;
    for (const motion::LocomotionClip& gait : s.set.gaits) rawSlide = std::max(rawSlide, worstBlendSlide(walk(s, 4.0, [&](double) { return gait.speed; }), s, raw));
    const double slowest = s.set.slowest() * 1.001, fastest = s.set.fastest() * 0.999;
    double slowestStride = 0, fastestStride = 0;
    for (double v : {slowest, 0.5 * (slowest + s.set.gaits[1].speed), s.set.gaits[1].speed, 2.2, fastest}) {
        const Walked w = walk(s, 8.0, [v](double) { return v; });
        const double stride = strideLength(w, pelvisClip);
        const double speed = quality::arcSpeed(quality::groundPath(w.joints, pelvisClip.anatomy.pelvis, 60), kFrame) / w.scale;
        const double slide = worstBlendSlide(w, s, raw);
        std::printf("CMU set at %.2f m/s: stride %.3f m, ground speed %.3f m/s (%.1f%% off), worst slide %.2f cm per contact (clips alone %.2f)\n",
                    v, stride, speed, 100.0 * (speed / v - 1.0), slide, rawSlide);
        EXPECT_NEAR(speed / v, 1.0, 0.05) << "at " << v << " m/s";
        EXPECT_LE(slide, rawSlide + 1.0) << "at " << v << " m/s";
        if (v == slowest) slowestStride = stride;
        if (v == fastest) fastestStride = stride;
    }
    EXPECT_GE(fastestStride, 1.3 * slowestStride);
    // From the slowest walk to the fastest run over 3 s.
    const Walked w = walk(s, 5.0, [&](double t) { return slowest + std::min(1.0, t / 3.0) * (fastest - slowest); });
    std::printf("CMU set, slowest to fastest in 3 s: worst slide %.2f cm per contact (clips alone %.2f)\n", worstBlendSlide(w, s, raw), rawSlide);
    EXPECT_LE(worstBlendSlide(w, s, raw), rawSlide + 1.0);
}

}  // namespace
