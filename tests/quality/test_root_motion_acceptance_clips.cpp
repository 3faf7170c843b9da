// Issue #11's acceptance, part two: speed (and ORCA on it), stature, loops and gait, warnings.
// Known answers come from known_answers.json (the generator's parameters) or from the raw
// capture; the figures are printed, so the log shows them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "acceptance_support.h"
#include "throng/motion/skeleton_anatomy.h"

namespace {

using namespace throng;
using acceptance::Loaded;

constexpr double kRadToDeg = 57.29577951308232;

bool anyWarningMentions(const motion::BakedClip& clip, const std::string& text) {
    return std::any_of(clip.warnings.begin(), clip.warnings.end(),
                       [&](const std::string& warning) { return warning.find(text) != std::string::npos; });
}

void printWarnings(const char* name, const motion::BakedClip& clip) {
    std::printf("%s: %zu warning(s)\n", name, clip.warnings.size());
    for (const std::string& warning : clip.warnings) std::printf("  warning: %s\n", warning.c_str());
}

// A curving walk's rated speed is within 5% of its arc speed, and ORCA crowds of it keep 0.9 of
// the radii sum, as straight walks do.
TEST(RootMotionAcceptance, SpeedCurvingWalkIsRatedAtItsArcSpeedAndAvoids) {
    const nlohmann::json& known = acceptance::knownAnswers("curving_walk");
    const Loaded curving = acceptance::load(acceptance::generatedClip("curving_walk"));
    const double knownArc = known.at("arc_speed_m_per_s");
    std::printf("curving_walk: rated speed %.4f m/s (known arc speed %.4f m/s), turn rate %.1f deg/s (known %.1f deg/s)\n",
                curving.clip.speed, knownArc, curving.clip.turnRate * kRadToDeg, known.at("turn_rate_deg_per_s").get<double>());
    EXPECT_NEAR(curving.clip.speed, knownArc, 0.05 * knownArc);

    // 30 characters with random goals in 6 x 6 m for 20 s: the closest two ever come, over
    // the sum of their radii, for the curving walk and for the straight walk.
    const Loaded straight = acceptance::load(acceptance::generatedClip("yup_walk"));
    const double curvingClosest = acceptance::closestApproach(curving.clip, 30, 6.0F, 20.0);
    const double straightClosest = acceptance::closestApproach(straight.clip, 30, 6.0F, 20.0);
    std::printf("avoid mode, 30 characters in 6 x 6 m for 20 s: closest %.3f of the radii sum (curving_walk), %.3f (yup_walk)\n",
                curvingClosest, straightClosest);
    EXPECT_GE(straightClosest, 0.9);
    EXPECT_GE(curvingClosest, 0.9);
}

// Stature within 1.4-2.0 m on every shared capture, and the same subject's CMU clips (131_01,
// 131_02) agree within 3%.
TEST(RootMotionAcceptance, StatureIsHumanOnEverySharedCapture) {
    if (!acceptance::haveSharedCaptures()) GTEST_SKIP() << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
    for (const std::string& path : acceptance::sharedCaptures()) {
        SCOPED_TRACE(path);
        const Loaded l = acceptance::load(path);
        // Measured again from the raw capture (head top minus the lowest sole, per frame).
        const motion::Anatomy anatomy = motion::findAnatomy(l.raw);
        const quality::PointSeries raw = quality::rawWorldPositions(l.raw, l.clip.metresPerUnit, l.clip.upAxis, true);
        const int first = acceptance::firstUsableFrame(l.clip);
        const double median = quality::measuredStature(raw, anatomy, 0.5, first);
        const double p90 = quality::measuredStature(raw, anatomy, 0.9, first);
        std::printf("%-40s stature %.4f m (raw: median %.4f m, 90th percentile %.4f m)\n", acceptance::fileName(path).c_str(),
                    l.clip.stature, median, p90);
        EXPECT_GE(l.clip.stature, 1.4);
        EXPECT_LE(l.clip.stature, 2.0);
        EXPECT_NEAR(l.clip.stature, p90, 0.01 * p90) << "the engine's stature is not the body's upright height";
    }
    const double a = acceptance::load(acceptance::sharedCapture("cmu_131_01_walk_3dsmax.bvh")).clip.stature;
    const double b = acceptance::load(acceptance::sharedCapture("cmu_131_02_walk_3dsmax_scaled_m.bvh")).clip.stature;
    const double difference = std::abs(a - b) / std::min(a, b);
    std::printf("CMU subject 131: 131_01 %.4f m, 131_02 %.4f m, differ by %.2f%%\n", a, b, 100.0 * difference);
    EXPECT_LE(difference, 0.03);
}

// A clip too short for a cycle is static (no root motion) with a warning.
void expectStaticWithWarning(const char* name, const motion::BakedClip& clip) {
    const motion::GroundFrame& perLoop = clip.rootMotion.loopDisplacement();
    double furthest = 0.0;
    for (const motion::GroundFrame& ground : clip.rootMotion.frames())
        furthest = std::max(furthest, glm::length(ground.position - clip.rootMotion.frames().front().position));
    std::printf("%s: %d frames, static %d, speed %.4f m/s, loop displacement %.2e m / %.2e rad, root moves %.4f m\n", name,
                clip.frameCount, clip.isStatic ? 1 : 0, clip.speed, glm::length(perLoop.position), perLoop.yaw, furthest);
    printWarnings(name, clip);
    EXPECT_TRUE(clip.isStatic);
    EXPECT_EQ(clip.speed, 0.0);
    EXPECT_LT(glm::length(perLoop.position), 1e-9);  // composed from frames: rounding, not travel
    EXPECT_LT(std::abs(perLoop.yaw), 1e-12);
    EXPECT_EQ(furthest, 0.0);
    EXPECT_TRUE(anyWarningMentions(clip, "too short"));
}

// The pirouette-like case loops over more than half its length; the 2-frame clip is static
// with a warning.
TEST(RootMotionAcceptance, LoopsAndGaitDanceLoopsLongAndTwoFramesAreStatic) {
    expectStaticWithWarning("two_frames", acceptance::load(acceptance::generatedClip("two_frames")).clip);
    if (!acceptance::haveSharedCaptures()) GTEST_SKIP() << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
    expectStaticWithWarning("biovision_example_2frames",
                            acceptance::load(acceptance::sharedCapture("biovision_example_2frames.bvh")).clip);

    const Loaded dance = acceptance::load(acceptance::sharedCapture("mocapbank_19j_zxy_crlf.bvh"));
    const motion::BakedClip& clip = dance.clip;
    const int usable = clip.frameCount - 1 - acceptance::firstUsableFrame(clip);  // frame steps in the clip
    std::printf("mocapbank dance: %d frames, loop %d..%d (%d of %d frame steps, %.0f%%), locomotion %d, gait period %.1f frames\n",
                clip.frameCount, clip.loop().first, clip.loop().last, clip.loop().length(), usable,
                100.0 * clip.loop().length() / usable, clip.locomotion ? 1 : 0, clip.gaitPeriodFrames);
    EXPECT_FALSE(clip.locomotion) << "a dance on the spot";
    EXPECT_GT(2 * clip.loop().length(), usable);
}

// Warnings: a static ROOT, a non-Y up axis and a clip's own turning are each named; a plain
// Y-up straight walk has none.
TEST(RootMotionAcceptance, WarningsNameWhatWasGuessed) {
    const Loaded staticRoot = acceptance::load(acceptance::generatedClip("static_root_walk"));
    printWarnings("static_root_walk", staticRoot.clip);
    const std::string root = acceptance::knownAnswers("static_root_walk").at("root_joint");
    EXPECT_TRUE(anyWarningMentions(staticRoot.clip, "ROOT")) << "no warning about the ROOT";
    EXPECT_TRUE(anyWarningMentions(staticRoot.clip, root)) << "no warning names the ROOT joint " << root;

    for (const char* name : {"zup_walk", "xup_walk"}) {
        const Loaded l = acceptance::load(acceptance::generatedClip(name));
        printWarnings(name, l.clip);
        EXPECT_TRUE(anyWarningMentions(l.clip, "up axis")) << name << ": no warning about the up axis";
    }

    const Loaded curving = acceptance::load(acceptance::generatedClip("curving_walk"));
    printWarnings("curving_walk", curving.clip);
    EXPECT_TRUE(anyWarningMentions(curving.clip, "turns")) << "no warning about the clip's own turning";

    const Loaded yup = acceptance::load(acceptance::generatedClip("yup_walk"));
    printWarnings("yup_walk", yup.clip);
    EXPECT_TRUE(yup.clip.warnings.empty());
}

}  // namespace
