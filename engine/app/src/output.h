#pragma once
// How every subcommand talks back: errors as one line on stderr with the exit code they map
// to, output files written atomically (or to stdout for "-"), and tables of figures that print
// as aligned text, CSV or JSON from one definition of their columns.

#include <cstdint>
#include <span>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "throng/core/atomic_file.h"
#include "throng/core/error.h"

namespace throng::app {

/// Prints `error` as one line on stderr; returns the exit code: 2 for bad input, 1 otherwise.
int reportError(const Error& error);

/// Writes `text` to `path` atomically, or to stdout when `path` is "-", or in place to a
/// device (see throng/core/atomic_file.h). Returns the exit code (0, or reportError's).
int writeOutput(const std::string& path, const std::string& text);
/// Writes every output, or (as far as the system allows) none: see writeFilesAtomically.
int writeOutputs(std::span<const OutputFile> outputs);

/// `json` as text, compact or indented by `indent`. Strings that are not valid UTF-8 (a BVH
/// joint name or a path is just bytes) have their invalid bytes replaced by U+FFFD instead
/// of failing the whole output.
[[nodiscard]] std::string jsonText(const nlohmann::ordered_json& json, int indent = -1);

/// Whether PNG bytes may go to `path`: a FILE.png (any case), stdout ("-"), or a device or
/// FIFO that takes whatever it is given (/dev/null). PNG bytes under a .jpg name would lie.
[[nodiscard]] bool namesPngImage(const std::string& path);

/// Median, minimum and maximum of a set of timings.
struct Summary {
    double median = 0.0, min = 0.0, max = 0.0;
};
/// The median of an even count is the mean of the two middle values; all zero when empty.
[[nodiscard]] Summary summarize(std::vector<double> values);

/// Where a column appears.
enum class ColumnUse : std::uint8_t { Everywhere, TextOnly, DataOnly };

struct TableColumn {
    std::string key;       ///< CSV header and JSON member name, e.g. "frame_ms_median".
    std::string heading;   ///< Text table heading, e.g. "frame_ms"; empty means `key`.
    int precision = 3;     ///< Digits after the point for numbers in the text table.
    ColumnUse use = ColumnUse::Everywhere;
};

class Table {
public:
    using Cell = std::variant<std::string, std::int64_t, double>;

    explicit Table(std::vector<TableColumn> columns) : columns_(std::move(columns)) {}
    /// One value per column, in column order.
    void addRow(std::vector<Cell> cells);

    /// Aligned columns with a heading line, for people.
    [[nodiscard]] std::string text() const;
    /// A header line of keys, then one line per row.
    [[nodiscard]] std::string csv() const;
    /// An array of objects, one per row, keyed by column.
    [[nodiscard]] nlohmann::ordered_json json() const;
    [[nodiscard]] bool empty() const { return rows_.empty(); }

private:
    std::vector<TableColumn> columns_;
    std::vector<std::vector<Cell>> rows_;
};

}  // namespace throng::app
