#pragma once
// Writing output files so that a failure never leaves a partial file behind: the bytes go
// to a temporary file in the same directory, which is renamed over the target only once
// everything was written and flushed.
//
// - "-" means standard output.
// - A target that exists and is not a regular file (a device such as /dev/null or /dev/full,
//   a FIFO) is written in place, never replaced: renaming over it would turn /dev/null into a
//   regular file when run as root. A write error there (ENOSPC from /dev/full) is an Error.
// - While a temporary file exists, SIGINT, SIGTERM and SIGHUP remove it before the process
//   ends (the handlers only unlink and re-raise, which is async-signal-safe); a signal that
//   was ignored when the first temporary was made stays ignored.

#include <span>
#include <string>
#include <string_view>

#include "throng/core/error.h"

namespace throng {

/// Writes `bytes` to `path` atomically. On failure returns a BadInput error naming the path
/// (exit 2: the output the user named can't be written), and neither `path` nor the temporary file exists
/// afterwards (unless `path` did before, in which case it is untouched).
[[nodiscard]] Result<bool> writeFileAtomically(const std::string& path, std::string_view bytes);

/// One output of writeFilesAtomically.
struct OutputFile {
    std::string path;        ///< Target path, or "-" for standard output.
    std::string_view bytes;  ///< What to write; must stay alive during the call.
};

/// Writes several outputs all or nothing, as far as the system allows: every regular target
/// is first written to its temporary, then the in-place targets (stdout, devices) are
/// written, and only when all of that succeeded are the temporaries renamed into place. On
/// failure no temporary is left and no target this call created remains; bytes already sent
/// to stdout or a device can't be taken back. The paths must differ.
[[nodiscard]] Result<bool> writeFilesAtomically(std::span<const OutputFile> outputs);

/// Whether `path` names an existing file that is not a regular file or directory (a device,
/// FIFO or socket), which writes go to in place.
[[nodiscard]] bool isSpecialFile(const std::string& path);

}  // namespace throng
