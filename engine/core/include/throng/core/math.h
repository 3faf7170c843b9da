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

}  // namespace throng
