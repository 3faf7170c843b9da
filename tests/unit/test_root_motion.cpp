// RootMotionTrack: ground frames at any unwrapped frame position, continuous across the loop.
#include <gtest/gtest.h>

#include "throng/motion/root_motion.h"

namespace {

using throng::motion::GroundFrame;
using throng::motion::LoopRange;
using throng::motion::RootMotionTrack;

void expectNear(const GroundFrame& a, const GroundFrame& b, double tolerance = 1e-9) {
    EXPECT_NEAR(a.position.x, b.position.x, tolerance);
    EXPECT_NEAR(a.position.y, b.position.y, tolerance);
    EXPECT_NEAR(a.yaw, b.yaw, tolerance);
}

// A clip that walks along +Z at 1 unit per frame while turning 0.1 rad per frame.
RootMotionTrack curvingTrack() {
    std::vector<GroundFrame> frames;
    GroundFrame g;
    for (int f = 0; f < 11; ++f) {
        frames.push_back(g);
        g = g.then(GroundFrame{{0.0, 1.0}, 0.1});
    }
    return RootMotionTrack(frames, LoopRange{2, 8});
}

TEST(GroundFrame, ThenAndInverseAreConsistent) {
    const GroundFrame a{{1.0, 2.0}, 0.7}, b{{-3.0, 0.5}, -1.2};
    expectNear(a.then(a.inverse()), GroundFrame{});
    expectNear(a.inverse().then(a.then(b)), b);
    // Rotating +Z by +90 degrees about +Y gives +X (right-handed, Y up).
    const glm::dvec2 p = GroundFrame{{0, 0}, 1.5707963267948966}.apply({0.0, 1.0});
    EXPECT_NEAR(p.x, 1.0, 1e-12);
    EXPECT_NEAR(p.y, 0.0, 1e-12);
}

TEST(GroundFrame, MatrixAgreesWithApply) {
    const GroundFrame g{{2.0, -1.0}, 0.4};
    const glm::dvec4 m = g.matrix() * glm::dvec4(0.3, 5.0, -0.7, 1.0);
    const glm::dvec2 p = g.apply({0.3, -0.7});
    EXPECT_NEAR(m.x, p.x, 1e-12);
    EXPECT_NEAR(m.z, p.y, 1e-12);
    EXPECT_NEAR(m.y, 5.0, 1e-12);
}

TEST(RootMotionTrack, InsideTheLoopItIsTheTrack) {
    const RootMotionTrack track = curvingTrack();
    for (int f = 2; f < 8; ++f) expectNear(track.at(f), track.frames()[static_cast<std::size_t>(f)]);
    // Halfway between frames it interpolates position and yaw.
    const GroundFrame mid = track.at(4.5);
    EXPECT_NEAR(mid.yaw, 0.45, 1e-12);
}

TEST(RootMotionTrack, WrapContinuesTheMotionInsteadOfJumpingBack) {
    const RootMotionTrack track = curvingTrack();
    // Frame 8 is where frame 2 stands in; past it the loop continues from frame 2, moved on.
    expectNear(track.at(8.0), track.frames()[8]);
    const GroundFrame before = track.at(7.999), after = track.at(8.001);
    EXPECT_LT(glm::length(after.position - before.position), 0.01);
    EXPECT_LT(std::abs(after.yaw - before.yaw), 0.001);
    // Each loop adds the same displacement: at(x + L) = D ∘ at(x).
    for (double x : {2.0, 3.25, 7.5}) expectNear(track.at(x + 6.0), track.loopDisplacement().then(track.at(x)), 1e-9);
}

TEST(RootMotionTrack, DeltasComposeOverAnySplit) {
    const RootMotionTrack track = curvingTrack();
    const GroundFrame whole = track.delta(2.3, 31.7);  // several loops in one step
    GroundFrame stepped;
    for (double x = 2.3; x < 31.7 - 1e-9; x += 0.7) stepped = stepped.then(track.delta(x, std::min(x + 0.7, 31.7)));
    expectNear(stepped, whole, 1e-9);
}

TEST(RootMotionTrack, HugeJumpsStayFinite) {
    const RootMotionTrack track = curvingTrack();
    const GroundFrame far = track.at(6.0e6);
    EXPECT_TRUE(std::isfinite(far.position.x) && std::isfinite(far.position.y) && std::isfinite(far.yaw));
}

TEST(RootMotionTrack, WrapFoldsIntoTheLoop) {
    const RootMotionTrack track = curvingTrack();
    EXPECT_DOUBLE_EQ(track.wrap(2.0), 2.0);
    EXPECT_DOUBLE_EQ(track.wrap(8.0), 2.0);
    EXPECT_DOUBLE_EQ(track.wrap(9.5), 3.5);
    EXPECT_DOUBLE_EQ(track.wrap(1.0), 7.0);
}

}  // namespace

// delta() takes its rotation from stored cosines and a series for the turn within a frame:
// it must agree with at(from).to(at(to)) (the library's cos and sin) for gentle turns, for
// turns too wild for the series (which take the library's), and across the loop's seam.
TEST(RootMotionTrack, DeltaAgreesWithComposingTheFramesAtAnyTurnRate) {
    for (const double turnPerFrame : {0.0, 0.1, -0.2, 0.4, -1.5}) {
        std::vector<GroundFrame> frames;
        GroundFrame g{{3.0, -2.0}, 0.3};
        for (int f = 0; f < 40; ++f) {
            frames.push_back(g);
            g = g.then(GroundFrame{{0.05 * f, 1.0}, turnPerFrame * (1.0 + 0.01 * f)});
        }
        const RootMotionTrack track(frames, LoopRange{3, 37});
        for (int k = 0; k < 500; ++k) {
            const double from = 3.0 + 33.99 * k / 500.0;
            for (const double step : {0.0, 0.37, 1.0, 2.6, 40.0}) {
                const GroundFrame expected = track.at(from).to(track.at(from + step));
                const GroundFrame got = track.delta(from, from + step);
                EXPECT_NEAR(got.position.x, expected.position.x, 1e-12) << turnPerFrame << " " << from << " " << step;
                EXPECT_NEAR(got.position.y, expected.position.y, 1e-12) << turnPerFrame << " " << from << " " << step;
                EXPECT_EQ(got.yaw, expected.yaw);
            }
        }
    }
}
