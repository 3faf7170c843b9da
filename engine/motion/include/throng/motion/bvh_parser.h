#pragma once
// BVH (Biovision Hierarchy) reader. It accepts the whole format as real exporters write it
// (any channel order, 0-6 channels per joint, End Sites, CRLF/LF/mixed line endings, tabs,
// blank lines, every decimal form) and rejects everything else with an Error that names
// the file, line and column and says what was expected and what was found. Input is never
// accepted half-read: a Result holds either the whole RawMotion or an Error.

#include <string>
#include <string_view>

#include "throng/core/error.h"
#include "throng/core/supported_range.h"
#include "throng/motion/raw_motion.h"

namespace throng::motion {

/// Limits that bound work and memory on hostile input. Defaults fit any real capture.
struct BvhLimits {
    int maxJoints = range::kMaxJoints;           ///< ROOT + JOINT blocks, End Sites excluded.
    long long maxFileBytes = 1LL << 30;          ///< Larger files are refused before reading.
};

/// Parses BVH text. `sourceName` is used in error messages (a path, or a label).
[[nodiscard]] Result<RawMotion> parseBvh(std::string_view text, std::string_view sourceName,
                                         const BvhLimits& limits = {});

/// Reads and parses a file. A missing or unreadable file is a BadInput error naming it.
[[nodiscard]] Result<RawMotion> loadBvhFile(const std::string& path, const BvhLimits& limits = {});

}  // namespace throng::motion
