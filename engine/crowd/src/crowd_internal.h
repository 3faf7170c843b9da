#pragma once
// Small helpers the crowd's translation units share: the ground plane's, and numbers in messages.

#include <cmath>
#include <cstdio>
#include <string>

#include "throng/core/rng.h"
#include "throng/crowd/crowd.h"

namespace throng::crowd::detail {

inline glm::vec2 randomPointIn(const Region& region, Rng& rng) {
    return region.centre + glm::vec2(rng.uniform(-0.5F, 0.5F) * region.size.x, rng.uniform(-0.5F, 0.5F) * region.size.y);
}

/// The part of `x` past its floor, 0..1: a gait phase from a count of cycles.
inline double fraction(double x) { return x - fastFloor(x); }

/// The whole number nearest `x` (halves round up): x - nearestWhole(x) is how far a phase
/// difference is from agreeing, -0.5..0.5.
inline double nearestWhole(double x) { return fastFloor(x + 0.5); }

/// The yaw that faces `direction` (0 faces +Z, the ground frame's heading convention). The
/// crowd step takes two per character, so without a libm call (fastAtan2).
inline float yawToward(glm::vec2 direction) { return fastAtan2(direction.x, direction.y); }

/// A number as error messages show it: "1", "12.5", "1e+07".
inline std::string shown(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace throng::crowd::detail
