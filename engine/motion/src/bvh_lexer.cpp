#include "bvh_lexer.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace throng::motion::detail {
namespace {

// '\r' is plain whitespace so CRLF, LF and mixed endings all read the same; only '\n' ends a line.
bool isSpaceInLine(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool isBrace(char c) { return c == '{' || c == '}'; }

}  // namespace

void BvhLexer::skipSpaceInLine() {
    while (pos_ < text_.size() && isSpaceInLine(text_[pos_])) ++pos_;
}

void BvhLexer::skipWhitespace() {
    for (;;) {
        skipSpaceInLine();
        if (pos_ < text_.size() && text_[pos_] == '\n') {
            ++pos_;
            ++line_;
            lineStart_ = pos_;
            continue;
        }
        return;
    }
}

Token BvhLexer::nextOnLine() {
    skipSpaceInLine();
    Token token{{}, line_, column()};
    if (pos_ >= text_.size() || text_[pos_] == '\n') return token;
    const std::size_t start = pos_;
    if (isBrace(text_[pos_])) {
        ++pos_;
    } else {
        while (pos_ < text_.size() && !isSpaceInLine(text_[pos_]) && text_[pos_] != '\n' &&
               !isBrace(text_[pos_]))
            ++pos_;
    }
    token.text = text_.substr(start, pos_ - start);
    return token;
}

bool BvhLexer::nextLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    if (pos_ >= text_.size()) return false;
    ++pos_;
    ++line_;
    lineStart_ = pos_;
    return true;
}

Token BvhLexer::next() {
    skipWhitespace();
    return nextOnLine();
}

Token BvhLexer::peek() {
    const std::size_t pos = pos_, lineStart = lineStart_;
    const int line = line_;
    Token token = next();
    pos_ = pos;
    lineStart_ = lineStart;
    line_ = line;
    return token;
}

Token BvhLexer::restOfLine() {
    skipSpaceInLine();
    Token token{{}, line_, column()};
    const std::size_t start = pos_;
    std::size_t end = start;
    while (end < text_.size() && text_[end] != '\n') ++end;
    // A trailing '{' on the same line opens the block; leave it for the caller.
    std::size_t stop = end;
    while (stop > start && isSpaceInLine(text_[stop - 1])) --stop;
    if (stop > start && text_[stop - 1] == '{') {
        --stop;
        while (stop > start && isSpaceInLine(text_[stop - 1])) --stop;
    }
    token.text = text_.substr(start, stop - start);
    pos_ = stop;
    return token;
}

void BvhLexer::skipLine() { nextLine(); }

bool BvhLexer::atEnd() {
    skipWhitespace();
    return pos_ >= text_.size();
}

std::string quoteToken(std::string_view token) {
    if (token.empty()) return "end of file";
    constexpr std::size_t kMaxShown = 24;
    std::string out = "'";
    for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
        const auto byte = static_cast<unsigned char>(token[i]);
        if (byte >= 0x20 && byte < 0x7f) {
            out += static_cast<char>(byte);
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            out += escaped;
        }
    }
    if (token.size() > kMaxShown) out += "...";
    return out + "'";
}

// Says why a number-looking token was refused, so "1e999" doesn't read as a typo.
std::string numberProblem(std::string_view text) {
    std::string_view digits = text;
    if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
    double ignored = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), ignored);
    if (ec == std::errc::result_out_of_range) return " (out of range for a double)";
    if (ec == std::errc() && end == digits.data() + digits.size()) return " (not a finite number)";
    return "";
}

// std::from_chars accepts '5.', '.5', '1E-3' but not a leading '+', and it reads
// "nan"/"inf", which are refused here because they would poison every transform.
std::optional<double> parseBvhNumber(std::string_view text) {
    if (text.empty()) return std::nullopt;
    bool negative = false;
    if (text[0] == '+' || text[0] == '-') {
        negative = text[0] == '-';
        text.remove_prefix(1);
    }
    if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.')) return std::nullopt;
    double value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (end != text.data() + text.size()) return std::nullopt;
    // Underflow ("1e-999") is as good as zero; overflow and nan/inf are not numbers here.
    const bool underflow = ec == std::errc::result_out_of_range &&
                           (text.find("e-") != std::string_view::npos || text.find("E-") != std::string_view::npos);
    if (underflow) return 0.0;
    if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
    return negative ? -value : value;
}

}  // namespace throng::motion::detail
