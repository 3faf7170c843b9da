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
// Whether a number that from_chars found out of range is too small rather than too large: the
// decimal order of its first significant digit plus its exponent is negative (1e-400 and
// 0.000...1 are; 1 followed by 400 zeros, e-1, is not).
inline bool underflows(std::string_view text) {
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) text.remove_prefix(1);
    const std::size_t e = text.find_first_of("eE");
    long long exponent = 0;
    if (e != std::string_view::npos) {
        std::string_view written = text.substr(e + 1);
        const bool negative = !written.empty() && written.front() == '-';
        if (!written.empty() && (written.front() == '-' || written.front() == '+')) written.remove_prefix(1);
        long long value = 0;
        const auto [end, ec] = std::from_chars(written.data(), written.data() + written.size(), value);
        if (ec == std::errc::result_out_of_range) value = 1LL << 60;  // past any mantissa's length
        exponent = negative ? -value : value;
    }
    const std::string_view mantissa = text.substr(0, e);
    const std::size_t point = mantissa.find('.');
    const std::string_view whole = mantissa.substr(0, point);
    const std::size_t leading = whole.find_first_not_of('0');
    long long order = 0;  // of the first significant digit: 0 for 1.5, -3 for 0.001
    if (leading != std::string_view::npos) {
        order = static_cast<long long>(whole.size() - leading) - 1;
    } else {
        const std::string_view fraction = point == std::string_view::npos ? std::string_view() : mantissa.substr(point + 1);
        const std::size_t first = fraction.find_first_not_of('0');
        if (first == std::string_view::npos) return true;  // all zeros
        order = -static_cast<long long>(first) - 1;
    }
    return order + exponent < 0;
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
