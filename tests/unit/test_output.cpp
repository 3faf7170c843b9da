// The app's output helpers: timing summaries and the table that prints as text, CSV and JSON.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "output.h"

using throng::app::ColumnUse;
using throng::app::summarize;
using throng::app::Table;

TEST(Summary, OddCountTakesTheMiddleValue) {
    const auto s = summarize({5.0, 1.0, 3.0});
    EXPECT_DOUBLE_EQ(s.median, 3.0);
    EXPECT_DOUBLE_EQ(s.min, 1.0);
    EXPECT_DOUBLE_EQ(s.max, 5.0);
}

TEST(Summary, EvenCountAveragesTheTwoMiddleValues) {
    EXPECT_DOUBLE_EQ(summarize({4.0, 1.0, 2.0, 10.0}).median, 3.0);
    EXPECT_DOUBLE_EQ(summarize({7.0, 8.0}).median, 7.5);
}

TEST(Summary, EmptyIsZero) {
    const auto s = summarize({});
    EXPECT_EQ(s.median, 0.0);
    EXPECT_EQ(s.min, 0.0);
    EXPECT_EQ(s.max, 0.0);
}

namespace {
Table sampleTable() {
    Table table({{"mode", "", 0}, {"characters", "", 0}, {"frame_ms_median", "frame_ms", 2}, {"note", "", 0, ColumnUse::TextOnly},
                 {"bytes", "", 0, ColumnUse::DataOnly}});
    table.addRow({std::string("fast"), std::int64_t{2000}, 58.4375, std::string("ok"), std::int64_t{1768}});
    table.addRow({std::string("compute"), std::int64_t{250}, 0.1, std::string("slow"), std::int64_t{1520}});
    return table;
}
}  // namespace

TEST(Table, TextAlignsColumnsAndLeavesDataOnlyColumnsOut) {
    const std::string text = sampleTable().text();
    EXPECT_EQ(text,
              "mode     characters  frame_ms  note\n"
              "fast           2000     58.44    ok\n"
              "compute         250      0.10  slow\n");
}

TEST(Table, CsvHasKeysAndExactNumbersAndLeavesTextOnlyColumnsOut) {
    EXPECT_EQ(sampleTable().csv(),
              "mode,characters,frame_ms_median,bytes\n"
              "fast,2000,58.4375,1768\n"
              "compute,250,0.1,1520\n");
}

TEST(Table, JsonRowsAreObjectsKeyedByColumn) {
    const auto json = sampleTable().json();
    ASSERT_EQ(json.size(), 2U);
    EXPECT_EQ(json[0]["mode"], "fast");
    EXPECT_EQ(json[0]["characters"], 2000);
    EXPECT_DOUBLE_EQ(json[1]["frame_ms_median"].get<double>(), 0.1);
    EXPECT_EQ(json[1]["bytes"], 1520);
    EXPECT_FALSE(json[0].contains("note"));
}

TEST(Table, RowWithTheWrongCellCountIsRefused) {
    Table table({{"a", "", 0}, {"b", "", 0}});
    EXPECT_THROW(table.addRow({std::int64_t{1}}), throng::ThrongException);
}

// CSV numbers (throng simulate): byte for byte what std::to_chars writes with six decimals,
// including rounding ties, values near them, negatives that round to zero and non-finite ones.
namespace {
std::string toChars6(double value) {
    char text[400];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, 6);
    return ec == std::errc() ? std::string(text, end) : std::string("?");
}
std::string fixed6(double value) {
    std::string out;
    throng::app::appendFixed6(out, value, ';');
    return out;
}
}  // namespace

TEST(CsvNumbers, SixDecimalsExactlyAsToChars) {
    std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0.5, 1e-7, -1e-7, 4e-7, 5e-7, 6e-7, -4e-7, 0.0000005, 1.0 / 128, 3.0 / 128,
                               -5.0 / 128, 0.1234565, 1.0000005, 999999.9999995, 999999.999999, 1e6, -1e6, 123456.7890125,
                               1e7, 1e12, 1e300, -1e300, std::nextafter(1e6, 0.0), std::numeric_limits<double>::denorm_min(),
                               std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()};
    // Every magnitude, both signs, and values one ulp either side of a tie k + 0.5 (in millionths).
    std::uint64_t state = 12345;
    for (int i = 0; i < 200000; ++i) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const double unit = static_cast<double>(state >> 11) / 9007199254740992.0;
        const double magnitude = std::pow(10.0, -9.0 + 17.0 * unit);
        values.push_back((state & 1) != 0 ? magnitude : -magnitude);
        const double tie = (std::floor(unit * 1e9) + 0.5) / 1e6;
        values.push_back(tie);
        values.push_back(std::nextafter(tie, 0.0));
        values.push_back(std::nextafter(tie, 1e9));
    }
    for (const double value : values) ASSERT_EQ(fixed6(value), toChars6(value) + ";") << value;
    EXPECT_EQ(fixed6(-1e-7), "-0.000000;");
    EXPECT_EQ(fixed6(1.0 / 128), "0.007812;");  // an exact tie rounds to even, as to_chars does
    EXPECT_EQ(fixed6(2.5), "2.500000;");
}

TEST(CsvNumbers, FieldsAreQuotedOnlyWhenTheyMustBe) {
    EXPECT_EQ(throng::app::csvField("LeftFoot"), "LeftFoot");
    EXPECT_EQ(throng::app::csvField("mixamorig:Hips"), "mixamorig:Hips");
    EXPECT_EQ(throng::app::csvField("a,b"), "\"a,b\"");
    EXPECT_EQ(throng::app::csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(throng::app::csvField("two\nlines"), "\"two\nlines\"");
    EXPECT_EQ(throng::app::csvField(""), "");
}
