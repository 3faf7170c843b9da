#pragma once
// Trajectories from other tools: pedestrian simulators (JuPedSim, Vadere, Menge, RVO2
// applications, social-force models) and measured crowds (ETH/UCY, the Jülich experiments as
// PedPy reads them). A file is read once into tracks, one per person, of timed ground
// positions; a crowd spawned with them (CrowdSetup::trajectories) follows them instead of
// simulating, its poses blended from a locomotion set by the speed the track moves at.
//
// Two layouts, told apart by the first line that is not blank:
//   CSV with a header: id, frame or time, x, y and optionally z, in any order, other columns
//     ignored (Throng's own `simulate --out` file is one); a row per person and sample; a
//     header with spaces and no comma leads space-separated rows, and Vadere's column names
//     (pedestrianId, simTime, timeStep, startX-PID1, ...) read as Throng's;
//   the whitespace text layout of JuPedSim and PedPy: '#' comment lines (a "framerate" line
//     gives the rate, "x/cm", "in cm" or "in mm" the unit), an optional "#ID FR X Y Z" column
//     line, then rows "ID FR X Y [Z ...]".
// Throng's time 0 is the file's earliest sample, and the positions are turned into Throng's
// ground (x, z) without mirroring: see TrajectoryAxes.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "throng/core/error.h"
#include "throng/core/math.h"

namespace throng::crowd {

/// Which two of a file's coordinate columns are the ground plane.
enum class TrajectoryAxes : std::uint8_t {
    Auto,  ///< xz for a file whose header has Throng's own `heading` column (Y up), else xy.
    Xy,    ///< x and y are the ground (pedestrian tools; z is a level's height): world x = x,
           ///< world z = -y, so a plan seen from above is not mirrored (Throng is Y up, right-handed).
    Xz,    ///< x and z are the ground, Y up as in Throng: world x = x, world z = z.
};
[[nodiscard]] const char* trajectoryAxesName(TrajectoryAxes axes);  ///< "auto", "xy", "xz"

/// The supported ranges of a trajectory file, checked where each value enters.
inline constexpr double kMinTrajectoryRate = 1.0;      ///< Samples per second, a numbered file's frame rate.
inline constexpr double kMaxTrajectoryRate = 1000.0;   ///< Also the closest two timed samples of a track may be (1 ms).
inline constexpr double kMaxTrajectoryClock = 1e10;    ///< Seconds, |time| in a file: Unix time (seconds since 1970) fits.
inline constexpr double kMaxTrajectoryTime = 1e7;      ///< Seconds from a file's first sample to its last (about 115 days).
inline constexpr std::int64_t kMaxTrajectoryFrame = 1'000'000'000;
inline constexpr std::uint64_t kMaxTrajectoryBytes = std::uint64_t{1} << 31;  ///< 2 GiB.

/// How to read a file where it can't say itself.
struct TrajectoryOptions {
    TrajectoryAxes axes = TrajectoryAxes::Auto;
    /// Metres per file unit (--trajectory-units m 1, cm 0.01, mm 0.001). nullopt: what the
    /// header says (the text layout's "x/cm", "in cm", "in mm"), else metres.
    std::optional<double> metresPerUnit;
    /// Samples per second of a file that numbers frames (--trajectory-fps), 1..1000. nullopt:
    /// the text layout's "framerate" comment; a CSV with only a frame column then needs it.
    std::optional<double> framesPerSecond;
};

/// One sample of a track.
struct TrackSample {
    double time = 0.0;             ///< Seconds since the file's earliest sample (>= 0).
    glm::dvec2 position{0.0};      ///< Throng's ground (world x, world z), metres.
};

/// One person's path: at least two samples, their times strictly increasing.
struct Track {
    std::int64_t id = 0;               ///< The file's id.
    std::vector<TrackSample> samples;
};

/// A file's tracks, with what was found in it.
struct Trajectories {
    std::vector<Track> tracks;    ///< In ascending id.
    /// What was detected, for the user: layout, columns used, ground axes, unit, rate.
    std::string format;
    double startTime = 0.0;       ///< The earliest sample's own time in the file, seconds (Throng's time 0).
    double duration = 0.0;        ///< Seconds from the earliest sample to the latest.
    std::size_t rows = 0;         ///< Samples read.
};

/// Reads and checks `path` (at most kMaxTrajectoryBytes). Every error is BadInput and names
/// the file, line and column: a missing column, a field that is not a number (or is NaN,
/// infinite or out of range), a row with fields missing, an id or frame that isn't whole, an
/// (id, frame) given twice, a track whose samples go back in time, a track of one sample, no
/// frame rate for numbered frames, samples closer than 1 ms, more tracks than kMaxCharacters.
[[nodiscard]] Result<Trajectories> readTrajectories(const std::string& path, const TrajectoryOptions& options);

/// The same for text already in memory; `path` only names it in errors.
[[nodiscard]] Result<Trajectories> parseTrajectories(std::string_view text, const std::string& path, const TrajectoryOptions& options);

/// Where `track` is at `time` (seconds, Throng's clock): a cubic Hermite curve through its
/// samples (tangents from the neighbouring samples, limited to 1.5 times the slower adjacent
/// chord's speed so it never overshoots into a stop), so motion is smooth at any output frame
/// rate and exact at every sample; held at the first or last sample outside the track's span.
[[nodiscard]] glm::dvec2 trackPosition(const Track& track, double time);

}  // namespace throng::crowd
