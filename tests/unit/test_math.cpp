// The libm-free float atan2 and cos the crowd step uses, against the C library's, over every
// direction of the circle and over the argument range the step gives them; and the division
// of whole numbers by a stored inverse.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "throng/core/math.h"

namespace throng {
namespace {

TEST(FastMath, Atan2MatchesTheLibraryAllRoundTheCircle) {
    double worst = 0.0;
    // A prime count of directions, so no two land on the same octant boundary pattern, and
    // lengths from a millimetre to a kilometre (the ratio is what matters; the length must not).
    for (const float length : {1e-3F, 0.7F, 1.0F, 3.5F, 1e3F})
        for (int k = 0; k < 100003; ++k) {
            const double angle = -3.141592653589793 + 6.283185307179586 * k / 100003.0;
            const auto y = static_cast<float>(length * std::sin(angle)), x = static_cast<float>(length * std::cos(angle));
            const double error = std::abs(static_cast<double>(fastAtan2(y, x)) - std::atan2(static_cast<double>(y), static_cast<double>(x)));
            worst = std::max(worst, std::min(error, std::abs(error - 6.283185307179586)));  // -pi and pi are one direction
        }
    EXPECT_LT(worst, 3e-7);
}

TEST(FastMath, Atan2OnTheAxesAndAtTheEdges) {
    constexpr auto kHalfPi = static_cast<float>(1.5707963267948966), kPi = static_cast<float>(3.141592653589793);
    EXPECT_EQ(fastAtan2(0.0F, 1.0F), 0.0F);
    EXPECT_EQ(fastAtan2(0.0F, 0.0F), 0.0F);
    EXPECT_NEAR(fastAtan2(1.0F, 0.0F), kHalfPi, 1e-7F);
    EXPECT_NEAR(fastAtan2(-1.0F, 0.0F), -kHalfPi, 1e-7F);
    EXPECT_NEAR(fastAtan2(0.0F, -1.0F), kPi, 1e-7F);
    EXPECT_NEAR(fastAtan2(1.0F, 1.0F), 0.78539816F, 1e-7F);
    EXPECT_NEAR(fastAtan2(1e-30F, 1e30F), 0.0F, 1e-7F);
    EXPECT_NEAR(fastAtan2(1e30F, 1e-30F), kHalfPi, 1e-7F);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isnan(fastAtan2(nan, 1.0F)));
    EXPECT_TRUE(std::isnan(fastAtan2(1.0F, nan)));
}

TEST(FastMath, CosMatchesTheLibrary) {
    double worst = 0.0;
    for (int k = 0; k <= 200000; ++k) {
        const float x = -20.0F + 40.0F * static_cast<float>(k) / 200000.0F;
        worst = std::max(worst, std::abs(static_cast<double>(fastCos(x)) - std::cos(static_cast<double>(x))));
    }
    for (const float x : {0.0F, 1.5707964F, -1.5707964F, 3.1415927F, -3.1415927F, 1e4F, -9999.5F})
        worst = std::max(worst, std::abs(static_cast<double>(fastCos(x)) - std::cos(static_cast<double>(x))));
    EXPECT_LT(worst, 2e-7);
    EXPECT_TRUE(std::isnan(fastCos(std::numeric_limits<float>::quiet_NaN())));
    for (const float x : {1e5F, -3e9F, 1e30F, std::numeric_limits<float>::max()}) EXPECT_EQ(fastCos(x), std::cos(x)) << x;
    EXPECT_TRUE(std::isnan(fastCos(std::numeric_limits<float>::infinity())));
}

TEST(FastMath, DivideWholeIsExactEvenWhenTheInverseIsOffByAnUlpOrTwo) {
    // An inverse nudged down makes m k (1/m) round below k, one nudged up makes -m k round
    // below -k: both would give the wrong quotient without the correction step.
    for (const double count : {1.0, 2.0, 3.0, 5.0, 7.0})
        for (const double direction : {0.0, 1.0}) {
            double inverse = 1.0 / count;
            for (int nudge = 0; nudge < 2; ++nudge) inverse = std::nextafter(inverse, direction);
            for (double whole = -30000.0; whole <= 30000.0; whole += 1.0) {
                const WholeDivision got = divideWhole(whole, count, inverse);
                ASSERT_EQ(got.quotient, std::floor(whole / count)) << whole << " / " << count;
                ASSERT_EQ(got.remainder, whole - std::floor(whole / count) * count) << whole << " / " << count;
            }
        }
}

}  // namespace
}  // namespace throng
