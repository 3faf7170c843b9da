#include "throng/core/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <mutex>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace throng {
namespace {

// --- Temporary files that a signal must not leave behind --------------------------------
//
// A fixed table the signal handler can read without locks or allocation: a slot is free (0),
// being filled (1) or armed (2). The handler unlinks every armed path and re-raises.

constexpr std::size_t kSlots = 32;
constexpr std::size_t kPathBytes = 4096 + 32;  // PATH_MAX plus the ".tmp-XXXXXX" suffix
constexpr std::array<int, 4> kSignals{SIGINT, SIGTERM, SIGHUP, SIGPIPE};

struct PendingSlot {
    std::atomic<int> state{0};
    char path[kPathBytes] = {};
};
PendingSlot gPending[kSlots];
struct sigaction gPrevious[kSignals.size()];
std::mutex gInstalling;  // installHandlers() from several threads at once

extern "C" void removePendingThenReraise(int signal) {
    const int savedErrno = errno;
    for (PendingSlot& slot : gPending)
        if (slot.state.load() == 2) ::unlink(slot.path);
    for (std::size_t i = 0; i < kSignals.size(); ++i)
        if (kSignals[i] == signal) ::sigaction(signal, &gPrevious[i], nullptr);
    errno = savedErrno;
    ::raise(signal);  // now with the previous disposition: the default ends the process
}

// Before each temporary is armed, not once per process: whoever changed a disposition since
// (a library, a forked child resetting it) gets the cleanup back in front of theirs.
void installHandlers() {
    const std::lock_guard lock(gInstalling);
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
        struct sigaction current {};
        if (::sigaction(kSignals[i], nullptr, &current) != 0) continue;
        if (current.sa_handler == &removePendingThenReraise) continue;  // ours already
        if (current.sa_handler == SIG_IGN) continue;  // nohup and friends: keep ignoring it
        gPrevious[i] = current;
        struct sigaction action {};
        action.sa_handler = &removePendingThenReraise;
        sigfillset(&action.sa_mask);
        ::sigaction(kSignals[i], &action, nullptr);
    }
}

// Blocks the cleanup signals on this thread while a temporary is created or renamed, so the
// table and the filesystem agree whenever the handler can run here.
class SignalBlock {
public:
    SignalBlock() {
        sigset_t set;
        sigemptyset(&set);
        for (const int signal : kSignals) sigaddset(&set, signal);
        pthread_sigmask(SIG_BLOCK, &set, &previous_);
    }
    ~SignalBlock() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
    SignalBlock(const SignalBlock&) = delete;
    SignalBlock& operator=(const SignalBlock&) = delete;

private:
    sigset_t previous_{};
};

// An output the user named that can't be written (a full device, no permission, a missing
// folder) is bad input, exit 2, like an input that can't be read.
Error writeError(const std::string& path, const char* what, int error) {
    return Error{Error::Kind::BadInput, std::string(what) + ": " + std::strerror(error), {path, 0, 0}};
}

// Writes all of `bytes` to `fd`, retrying short writes and EINTR; 0 or an errno.
int writeAll(int fd, std::string_view bytes) {
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        if (n == 0) return EIO;
        written += static_cast<std::size_t>(n);
    }
    return 0;
}

bool isInPlaceTarget(const std::string& path) { return path == "-" || isSpecialFile(path); }

}  // namespace

