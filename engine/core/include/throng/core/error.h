#pragma once
// The project's error value and a minimal result type (std::expected is C++23).

#include <cassert>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace throng {

/// Where in a text input an error was found. Lines and columns count from 1;
/// 0 means "not known" (for example an error about the file as a whole).
struct SourceLocation {
    std::string file;  ///< Path as the user gave it; empty for in-memory text.
    int line = 0;      ///< 1-based line, 0 when the error has no line.
    int column = 0;    ///< 1-based column (bytes), 0 when unknown.
};

/// Why an operation failed. `kind` picks the CLI exit code (see DESIGN.md §3).
struct Error {
    enum class Kind {
        BadInput,  ///< Malformed or out-of-range input: exit code 2.
        Runtime,   ///< The machine could not do it (I/O, device): exit code 1.
    };
    Kind kind = Kind::BadInput;
    std::string message;      ///< One sentence: what was expected, what was found.
    SourceLocation location;  ///< Optional file/line/column.

    /// "file:line:column: message", omitting the parts that are unknown.
    [[nodiscard]] std::string describe() const;
};

/// User text quoted in a message, cut to its first `most` bytes (then "..."): a 15 MB field
/// or key must not become a 15 MB error line.
[[nodiscard]] inline std::string excerpt(std::string_view text, std::size_t most = 48) {
    if (text.size() <= most) return std::string(text);
    std::size_t cut = most;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0U) == 0x80U) --cut;  // not inside a UTF-8 character
    return std::string(text.substr(0, cut)) + "...";
}

/// Thrown by code that cannot return a Result (constructors, deep call chains);
/// caught at module boundaries and turned back into an Error.
class ThrongException : public std::runtime_error {
public:
    explicit ThrongException(Error error)
        : std::runtime_error(error.describe()), error_(std::move(error)) {}
    [[nodiscard]] const Error& error() const noexcept { return error_; }

private:
    Error error_;
};

/// Either a value or an Error.
template <typename T>
class Result {
public:
    Result(T value) : state_(std::move(value)) {}           // NOLINT: implicit by design
    Result(Error error) : state_(std::move(error)) {}       // NOLINT: implicit by design

    [[nodiscard]] bool ok() const noexcept { return state_.index() == 0; }
    explicit operator bool() const noexcept { return ok(); }

    [[nodiscard]] T& value() & { assert(ok()); return std::get<0>(state_); }
    [[nodiscard]] const T& value() const& { assert(ok()); return std::get<0>(state_); }
    [[nodiscard]] T&& value() && { assert(ok()); return std::get<0>(std::move(state_)); }
    [[nodiscard]] const Error& error() const { assert(!ok()); return std::get<1>(state_); }

    /// The value, or throws ThrongException carrying the error.
    T& orThrow() & {
        if (!ok()) throw ThrongException(error());
        return value();
    }
    T orThrow() && {
        if (!ok()) throw ThrongException(error());
        return std::get<0>(std::move(state_));
    }

private:
    std::variant<T, Error> state_;
};

}  // namespace throng
