#include "throng/core/input_file.h"

#include <filesystem>
#include <fstream>
#include <system_error>

namespace throng {

Result<std::string> readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what) {
    const auto fail = [&](const std::string& why) { return Error{Error::Kind::BadInput, "cannot open " + what + ": " + why, {path, 0, 0}}; };
    // A symlink loop or an over-long name shows up here as an error code, never an exception.
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) return fail(ec.message());
    if (!std::filesystem::exists(status)) return fail("no such file");
    if (std::filesystem::is_directory(status)) return fail("it is a directory");
    if (!std::filesystem::is_regular_file(status)) return fail("not a regular file (a pipe, socket or device)");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return fail(ec.message());
    if (size > maxBytes)
        return fail("it is " + std::to_string(size) + " bytes, over the " + std::to_string(maxBytes) + "-byte limit");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail("permission denied or unreadable");
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.gcount() != static_cast<std::streamsize>(size)) return fail("read failed");
    return text;
}

}  // namespace throng
