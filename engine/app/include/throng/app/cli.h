#pragma once
// Command-line parsing for `throng`, as a pure function from arguments to a Command value:
// no I/O, no globals, so every flag combination is unit-testable.

#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "throng/core/error.h"
#include "throng/motion/baked_clip.h"

namespace throng::app {

/// `throng bvh info FILE [--json OUT|-] [bake options]`
struct BvhInfoCommand {
    std::string file;
    motion::BakeOptions bake;              ///< --position-channels, --units, --loop, --keep-first-frame
    std::optional<std::string> jsonOut;    ///< Also write the summary as JSON ("-" for stdout).
};

/// `throng bvh bake FILE --json OUT|- [--frames all|LIST] [--position-channels replace|add]`
struct BvhBakeCommand {
    std::string file;
    std::string jsonOut;                   ///< Path, or "-" for stdout.
    std::optional<std::vector<int>> frames;  ///< nullopt means every frame.
    motion::PositionChannels positionChannels = motion::PositionChannels::Replace;
};

/// `throng bvh bench [FILE...] [--repeat N]`: parse and bake timings (a benchmark, not a test).
struct BvhBenchCommand {
    std::vector<std::string> files;        ///< Empty means the default clip.
    int repeat = 15;                       ///< Timed repetitions per file; the median is reported.
};

/// `--help` anywhere, or no arguments: print `text` to stdout and exit 0.
struct HelpCommand {
    std::string text;
};

struct VersionCommand {};

using Command = std::variant<HelpCommand, VersionCommand, BvhInfoCommand, BvhBakeCommand, BvhBenchCommand>;

/// Parses argv[1..]. Usage errors come back as BadInput errors whose message ends with a
/// hint to run --help.
[[nodiscard]] Result<Command> parseCommandLine(std::span<const std::string> args);

}  // namespace throng::app
