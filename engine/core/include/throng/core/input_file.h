#pragma once
// Reading a whole input file (a BVH clip, a scene, a trajectory) with the checks every input
// needs: it must be a regular file (a FIFO or a device would block or never end), readable,
// and no larger than the caller's limit. Errors name the file and say what was wrong.

#include <cstdint>
#include <string>

#include "throng/core/error.h"

namespace throng {

/// The file's bytes. `what` names the kind of file in messages ("BVH file", "scene file").
/// Fails (BadInput) when the path is missing, not a regular file, unreadable or over `maxBytes`.
[[nodiscard]] Result<std::string> readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what);

}  // namespace throng
