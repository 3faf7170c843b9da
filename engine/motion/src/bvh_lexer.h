#pragma once
// Whitespace-separated tokens with their line and column; '{' and '}' are always tokens of
// their own. Private to the parser.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace throng::motion::detail {

struct Token {
    std::string_view text;  ///< Empty at end of input.
    int line = 1;
    int column = 1;
    [[nodiscard]] bool atEnd() const { return text.empty(); }
};

class BvhLexer {
public:
    explicit BvhLexer(std::string_view text) : text_(text) {}

    /// Next token, advancing past it.
    Token next();
    /// Next token without consuming it.
    Token peek();
    /// The rest of the current line after the last token, trimmed (used for joint names).
    Token restOfLine();
    /// Skips to the start of the next line (after the last token's line ends).
    void skipLine();
    /// True when only whitespace remains.
    bool atEnd();

    [[nodiscard]] std::size_t offset() const { return pos_; }
    [[nodiscard]] std::size_t remainingBytes() const { return text_.size() - pos_; }
    [[nodiscard]] int line() const { return line_; }
    [[nodiscard]] int column() const { return static_cast<int>(pos_ - lineStart_) + 1; }
    [[nodiscard]] std::string_view text() const { return text_; }

    /// Reads the tokens of the current line only (stops at '\n'); for motion rows.
    /// Returns an empty token at end of line without consuming the newline.
    Token nextOnLine();
    /// Consumes the newline that ends the current line; false at end of input.
    bool nextLine();

private:
    void skipSpaceInLine();
    void skipWhitespace();

    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t lineStart_ = 0;
    int line_ = 1;
};

/// Printable rendering of a token for error messages: quoted, shortened, escaped.
std::string quoteToken(std::string_view token);

/// The finite number that is all of `text` ('+1', '.5', '5.', '1E-3'; underflow reads as 0),
/// or nullopt: NaN, infinity and overflow are not numbers here.
std::optional<double> parseBvhNumber(std::string_view text);

/// Why a number-looking token was refused, e.g. " (out of range for a double)", or "".
std::string numberProblem(std::string_view text);

}  // namespace throng::motion::detail
