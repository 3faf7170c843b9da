#pragma once
// Whole numbers from environment variables (the test hooks that lower a device's limits).

#include <cstdint>
#include <optional>

namespace throng {

/// The whole number in environment variable `name`, or nothing when it is unset or empty.
/// Throws ThrongException (BadInput) naming the variable when it is not a whole number from
/// `least` to `most`; `what` says what it counts ("a byte count", "a workgroup count").
[[nodiscard]] std::optional<std::uint64_t> wholeNumberFromEnvironment(const char* name, std::uint64_t least, std::uint64_t most, const char* what);

}  // namespace throng
