#pragma once
// Writing output files so that a failure never leaves a partial file behind: the bytes go
// to a temporary file in the same directory, which is renamed over the target only once
// everything was written and flushed.

#include <string>
#include <string_view>

#include "throng/core/error.h"

namespace throng {

/// Writes `bytes` to `path` atomically. On failure returns a Runtime error naming the path,
/// and neither `path` nor the temporary file exists afterwards (unless `path` did before,
/// in which case it is untouched).
[[nodiscard]] Result<bool> writeFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace throng
