#pragma once
// How every subcommand talks back: errors as one line on stderr with the exit code they map
// to, output files written atomically (or to stdout for "-"), and tables of figures that print
// as aligned text, CSV or JSON from one definition of their columns.

#include <cstdint>
#include <span>
#include <nlohmann/json.hpp>
#include <optional>
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

/// Refuses (BadInput, naming `option` and the path) an output path whose directory doesn't
/// exist or that names a directory, before any expensive work; names the filesystem can't
/// even look up (over-long, a symlink loop) too. "-" (stdout) always passes.
[[nodiscard]] std::optional<Error> checkOutputPath(const std::string& path, const char* option);
/// `prefix` + N + `extension` for the first N after `counter` that names no file in the
/// working directory, with `counter` left at that N: the demo's screenshots and recordings
/// never overwrite one.
[[nodiscard]] std::string nextFreeName(const std::string& prefix, int& counter, const std::string& extension);
/// Whether two output paths name one file: spelled alike, alike once resolved, or hard links.
[[nodiscard]] bool sameFile(const std::string& a, const std::string& b);

/// Appends `value` exactly as std::to_chars writes it in fixed notation with six decimals
/// (so the same bytes under any locale; "-0.000000" for a negative that rounds to zero,
/// "nan", "inf"), then `after`. Several times faster than to_chars for the values CSV rows
/// carry (|value| < 1e6), where it rounds the scaled value itself.
void appendFixed6(std::string& out, double value, char after);
/// `text` as one CSV field (RFC 4180): as it is, or quoted with its quotes doubled when it
/// holds a comma, a quote or a line break. Bytes stay bytes.
[[nodiscard]] std::string csvField(const std::string& text);

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