// One output: a temporary beside a regular target, renamed over it at commit and removed on
// destruction unless it was; or the target itself, written in place (stdout, a device, a
// FIFO), opened at its first bytes so that a FIFO nobody reads blocks only once the
// temporaries exist.
class StreamedOutputs::Target {
public:
    explicit Target(std::string path) : path_(std::move(path)), inPlace_(isInPlaceTarget(path_)) {}
    Target(const Target&) = delete;
    Target& operator=(const Target&) = delete;
    ~Target() {
        if (fd_ >= 0) ::close(fd_);
        discard();
    }

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] bool inPlace() const { return inPlace_; }

    /// A regular target's temporary; nothing for one written in place.
    Result<bool> create() {
        if (inPlace_) return true;
        const std::string pattern = path_ + ".tmp-XXXXXX";
        if (pattern.size() >= kPathBytes) return writeError(path_, "cannot create output file", ENAMETOOLONG);
        const SignalBlock block;
        installHandlers();
        for (std::size_t i = 0; i < kSlots && slot_ == nullptr; ++i) {
            int expected = 0;
            if (gPending[i].state.compare_exchange_strong(expected, 1)) slot_ = &gPending[i];
        }
        if (slot_ == nullptr) return writeError(path_, "cannot create output file", EMFILE);
        std::memcpy(slot_->path, pattern.c_str(), pattern.size() + 1);
        fd_ = ::mkostemp(slot_->path, O_CLOEXEC);
        if (fd_ < 0) {
            const int saved = errno;
            release();
            return writeError(path_, "cannot create output file", saved);
        }
        slot_->state.store(2);
        // mkstemp creates 0600; outputs are ordinary files the user and others may read.
        ::fchmod(fd_, 0644);
        return true;
    }

    Result<bool> append(std::string_view bytes) {
        if (path_ == "-") {
            errno = 0;
            if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size())
                return writeError("-", "cannot write to standard output", errno != 0 ? errno : EIO);
            return true;
        }
        if (fd_ < 0 && inPlace_) {
            // No O_CREAT, no O_TRUNC: the device or FIFO exists and stays what it is.
            fd_ = ::open(path_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
            if (fd_ < 0) return writeError(path_, "cannot open output file", errno);
        }
        if (const int error = writeAll(fd_, bytes); error != 0) return writeError(path_, "cannot write output file", error);
        return true;
    }

    /// Everything written reaches its file (a temporary is flushed to disk) and is closed.
    Result<bool> finish() {
        if (path_ == "-") {
            if (std::fflush(stdout) != 0) return writeError("-", "cannot write to standard output", errno);
            return true;
        }
        if (fd_ < 0 && inPlace_)  // opened even when given no bytes, as a device or FIFO expects
            if (auto opened = append({}); !opened) return opened;
        int error = !inPlace_ && ::fsync(fd_) != 0 ? errno : 0;
        if (::close(fd_) != 0 && error == 0) error = errno;
        fd_ = -1;
        if (error != 0) return writeError(path_, "cannot write output file", error);
        return true;
    }

    /// Renames the temporary over the target; afterwards nothing is left to discard.
    Result<bool> commit() {
        if (inPlace_) return true;
        const SignalBlock block;
        if (std::rename(slot_->path, path_.c_str()) != 0) return writeError(path_, "cannot move output into place", errno);
        release();
        return true;
    }

private:
    void discard() {
        if (slot_ == nullptr) return;
        const SignalBlock block;
        ::unlink(slot_->path);
        release();
    }
    void release() {
        slot_->state.store(0);
        slot_ = nullptr;
    }

    std::string path_;
    bool inPlace_ = false;
    int fd_ = -1;
    PendingSlot* slot_ = nullptr;
};

StreamedOutputs::StreamedOutputs() = default;
StreamedOutputs::StreamedOutputs(StreamedOutputs&&) noexcept = default;
StreamedOutputs& StreamedOutputs::operator=(StreamedOutputs&&) noexcept = default;
StreamedOutputs::~StreamedOutputs() = default;

Result<StreamedOutputs> StreamedOutputs::open(std::span<const std::string> paths) {
    StreamedOutputs outputs;
    for (const std::string& path : paths) {
        if (path.empty()) return Error{Error::Kind::BadInput, "the output file name is empty", {}};
        outputs.targets_.push_back(std::make_unique<Target>(path));
        if (auto created = outputs.targets_.back()->create(); !created) return created.error();
    }
    return outputs;
}

Result<bool> StreamedOutputs::append(std::size_t index, std::string_view bytes) { return targets_.at(index)->append(bytes); }

bool StreamedOutputs::writesInPlace(std::size_t index) const { return targets_.at(index)->inPlace(); }

Result<bool> StreamedOutputs::commit() {
    for (const std::unique_ptr<Target>& target : targets_)
        if (auto finished = target->finish(); !finished) return finished;
    // Renames; a failure takes back the targets this call already put in place.
    std::vector<std::string> committed;
    for (const std::unique_ptr<Target>& target : targets_) {
        if (auto moved = target->commit(); !moved) {
            for (const std::string& path : committed) ::unlink(path.c_str());
            return moved;
        }
        if (!target->inPlace()) committed.push_back(target->path());
    }
    targets_.clear();
    return true;
}

bool isSpecialFile(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

Result<bool> writeFilesAtomically(std::span<const OutputFile> outputs) {
    std::vector<std::string> paths;
    for (const OutputFile& output : outputs) paths.push_back(output.path);
    auto streamed = StreamedOutputs::open(paths);
    if (!streamed) return streamed.error();
    // Every regular target to its temporary first; then devices and stdout, which can fail
    // (ENOSPC) but not be undone; then the renames.
    for (const bool inPlace : {false, true})
        for (std::size_t i = 0; i < outputs.size(); ++i)
            if (streamed.value().writesInPlace(i) == inPlace)
                if (auto written = streamed.value().append(i, outputs[i].bytes); !written) return written;
    return streamed.value().commit();
}

Result<bool> writeFileAtomically(const std::string& path, std::string_view bytes) {
    const OutputFile output{path, bytes};
    return writeFilesAtomically(std::span(&output, 1));
}

}  // namespace throng
