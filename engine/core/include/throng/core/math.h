#pragma once
// Math for the whole project goes through GLM, with one set of conventions:
//  - column-major matrices acting on column vectors: p' = M * p, and A * B applies B first;
//  - right-handed coordinates, +Y up, characters face +Z in their own frame;
//  - lengths in metres once a clip is baked (raw BVH data keeps its own units);
//  - angles in radians inside the engine; BVH files store degrees.
// Include this header instead of GLM directly so every translation unit agrees on them.

#define GLM_FORCE_RADIANS
#define GLM_FORCE_DEPTH_ZERO_TO_ONE  // Vulkan clip space: z in [0, 1]
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

/// On a function: GCC's auto-vectoriser leaves it alone. For short loops over a small buffer
/// just filled by scalar stores: a vector load spanning several of them can't take them from
/// the store buffer and waits for them to reach the cache (in the crowd's neighbour search that
/// wait was a quarter of the search). Clang (the fuzz build) goes without. GCC applies it to
/// the function's own body, lambdas inlined into it included, and no longer inlines the function
/// into its callers; GCC 14's `#pragma GCC novector` on the loops would say it more narrowly.
#if defined(__GNUC__) && !defined(__clang__)
#define THRONG_NO_VECTORIZE __attribute__((optimize("no-tree-vectorize")))
#else
#define THRONG_NO_VECTORIZE
#endif

namespace throng {

/// Rotation about +Y (yaw) by `radians`, counter-clockwise seen from above (+Y).
inline glm::dquat yawQuat(double radians) { return glm::angleAxis(radians, glm::dvec3(0, 1, 0)); }

/// Rotates a ground-plane vector (x, z) by `radians` about +Y, matching yawQuat.
inline glm::dvec2 rotateGround(glm::dvec2 xz, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    // Rotation about +Y maps x -> (c x + s z) and z -> (-s x + c z).
    return {c * xz.x + s * xz.y, -s * xz.x + c * xz.y};
}

/// Yaw (radians) of a direction projected onto the ground: 0 faces +Z, +pi/2 faces +X.
inline double yawOf(glm::dvec3 direction) { return std::atan2(direction.x, direction.z); }

/// Wraps an angle into (-pi, pi].
inline double wrapAngle(double radians) {
    constexpr double kPi = 3.141592653589793238463, kTwoPi = 2.0 * kPi;
    // Angles here are almost always within a turn or two of the range; loops beat
    // std::remainder (a slow libm call) there, and the remainder handles the rest.
    if (std::abs(radians) > 8.0 * kTwoPi) radians = std::remainder(radians, kTwoPi);
    while (radians > kPi) radians -= kTwoPi;
    while (radians <= -kPi) radians += kTwoPi;
    return radians;
}

/// std::floor(value), without a libm call: baseline x86-64 (what Debian builds for) has no
/// SSE4.1 rounding instruction, so std::floor is a function call, and the crowd step takes a
/// dozen per character. Same value for every input (NaN and infinities pass through; doubles
/// of magnitude 2^52 or more are already whole), except that -0.0 gives +0.0.
inline double fastFloor(double value) {
    constexpr double kWhole = 4503599627370496.0;  // 2^52
    if (!(std::abs(value) < kWhole)) return value;
    const auto truncated = static_cast<double>(static_cast<long long>(value));
    return truncated > value ? truncated - 1.0 : truncated;
}

/// floor(value) as an integer clamped to [lo, hi], with NaN giving lo. Converting a float
/// that is NaN, infinite or out of the integer's range is undefined behaviour (and at -O3 it
/// really misbehaves), so every float-to-index conversion goes through here.
template <typename Int>
[[nodiscard]] inline Int clampedFloor(double value, Int lo, Int hi) {
    if (!(value > static_cast<double>(lo))) return lo;  // below, or NaN
    if (!(value < static_cast<double>(hi))) return hi;
    return static_cast<Int>(fastFloor(value));
}

/// floor(whole / count) and the remainder, for a whole number `whole` and a positive whole
/// `count`, from `inverse`, 1 / count to within a few units in the last place: a product
/// instead of a division (its latency is four multiplications'), which may round across a
/// multiple of count; one step puts it back. The remainder is in [0, count).
struct WholeDivision {
    double quotient = 0.0;
    double remainder = 0.0;
};
inline WholeDivision divideWhole(double whole, double count, double inverse) {
    WholeDivision result{fastFloor(whole * inverse), 0.0};
    result.remainder = whole - result.quotient * count;
    if (result.remainder >= count) {
        result.quotient += 1.0;
        result.remainder -= count;
    } else if (result.remainder < 0.0) {
        result.quotient -= 1.0;
        result.remainder += count;
    }
    return result;
}

/// atan2(y, x) in float, in [-pi, pi], without a libm call: glibc's atan2f was a tenth of the
/// avoid-mode crowd step (two per character per step). Cephes' atanf polynomial after folding
/// the ratio into [0, tan(pi/8)]: within 3e-7 radians of std::atan2 (tests/unit/test_math.cpp),
/// and the same bits on every machine, whatever its libm. NaN in (or both infinite) gives NaN;
/// (0, 0) gives 0.
inline float fastAtan2(float y, float x) {
    constexpr float kPi = 3.14159265358979F, kHalfPi = 0.5F * kPi, kQuarterPi = 0.25F * kPi;
    constexpr float kTanEighthPi = 0.414213562373095F;
    const float ax = std::abs(x), ay = std::abs(y);
    // The angle of (ax, ay), 0..pi/2, from a ratio t in [0, 1].
    const bool steep = ay > ax;
    const float larger = steep ? ay : ax;
    float t = larger > 0.0F ? (steep ? ax : ay) / larger : (larger == 0.0F ? 0.0F : larger);
    float offset = 0.0F;
    if (t > kTanEighthPi) {  // atan(t) = pi/4 + atan((t - 1) / (t + 1))
        offset = kQuarterPi;
        t = (t - 1.0F) / (t + 1.0F);
    }
    const float z = t * t;
    float angle = offset + ((((8.05374449538e-2F * z - 1.38776856032e-1F) * z + 1.99777106478e-1F) * z - 3.33329491539e-1F) * z * t + t);
    if (steep) angle = kHalfPi - angle;
    if (x < 0.0F) angle = kPi - angle;
    return std::copysign(angle, y);
}

/// cos(radians) in float without a libm call, within 2e-7 of std::cos for |radians| up to
/// 1e4 (tests/unit/test_math.cpp); the crowd step takes one per character. Past 1e4 radians
/// (never, from the step) and for NaN it is std::cos, as a reduction by 2 pi loses precision.
inline float fastCos(float radians) {
    constexpr double kTwoPi = 6.283185307179586;
    if (!(std::abs(radians) <= 1e4F)) return std::cos(radians);
    // Reduced in double, so the reduction itself loses nothing a float would notice.
    double x = static_cast<double>(radians);
    x -= kTwoPi * fastFloor(x * (1.0 / kTwoPi) + 0.5);  // -pi..pi (to rounding: cos doesn't mind)
    // cos(x) = -cos(pi - |x|): fold into [0, pi/2], where the series converges fast.
    const bool far = std::abs(x) > 0.5 * 3.141592653589793;
    const double folded = far ? 3.141592653589793 - std::abs(x) : x;
    const double z = folded * folded;
    const double c = 1.0 + z * (-1.0 / 2 + z * (1.0 / 24 + z * (-1.0 / 720 + z * (1.0 / 40320 + z * (-1.0 / 3628800 + z * (1.0 / 479001600))))));
    return static_cast<float>(far ? -c : c);
}

}  // namespace throng
