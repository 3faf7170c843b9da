#include "throng/core/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
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
constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};

struct PendingSlot {
    std::atomic<int> state{0};
    char path[kPathBytes] = {};
};
PendingSlot gPending[kSlots];
struct sigaction gPrevious[kSignals.size()];
std::atomic<bool> gHandlersInstalled{false};

extern "C" void removePendingThenReraise(int signal) {
    const int savedErrno = errno;
    for (PendingSlot& slot : gPending)
        if (slot.state.load() == 2) ::unlink(slot.path);
    for (std::size_t i = 0; i < kSignals.size(); ++i)
        if (kSignals[i] == signal) ::sigaction(signal, &gPrevious[i], nullptr);
    errno = savedErrno;
    ::raise(signal);  // now with the previous disposition: the default ends the process
}

void installHandlers() {
    if (gHandlersInstalled.exchange(true)) return;
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
        if (::sigaction(kSignals[i], nullptr, &gPrevious[i]) != 0) continue;
        if (gPrevious[i].sa_handler == SIG_IGN) continue;  // nohup and friends: keep ignoring it
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

// A temporary beside its target, removed on destruction unless it was moved into place.
class Temporary {
public:
    explicit Temporary(std::string target) : target_(std::move(target)) {}
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;
    ~Temporary() { discard(); }

    Result<bool> write(std::string_view bytes) {
        const std::string pattern = target_ + ".tmp-XXXXXX";
        if (pattern.size() >= kPathBytes) return writeError(target_, "cannot create output file", ENAMETOOLONG);
        int fd = -1;
        {
            const SignalBlock block;
            installHandlers();
            for (std::size_t i = 0; i < kSlots && slot_ == nullptr; ++i) {
                int expected = 0;
                if (gPending[i].state.compare_exchange_strong(expected, 1)) slot_ = &gPending[i];
            }
            if (slot_ == nullptr) return writeError(target_, "cannot create output file", EMFILE);
            std::memcpy(slot_->path, pattern.c_str(), pattern.size() + 1);
            fd = ::mkostemp(slot_->path, O_CLOEXEC);
            if (fd < 0) {
                const int saved = errno;
                release();
                return writeError(target_, "cannot create output file", saved);
            }
            slot_->state.store(2);
        }
        // mkstemp creates 0600; outputs are ordinary files the user and others may read.
        ::fchmod(fd, 0644);
        int error = writeAll(fd, bytes);
        if (error == 0 && ::fsync(fd) != 0) error = errno;
        if (::close(fd) != 0 && error == 0) error = errno;
        if (error != 0) return writeError(target_, "cannot write output file", error);
        return true;
    }

    /// Renames the temporary over the target; afterwards nothing is left to discard.
    Result<bool> commit() {
        const SignalBlock block;
        if (std::rename(slot_->path, target_.c_str()) != 0) return writeError(target_, "cannot move output into place", errno);
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

    std::string target_;
    PendingSlot* slot_ = nullptr;
};

Result<bool> writeInPlace(const std::string& path, std::string_view bytes) {
    if (path == "-") {
        errno = 0;
        if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
            return writeError("-", "cannot write to standard output", errno != 0 ? errno : EIO);
        return true;
    }
    // No O_CREAT, no O_TRUNC: the device or FIFO exists and stays what it is.
    const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return writeError(path, "cannot open output file", errno);
    int error = writeAll(fd, bytes);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) return writeError(path, "cannot write output file", error);
    return true;
}

bool writesInPlace(const std::string& path) { return path == "-" || isSpecialFile(path); }

}  // namespace

bool isSpecialFile(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

Result<bool> writeFilesAtomically(std::span<const OutputFile> outputs) {
    for (const OutputFile& output : outputs)
        if (output.path.empty()) return Error{Error::Kind::BadInput, "the output file name is empty", {}};
    // 1. Every regular target to its temporary.
    std::vector<std::unique_ptr<Temporary>> temporaries(outputs.size());
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (writesInPlace(outputs[i].path)) continue;
        temporaries[i] = std::make_unique<Temporary>(outputs[i].path);
        if (auto written = temporaries[i]->write(outputs[i].bytes); !written) return written;
    }
    // 2. Devices and stdout, which can fail (ENOSPC) but not be undone.
    for (std::size_t i = 0; i < outputs.size(); ++i)
        if (!temporaries[i])
            if (auto written = writeInPlace(outputs[i].path, outputs[i].bytes); !written) return written;
    // 3. Renames; a failure takes back the targets this call already put in place.
    std::vector<std::string> committed;
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (!temporaries[i]) continue;
        if (auto moved = temporaries[i]->commit(); !moved) {
            for (const std::string& path : committed) ::unlink(path.c_str());
            return moved;
        }
        committed.push_back(outputs[i].path);
    }
    return true;
}

Result<bool> writeFileAtomically(const std::string& path, std::string_view bytes) {
    const OutputFile output{path, bytes};
    return writeFilesAtomically(std::span(&output, 1));
}

}  // namespace throng
