// Command-line parsing is a pure function, so every flag combination and every usage error
// is checked here without running anything.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

#include "throng/app/cli.h"

namespace {

using throng::Error;
using throng::app::BvhBakeCommand;
using throng::app::BvhBenchCommand;
using throng::app::BvhInfoCommand;
using throng::app::Command;
using throng::app::HelpCommand;
using throng::app::parseCommandLine;
using throng::app::VersionCommand;
using throng::motion::PositionChannels;

using Args = std::vector<std::string>;

throng::Result<Command> parse(const Args& args) { return parseCommandLine(args); }

std::string joined(const Args& args) {
    std::string out;
    for (const std::string& a : args) out += (out.empty() ? "" : " ") + a;
    return out;
}

template <typename T>
T parseAs(const Args& args) {
    auto result = parse(args);
    if (!result.ok()) {
        ADD_FAILURE() << "'" << joined(args) << "' failed: " << result.error().describe();
        return T{};
    }
    const T* command = std::get_if<T>(&result.value());
    if (command == nullptr) {
        ADD_FAILURE() << "'" << joined(args) << "' gave the wrong command (index " << result.value().index() << ")";
        return T{};
    }
    return *command;
}

/// Expects a usage error whose message mentions every word in `words` and the --help hint.
void expectUsageError(const Args& args, std::initializer_list<const char*> words) {
    SCOPED_TRACE(joined(args));
    auto result = parse(args);
    ASSERT_FALSE(result.ok()) << "parsed, but should be a usage error";
    const Error& e = result.error();
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    for (const char* word : words) EXPECT_NE(e.message.find(word), std::string::npos) << "'" << word << "' not in: " << e.message;
    EXPECT_NE(e.message.find("--help"), std::string::npos) << e.message;
    EXPECT_EQ(e.location.line, 0);
}

// --- Help and version -------------------------------------------------------------------

TEST(CliParse, NoArgumentsShowsMainHelp) {
    const auto help = parseAs<HelpCommand>({});
    EXPECT_NE(help.text.find("Usage: throng"), std::string::npos);
    EXPECT_NE(help.text.find("bvh info"), std::string::npos);
    EXPECT_NE(help.text.find("bvh bake"), std::string::npos);
    EXPECT_NE(help.text.find("bvh bench"), std::string::npos);
}

TEST(CliParse, MainHelpSpellings) {
    const std::string main = parseAs<HelpCommand>({}).text;
    const std::vector<Args> spellings{{"help"}, {"--help"}, {"-h"}};
    for (const Args& args : spellings) {
        SCOPED_TRACE(joined(args));
        EXPECT_EQ(parseAs<HelpCommand>(args).text, main);
    }
}

TEST(CliParse, EverySubcommandHasItsOwnHelp) {
    const std::string main = parseAs<HelpCommand>({}).text;
    const std::string info = parseAs<HelpCommand>({"bvh", "info", "--help"}).text;
    const std::string bake = parseAs<HelpCommand>({"bvh", "bake", "--help"}).text;
    const std::string bench = parseAs<HelpCommand>({"bvh", "bench", "--help"}).text;
    EXPECT_NE(info.find("Usage: throng bvh info"), std::string::npos) << info;
    EXPECT_NE(info.find("--position-channels"), std::string::npos);
    EXPECT_NE(info.find("--loop"), std::string::npos);
    EXPECT_NE(info.find("--keep-first-frame"), std::string::npos);
    EXPECT_NE(info.find("--units"), std::string::npos);
    EXPECT_NE(bake.find("Usage: throng bvh bake"), std::string::npos) << bake;
    EXPECT_NE(bake.find("--frames"), std::string::npos);
    EXPECT_NE(bake.find("--json"), std::string::npos);
    EXPECT_NE(bench.find("Usage: throng bvh bench"), std::string::npos) << bench;
    EXPECT_NE(bench.find("--repeat"), std::string::npos);
    EXPECT_NE(info, main);
    EXPECT_NE(bake, info);
    EXPECT_NE(bench, bake);

    // -h works too, and --help wins anywhere, even after other options or bad input.
    EXPECT_EQ(parseAs<HelpCommand>({"bvh", "info", "-h"}).text, info);
    EXPECT_EQ(parseAs<HelpCommand>({"bvh", "info", "walk.bvh", "--json", "x", "--help"}).text, info);
    EXPECT_EQ(parseAs<HelpCommand>({"bvh", "bake", "--frames", "x", "--help"}).text, bake);
    EXPECT_EQ(parseAs<HelpCommand>({"bvh", "bench", "--bogus", "-h"}).text, bench);
}

TEST(CliParse, Version) {
    auto result = parse({"--version"});
    ASSERT_TRUE(result.ok());
    EXPECT_TRUE(std::holds_alternative<VersionCommand>(result.value()));
}

// --- bvh info ---------------------------------------------------------------------------

TEST(CliParse, InfoWithJustAFile) {
    const auto info = parseAs<BvhInfoCommand>({"bvh", "info", "walk.bvh"});
    EXPECT_EQ(info.file, "walk.bvh");
    EXPECT_FALSE(info.jsonOut.has_value());
    EXPECT_EQ(info.bake.positionChannels, PositionChannels::Replace);
    EXPECT_FALSE(info.bake.metresPerUnit.has_value());
    EXPECT_FALSE(info.bake.loop.has_value());
    EXPECT_FALSE(info.bake.skipFirstFrame.has_value());
}

TEST(CliParse, InfoWithEveryOption) {
    const auto info = parseAs<BvhInfoCommand>({"bvh", "info", "--json", "out.json", "--position-channels", "add",
                                               "--units", "0.01", "--loop", "10:50", "--keep-first-frame",
                                               "clips/walk.bvh"});
    EXPECT_EQ(info.file, "clips/walk.bvh");
    ASSERT_TRUE(info.jsonOut.has_value());
    EXPECT_EQ(*info.jsonOut, "out.json");
    EXPECT_EQ(info.bake.positionChannels, PositionChannels::Add);
    ASSERT_TRUE(info.bake.metresPerUnit.has_value());
    EXPECT_DOUBLE_EQ(*info.bake.metresPerUnit, 0.01);
    ASSERT_TRUE(info.bake.loop.has_value());
    EXPECT_EQ(info.bake.loop->first, 10);
    EXPECT_EQ(info.bake.loop->last, 50);
    ASSERT_TRUE(info.bake.skipFirstFrame.has_value());
    EXPECT_FALSE(*info.bake.skipFirstFrame);
}

TEST(CliParse, InfoJsonToStdoutAndReplaceMode) {
    const auto info =
        parseAs<BvhInfoCommand>({"bvh", "info", "walk.bvh", "--json", "-", "--position-channels", "replace"});
    ASSERT_TRUE(info.jsonOut.has_value());
    EXPECT_EQ(*info.jsonOut, "-");
    EXPECT_EQ(info.bake.positionChannels, PositionChannels::Replace);
    EXPECT_EQ(parseAs<BvhInfoCommand>({"bvh", "info", "walk.bvh", "--loop", "0:1"}).bake.loop->last, 1);
    EXPECT_DOUBLE_EQ(*parseAs<BvhInfoCommand>({"bvh", "info", "a.bvh", "--units", "1"}).bake.metresPerUnit, 1.0);
}

TEST(CliParse, InfoUsageErrors) {
    expectUsageError({"bvh", "info"}, {"FILE"});
    expectUsageError({"bvh", "info", "--json", "out.json"}, {"FILE"});
    expectUsageError({"bvh", "info", "a.bvh", "b.bvh"}, {"second", "b.bvh"});
    expectUsageError({"bvh", "info", "a.bvh", "--bogus"}, {"unknown option", "--bogus"});
    expectUsageError({"bvh", "info", "a.bvh", "--frames", "all"}, {"unknown option", "--frames"});
    expectUsageError({"bvh", "info", "a.bvh", "--json"}, {"--json", "needs a value"});
    expectUsageError({"bvh", "info", "a.bvh", "--units"}, {"--units", "needs a value"});
    expectUsageError({"bvh", "info", "a.bvh", "--loop"}, {"--loop", "needs a value"});
    expectUsageError({"bvh", "info", "a.bvh", "--position-channels"}, {"--position-channels", "needs a value"});
    expectUsageError({"bvh", "info", "a.bvh", "--position-channels", "both"}, {"--position-channels", "both", "replace", "add"});
    expectUsageError({"bvh", "info", "a.bvh", "--position-channels", "Replace"}, {"--position-channels", "Replace"});
    for (const char* loop : {"5:3", "5:5", "x:3", "5", "5:", ":5", "-1:5", "1:2:3", "1.5:3", ""}) {
        SCOPED_TRACE(loop);
        expectUsageError({"bvh", "info", "a.bvh", "--loop", loop}, {"--loop", "FIRST"});
    }
    for (const char* units : {"0", "-1", "abc", "0.01m", "", "1e9", "nan", "inf"}) {
        SCOPED_TRACE(units);
        expectUsageError({"bvh", "info", "a.bvh", "--units", units}, {"--units"});
    }
}

// --- bvh bake ---------------------------------------------------------------------------

TEST(CliParse, BakeDefaults) {
    const auto bake = parseAs<BvhBakeCommand>({"bvh", "bake", "walk.bvh", "--json", "out.json"});
    EXPECT_EQ(bake.file, "walk.bvh");
    EXPECT_EQ(bake.jsonOut, "out.json");
    EXPECT_FALSE(bake.frames.has_value());
    EXPECT_EQ(bake.positionChannels, PositionChannels::Replace);
}

TEST(CliParse, BakeWithEveryOption) {
    const auto bake = parseAs<BvhBakeCommand>(
        {"bvh", "bake", "--frames", "0,5,17", "--position-channels", "add", "--json", "-", "walk.bvh"});
    EXPECT_EQ(bake.file, "walk.bvh");
    EXPECT_EQ(bake.jsonOut, "-");
    ASSERT_TRUE(bake.frames.has_value());
    EXPECT_EQ(*bake.frames, (std::vector<int>{0, 5, 17}));
    EXPECT_EQ(bake.positionChannels, PositionChannels::Add);

    const auto all = parseAs<BvhBakeCommand>(
        {"bvh", "bake", "walk.bvh", "--json", "o.json", "--frames", "all", "--position-channels", "replace"});
    EXPECT_FALSE(all.frames.has_value());
    EXPECT_EQ(all.positionChannels, PositionChannels::Replace);

    const auto single = parseAs<BvhBakeCommand>({"bvh", "bake", "walk.bvh", "--json", "o.json", "--frames", "3"});
    ASSERT_TRUE(single.frames.has_value());
    EXPECT_EQ(*single.frames, (std::vector<int>{3}));
}

TEST(CliParse, BakeUsageErrors) {
    expectUsageError({"bvh", "bake"}, {"FILE"});
    expectUsageError({"bvh", "bake", "--json", "out.json"}, {"FILE"});
    expectUsageError({"bvh", "bake", "walk.bvh"}, {"--json"});
    expectUsageError({"bvh", "bake", "walk.bvh", "--frames", "all"}, {"--json"});
    expectUsageError({"bvh", "bake", "a.bvh", "b.bvh", "--json", "o"}, {"second", "b.bvh"});
    expectUsageError({"bvh", "bake", "a.bvh", "--json", "o", "--bogus"}, {"unknown option", "--bogus"});
    expectUsageError({"bvh", "bake", "a.bvh", "--json", "o", "--units", "1"}, {"unknown option", "--units"});
    expectUsageError({"bvh", "bake", "a.bvh", "--json"}, {"--json", "needs a value"});
    expectUsageError({"bvh", "bake", "a.bvh", "--json", "o", "--frames"}, {"--frames", "needs a value"});
    expectUsageError({"bvh", "bake", "a.bvh", "--json", "o", "--position-channels"},
                     {"--position-channels", "needs a value"});
    expectUsageError({"bvh", "bake", "a.bvh", "--json", "o", "--position-channels", "mix"},
                     {"--position-channels", "mix", "replace", "add"});
    for (const char* frames : {"1,,2", "-1", "x", "", "1,", ",1", "1;2", "0,-5", "1.5", "ALL", "99999999999", " 1"}) {
        SCOPED_TRACE(frames);
        expectUsageError({"bvh", "bake", "a.bvh", "--json", "o", "--frames", frames}, {"--frames", frames});
    }
}

// --- bvh bench --------------------------------------------------------------------------

TEST(CliParse, BenchDefaultsAndOptions) {
    const auto plain = parseAs<BvhBenchCommand>({"bvh", "bench"});
    EXPECT_TRUE(plain.files.empty());
    EXPECT_EQ(plain.repeat, 15);

    const auto full = parseAs<BvhBenchCommand>({"bvh", "bench", "a.bvh", "--repeat", "3", "b.bvh"});
    EXPECT_EQ(full.files, (std::vector<std::string>{"a.bvh", "b.bvh"}));
    EXPECT_EQ(full.repeat, 3);
    EXPECT_EQ(parseAs<BvhBenchCommand>({"bvh", "bench", "--repeat", "1"}).repeat, 1);
    EXPECT_EQ(parseAs<BvhBenchCommand>({"bvh", "bench", "--repeat", "100000"}).repeat, 100000);
}

TEST(CliParse, BenchUsageErrors) {
    expectUsageError({"bvh", "bench", "--repeat"}, {"--repeat", "needs a value"});
    expectUsageError({"bvh", "bench", "--bogus"}, {"unknown option", "--bogus"});
    for (const char* repeat : {"0", "-3", "x", "", "2.5", "100001", "99999999999"}) {
        SCOPED_TRACE(repeat);
        expectUsageError({"bvh", "bench", "--repeat", repeat}, {"--repeat"});
    }
}

// --- Commands ---------------------------------------------------------------------------

TEST(CliParse, UnknownCommandsAndSubcommands) {
    expectUsageError({"frobnicate"}, {"unknown command", "frobnicate"});
    expectUsageError({"--bogus"}, {"unknown command", "--bogus"});
    expectUsageError({"bvh"}, {"subcommand"});
    expectUsageError({"bvh", "frob"}, {"unknown", "frob"});
    expectUsageError({"BVH", "info", "a.bvh"}, {"unknown command", "BVH"});
}

}  // namespace
