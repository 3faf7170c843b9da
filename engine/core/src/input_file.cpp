#include "throng/core/input_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace throng {
namespace {

// Closes the descriptor however the read ends.
struct FileDescriptor {
    int fd = -1;
    ~FileDescriptor() {
        if (fd >= 0) ::close(fd);
    }
};

std::string openProblem(int error) {
    switch (error) {
        case ENOENT: return "no such file";
        case EACCES: return "permission denied";
        case EISDIR: return "it is a directory";
        default: return std::strerror(error);  // ELOOP, ENAMETOOLONG, ENOTDIR, ...
    }
}

}  // namespace

Result<std::string> readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
    const auto fail = [&](const std::string& why) { return Error{Error::Kind::BadInput, "cannot open " + what + ": " + why, {path, 0, 0}}; };
    if (path.empty()) return fail("the file name is empty");
    // A read from /dev/zero or a pipe never ends: anything but a regular file is refused, by
    // name first (so a device is never even opened), then on the opened descriptor, so a file
    // swapped for a FIFO in between can't block us (O_NONBLOCK makes opening one return at once).
    const auto kind = [](const struct stat& info) {
        return S_ISDIR(info.st_mode) ? "it is a directory" : S_ISREG(info.st_mode) ? "" : "not a regular file (a pipe, socket or device)";
    };
    struct stat named {};
    if (::stat(path.c_str(), &named) == 0 && *kind(named) != '\0') return fail(kind(named));
    FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
    if (file.fd < 0) return fail(openProblem(errno));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0) return fail(std::strerror(errno));
    if (*kind(info) != '\0') return fail(kind(info));
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (size > maxBytes)
        return fail("it is " + std::to_string(size) + " bytes, over the " + std::to_string(maxBytes) + "-byte limit");
    // Read what fstat promised; a file that grows meanwhile is read up to that size.
    std::string text(static_cast<std::size_t>(size), '\0');
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::read(file.fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return fail(std::string("read failed: ") + std::strerror(errno));
        if (n == 0) return fail("the file shrank while it was read");
        done += static_cast<std::size_t>(n);
    }
    return text;
}

}  // namespace throng
