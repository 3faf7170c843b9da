#pragma once
// Writing output files so that a failure never leaves a partial file behind: the bytes go
// to a temporary file in the same directory, which is renamed over the target only once
// everything was written and flushed.
//
// - "-" means standard output.
// - A target that exists and is not a regular file (a device such as /dev/null or /dev/full,
//   a FIFO) is written in place, never replaced: renaming over it would turn /dev/null into a
//   regular file when run as root. A write error there (ENOSPC from /dev/full) is an Error.
// - While a temporary file exists, SIGINT, SIGTERM, SIGHUP and SIGPIPE (a reader of stdout
//   that went away while another output was still being written) remove it before the
//   process ends (the handlers only unlink and re-raise, which is async-signal-safe); a signal
//   that was ignored when the first temporary was made stays ignored.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

/// Outputs written piece by piece and put in place together: the streaming form of
/// writeFilesAtomically, for outputs too large to hold in memory (`throng simulate`'s CSV).
/// open() creates a temporary beside every regular target; append() adds bytes to one output
/// (a target written in place, stdout or a device or FIFO, is opened at its first bytes and
/// written as they come); commit() flushes and closes every output and renames the
/// temporaries into place, with writeFilesAtomically's guarantees. Until commit() succeeds no
/// regular target has changed: destroyed before (an error, an exception), it removes every
/// temporary, and a signal does too (see above). Move-only.
class StreamedOutputs {
public:
    /// One output per path, in this order (the paths must differ; an empty one is an error).
    [[nodiscard]] static Result<StreamedOutputs> open(std::span<const std::string> paths);
    /// Appends `bytes` to output `index`. Errors name the path (BadInput, as above); after one,
    /// only destruction is left to do.
    [[nodiscard]] Result<bool> append(std::size_t index, std::string_view bytes);
    /// Every output flushed, closed and put in place, or (as far as the system allows) none.
    /// Call once.
    [[nodiscard]] Result<bool> commit();
    /// Whether output `index` is written in place (stdout, a device, a FIFO) rather than renamed.
    [[nodiscard]] bool writesInPlace(std::size_t index) const;

    StreamedOutputs(StreamedOutputs&&) noexcept;
    StreamedOutputs& operator=(StreamedOutputs&&) noexcept;
    StreamedOutputs(const StreamedOutputs&) = delete;
    StreamedOutputs& operator=(const StreamedOutputs&) = delete;
    ~StreamedOutputs();

private:
    StreamedOutputs();
    class Target;
    std::vector<std::unique_ptr<Target>> targets_;
};

/// Whether `path` names an existing file that is not a regular file or directory (a device,
/// FIFO or socket), which writes go to in place.
[[nodiscard]] bool isSpecialFile(const std::string& path);

}  // namespace throng
