#include "output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <cstdio>
#include <charconv>
#include <cmath>
#include <system_error>

#include "throng/core/atomic_file.h"
#include "throng/core/log.h"

namespace throng::app {
namespace {

bool inText(const TableColumn& column) { return column.use != ColumnUse::DataOnly; }
bool inData(const TableColumn& column) { return column.use != ColumnUse::TextOnly; }

std::string formatCell(const Table::Cell& cell, int precision) {
    if (const auto* text = std::get_if<std::string>(&cell)) return *text;
    if (const auto* whole = std::get_if<std::int64_t>(&cell)) return std::to_string(*whole);
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", precision, std::get<double>(cell));
    return buffer;
}

// Shortest text that reads back to the same double, as CSV and JSON consumers expect.
std::string exactCell(const Table::Cell& cell) {
    if (const auto* number = std::get_if<double>(&cell)) {
        char buffer[64];
        const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, *number);
        return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
    }
    return formatCell(cell, 0);
}

}  // namespace

std::optional<Error> checkOutputPath(const std::string& path, const char* option) {
    if (path == "-") return std::nullopt;
    const auto refuse = [&](const std::string& why) { return Error{Error::Kind::BadInput, std::string(option) + ": " + why, {path, 0, 0}}; };
    std::error_code ec;
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
        return refuse(ec && ec != std::errc::no_such_file_or_directory ? ec.message()
                                                                        : "directory '" + parent.string() + "' does not exist");
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) return refuse(ec.message());
    if (std::filesystem::is_directory(status)) return refuse("is a directory");
    return std::nullopt;
}

std::string nextFreeName(const std::string& prefix, int& counter, const std::string& extension) {
    std::string name;
    do name = prefix + std::to_string(++counter) + extension;
    while (std::filesystem::exists(name));
    return name;
}

bool sameFile(const std::string& a, const std::string& b) {
    if (a == b) return true;
    if (a == "-" || b == "-") return false;
    const auto resolved = [](const std::string& path) {
        std::error_code ec;
        const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
        const std::filesystem::path canonical = ec ? std::filesystem::path(path) : std::filesystem::weakly_canonical(absolute, ec);
        return ec ? std::filesystem::path(path).lexically_normal() : canonical;
    };
    if (resolved(a) == resolved(b)) return true;
    std::error_code ec;
    return std::filesystem::equivalent(a, b, ec) && !ec;  // hard links
}

bool namesPngImage(const std::string& path) {
    if (path == "-" || isSpecialFile(path)) return true;
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".png";
}

Summary summarize(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

int reportError(const Error& error) {
    log::report(error.describe());
    return error.kind == Error::Kind::BadInput ? 2 : 1;
}

int writeOutput(const std::string& path, const std::string& text) {
    auto written = writeFileAtomically(path, text);
    return written ? 0 : reportError(written.error());
}

int writeOutputs(std::span<const OutputFile> outputs) {
    auto written = writeFilesAtomically(outputs);
    return written ? 0 : reportError(written.error());
}

void appendFixed6(std::string& out, double value, char after) {
    const double magnitude = std::fabs(value);
    const double scaled = magnitude * 1e6, whole = std::floor(scaled), fraction = scaled - whole;
    // Below 1e12 the scaled value is within 6.2e-5 of the exact product, so unless it sits
    // near a half (a rounding tie) it rounds to the integer to_chars's exact rounding picks.
    if (!(magnitude < 1e6) || std::fabs(fraction - 0.5) < 1e-3) {
        char text[400];  // room for any double in fixed notation
        const auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, 6);
        out.append(text, ec == std::errc() ? end : text);
        out += after;
        return;
    }
    const auto units = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1U : 0U);
    if (std::signbit(value)) out += '-';
    char text[24];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, units / 1'000'000);
    out.append(text, ec == std::errc() ? end : text);
    char decimals[7] = {'.'};
    for (std::uint64_t rest = units % 1'000'000, digit = 6; digit > 0; --digit, rest /= 10) decimals[digit] = static_cast<char>('0' + rest % 10);
    out.append(decimals, sizeof decimals);
    out += after;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string jsonText(const nlohmann::ordered_json& json, int indent) {
    return json.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

void Table::addRow(std::vector<Cell> cells) {
    if (cells.size() != columns_.size())
        throw ThrongException(Error{Error::Kind::Runtime, "table row has " + std::to_string(cells.size()) + " cells for " +
                                                              std::to_string(columns_.size()) + " columns", {}});
    rows_.push_back(std::move(cells));
}

std::string Table::text() const {
    std::vector<std::vector<std::string>> cells(rows_.size() + 1);
    std::vector<std::size_t> widths;
    for (const TableColumn& column : columns_) {
        if (!inText(column)) continue;
        cells[0].push_back(column.heading.empty() ? column.key : column.heading);
        widths.push_back(cells[0].back().size());
    }
    for (std::size_t r = 0; r < rows_.size(); ++r)
        for (std::size_t c = 0, shown = 0; c < columns_.size(); ++c) {
            if (!inText(columns_[c])) continue;
            cells[r + 1].push_back(formatCell(rows_[r][c], columns_[c].precision));
            widths[shown] = std::max(widths[shown], cells[r + 1].back().size());
            ++shown;
        }
    std::string out;
    for (const std::vector<std::string>& line : cells) {
        for (std::size_t c = 0; c < line.size(); ++c) {
            // The first column (a name) aligns left, numbers align right.
            const std::string padding(widths[c] - line[c].size(), ' ');
            out += (c == 0 ? line[c] + padding : padding + line[c]) + (c + 1 < line.size() ? "  " : "\n");
        }
    }
    return out;
}

std::string Table::csv() const {
    std::string out;
    for (const TableColumn& column : columns_)
        if (inData(column)) out += (out.empty() ? "" : ",") + column.key;
    out += '\n';
    for (const std::vector<Cell>& row : rows_) {
        std::string line;
        for (std::size_t c = 0; c < columns_.size(); ++c)
            if (inData(columns_[c])) line += (line.empty() ? "" : ",") + exactCell(row[c]);
        out += line + '\n';
    }
    return out;
}

nlohmann::ordered_json Table::json() const {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const std::vector<Cell>& row : rows_) {
        nlohmann::ordered_json object;
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            if (!inData(columns_[c])) continue;
            std::visit([&](const auto& value) { object[columns_[c].key] = value; }, row[c]);
        }
        rows.push_back(std::move(object));
    }
    return rows;
}

}  // namespace throng::app
