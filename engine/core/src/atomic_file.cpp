#include "throng/core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace throng {

Result<bool> writeFileAtomically(const std::string& path, std::string_view bytes) {
    // mkstemp in the target's directory keeps the final rename on one filesystem, so it is atomic.
    std::string temp = path + ".tmp-XXXXXX";
    const int fd = mkstemp(temp.data());
    if (fd < 0)
        return Error{Error::Kind::Runtime, std::string("cannot create output file: ") + std::strerror(errno), {path, 0, 0}};
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int saved = errno;
            ::close(fd);
            std::remove(temp.c_str());
            return Error{Error::Kind::Runtime, std::string("cannot write output file: ") + std::strerror(saved), {path, 0, 0}};
        }
        written += static_cast<std::size_t>(n);
    }
    // mkstemp creates 0600; outputs are ordinary files the user and others may read.
    ::fchmod(fd, 0644);
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const int saved = errno;
        std::remove(temp.c_str());
        return Error{Error::Kind::Runtime, std::string("cannot flush output file: ") + std::strerror(saved), {path, 0, 0}};
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        const int saved = errno;
        std::remove(temp.c_str());
        return Error{Error::Kind::Runtime, std::string("cannot move output into place: ") + std::strerror(saved), {path, 0, 0}};
    }
    return true;
}

}  // namespace throng
