// The app's output helpers: timing summaries and the table that prints as text, CSV and JSON.
#include <gtest/gtest.h>

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
