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
    // The checks are made on the opened descriptor, not on the name, so a file swapped for a
    // FIFO between a check and the open can't block us. O_NONBLOCK makes opening a FIFO return
    // at once (a read from /dev/zero or a pipe never ends: they are refused before reading).
    FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
    if (file.fd < 0) return fail(openProblem(errno));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0) return fail(std::strerror(errno));
    if (S_ISDIR(info.st_mode)) return fail("it is a directory");
    if (!S_ISREG(info.st_mode)) return fail("not a regular file (a pipe, socket or device)");
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
