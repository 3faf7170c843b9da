#pragma once
// Text handling for the trajectory reader (trajectory_reading.cpp): lines, fields and numbers,
// each field with its column so errors can point at it.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace throng::crowd::detail {

// One field of a row: its text and its 1-based byte column.
struct Field {
    std::string_view text;
    int column = 1;
};

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

inline std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// Fields split at commas, blanks around each trimmed. A field in double quotes (as R's
// write.csv and spreadsheets write names) is what is between them, commas included; a quote
// it holds is written twice ("") and kept so (no field Throng reads contains one). A quote
// left open runs to the end of the line; text after a closing quote ("1"5) keeps the field as
// written, which no number reads, so the row is refused at its column rather than read as 1.
inline void splitCsv(std::string_view line, std::vector<Field>& fields) {
    fields.clear();
    std::size_t start = 0;
    while (true) {
        std::size_t a = start;
        while (a < line.size() && isBlank(line[a])) ++a;
        const bool quoted = a < line.size() && line[a] == '"';
        std::size_t close = a + 1;  // a quoted field's closing quote: the first one not doubled
        while (quoted && close < line.size() && !(line[close] == '"' && (close + 1 >= line.size() || line[close + 1] != '"')))
            close += line[close] == '"' ? 2 : 1;
        const std::size_t comma = line.find(',', quoted ? std::min(close + 1, line.size()) : a);
        std::size_t b = comma == std::string_view::npos ? line.size() : comma;
        while (b > a && isBlank(line[b - 1])) --b;
        if (quoted && close >= line.size()) {  // left open: the rest of the line
            ++a;
        } else if (quoted && b == close + 1) {  // closed, with nothing after: between the quotes
            ++a;
            b = close;
        }
        fields.push_back({line.substr(a, b - a), static_cast<int>(a) + 1});
        if (comma == std::string_view::npos) return;
        start = comma + 1;
    }
}

inline void splitWhitespace(std::string_view line, std::vector<Field>& fields) {
    fields.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isBlank(line[i])) ++i;
        if (i > start) fields.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
}

// A finite number that is all of `text` (a leading '+' allowed), or nullopt.
// Whether a number that from_chars found out of range is too small rather than too large:
// a negative exponent, or no digit but zeros before the point.
inline bool underflows(std::string_view text) {
    const std::size_t exponent = text.find_first_of("eE");
    if (exponent != std::string_view::npos) return exponent + 1 < text.size() && text[exponent + 1] == '-';
    const std::size_t point = text.find('.');
    return point != std::string_view::npos && text.find_first_of("123456789") > point;
}

inline std::optional<double> parseReal(std::string_view text) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (end != text.data() + text.size()) return std::nullopt;
    // 1e-400 is 0 to a double, as strtod and a spreadsheet read it; 1e400 stays refused.
    if (ec == std::errc::result_out_of_range && underflows(text)) return text.front() == '-' ? -0.0 : 0.0;
    if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// A whole number ("12", or "12.0" as spreadsheets write it) within +-2^53, or nullopt.
inline std::optional<std::int64_t> parseWhole(std::string_view text) {
    std::int64_t value = 0;
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc() && end == text.data() + text.size()) return value;
    const std::optional<double> real = parseReal(text);
    constexpr double kExact = 9007199254740992.0;  // 2^53: every whole double below it is exact
    if (!real || std::abs(*real) > kExact || *real != std::floor(*real)) return std::nullopt;
    return static_cast<std::int64_t>(*real);
}

// The file's lines, numbered from 1, without their line ends.
class Lines {
public:
    explicit Lines(std::string_view text) : text_(text) {}
    bool next(std::string_view& line) {
        if (at_ >= text_.size()) return false;
        const std::size_t end = text_.find('\n', at_);
        const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
        line = text_.substr(at_, stop - at_);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        at_ = stop + 1;
        ++number_;
        return true;
    }
    [[nodiscard]] int number() const { return number_; }

private:
    std::string_view text_;
    std::size_t at_ = 0;
    int number_ = 0;
};

inline bool blankLine(std::string_view line) {
    return std::all_of(line.begin(), line.end(), [](char c) { return isBlank(c); });
}

}  // namespace throng::crowd::detail
