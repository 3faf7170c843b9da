#pragma once
// The world Throng supports, stated once. Every value that enters from outside (a scene file,
// the command line, a BVH file) is checked against these bounds where it enters, and refused
// with exit code 2 and a message naming the file:line:column (BVH), the JSON path (scene) or
// the option (command line). Finite is not enough: 1e39 is a finite double but an infinite
// float, and 1e300 survives parsing only to overflow later. Inside these bounds every later
// computation stays finite in float (coordinates squared stay below 1e14, far from FLT_MAX
// 3.4e38) and every float-to-integer conversion (frame indices, grid cells) is in range.
//
//   value                                       supported range
//   world coordinates: region centres,          |x| <= 1e6 m (1000 km; float still resolves
//     waypoints, camera eye and target,           6 cm there)
//   sizes: spawn regions, goal areas            0.01 m <= size <= 1e5 m
//   headings                                    any finite angle, reduced modulo 360 degrees
//   playback speed range                        0 < min <= max <= 4
//   desired ground speed (locomotion sets)      0 <= min <= max <= 20 m/s
//   camera field of view                        1 < fov < 170 degrees
//   characters / simulated time / waypoints     1..1e6 / 0..600 s / at most 10000
//   BVH OFFSET and channel values               |v| <= 1e6 (file units, or degrees)
//   BVH frame time                              1e-6 .. 3600 s
//   BVH skeleton                                at most 100000 joints (so forward kinematics
//                                                 sums at most 1e5 offsets of 1.7e6: 2e11),
//                                                 names of at most 256 bytes
//   baked clip                                  every joint within 1e6 m of the origin (after
//                                                 the unit scale) and frames x joints <= 2^24
//
// Characters that walk out of the world (a clip that travels 1e6 m per loop, for one) are
// held at its edge, kWorldEdge, so the simulation stays finite for any accepted input.

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace throng::range {

inline constexpr double kMaxCoordinate = 1e6;             ///< Metres, |x| of any world position given.
inline constexpr double kMinSize = 0.01;                  ///< Metres, smallest region or area side.
inline constexpr double kMaxSize = 1e5;                   ///< Metres, largest region or area side.
inline constexpr double kWorldEdge = 1e7;                 ///< Metres: characters are held within |x| <= this.
inline constexpr double kMaxPlaybackSpeed = 4.0;          ///< Playback multiplier.
inline constexpr double kLargestSpeed = 20.0;             ///< m/s, a desired ground speed (sets clamp it to their own range).
inline constexpr double kMinFieldOfView = 1.0;            ///< Degrees, exclusive.
inline constexpr double kMaxFieldOfView = 170.0;          ///< Degrees, exclusive.
inline constexpr int kMaxCharacters = 1'000'000;
inline constexpr double kMaxTimeSeconds = 600.0;
inline constexpr std::size_t kMaxWaypoints = 10'000;
inline constexpr double kMaxBvhValue = 1e6;               ///< |OFFSET| and |channel value|, file units or degrees.
inline constexpr double kMinFrameTime = 1e-6;             ///< Seconds.
inline constexpr double kMaxFrameTime = 3600.0;           ///< Seconds.
inline constexpr int kMaxJoints = 100'000;
inline constexpr std::size_t kMaxJointNameBytes = 256;
inline constexpr double kMaxClipReach = 1e6;              ///< Metres: a baked joint's largest |coordinate|.
/// Metres: the shortest body a clip with any height may stand (after its unit): units=1e-300
/// or OFFSETs of 1e-30 made bodies of 0 m, drawn as nothing with exit 0. A lone joint with no
/// height at all is a point, and allowed.
inline constexpr double kMinClipStature = 0.01;
inline constexpr std::int64_t kMaxBakedJointFrames = std::int64_t{1} << 24;  ///< frames x joints (512 MiB of poses).

/// True when lo <= value <= hi; false for NaN.
[[nodiscard]] constexpr bool within(double value, double lo, double hi) { return value >= lo && value <= hi; }
/// A world coordinate: |value| <= kMaxCoordinate.
[[nodiscard]] constexpr bool isCoordinate(double value) { return within(value, -kMaxCoordinate, kMaxCoordinate); }
/// A region or area side: kMinSize <= value <= kMaxSize (a positive 1e-50 is 0 as a float).
[[nodiscard]] constexpr bool isSize(double value) { return within(value, kMinSize, kMaxSize); }
/// A BVH OFFSET coordinate or channel value.
[[nodiscard]] constexpr bool isBvhValue(double value) { return within(value, -kMaxBvhValue, kMaxBvhValue); }

/// `degrees` reduced exactly into [-180, 180] (any finite angle is a heading); NaN stays NaN.
[[nodiscard]] inline double reduceDegrees(double degrees) { return std::remainder(degrees, 360.0); }

/// How messages state the ranges.
inline constexpr const char* kCoordinateText = "from -1000000 to 1000000 m";
inline constexpr const char* kSizeText = "from 0.01 to 100000 m";
inline constexpr const char* kBvhValueText = "from -1000000 to 1000000";

}  // namespace throng::range
