#include "bvh_lexer.h"

#include <cstdio>

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

}  // namespace throng::motion::detail
