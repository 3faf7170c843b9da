#include "throng/core/environment.h"

#include <cerrno>
#include <cstdlib>
#include <string>

#include "throng/core/error.h"

namespace throng {

std::optional<std::uint64_t> wholeNumberFromEnvironment(const char* name, std::uint64_t least, std::uint64_t most, const char* what) {
    const char* value = std::getenv(name);
    if (value == nullptr || value[0] == '\0') return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const unsigned long long number = std::strtoull(value, &end, 10);
    if (errno != 0 || end == value || *end != '\0' || value[0] == '-' || number < least || number > most)
        throw ThrongException(Error{Error::Kind::BadInput,
                                    std::string(name) + ": expected " + what + " from " + std::to_string(least) + " to " +
                                        std::to_string(most) + ", found '" + value + "'",
                                    {}});
    return number;
}

}  // namespace throng
