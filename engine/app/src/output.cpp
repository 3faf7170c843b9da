#include "output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <cstdio>
#include <charconv>

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
