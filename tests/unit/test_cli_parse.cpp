// Command-line parsing is a pure function, so every flag combination and every usage error
// is checked here without running anything.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "throng/app/cli.h"

namespace {

using throng::Error;
using throng::app::BvhBakeCommand;
using throng::app::BvhBenchCommand;
using throng::app::BenchCommand;
using throng::app::BvhInfoCommand;
using throng::app::Command;
using throng::app::DemoCommand;
using throng::app::DevicesCommand;
using throng::app::HelpCommand;
using throng::app::parseCommandLine;
using throng::app::RenderCommand;
using throng::app::VersionCommand;
using throng::motion::PositionChannels;
using throng::render::RenderPath;
using throng::render::Body;

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

// --- Help per command ------------------------------------------------------------------

bool mentions(const std::string& text, const std::string& word) { return text.find(word) != std::string::npos; }

TEST(CliParse, HelpCommandShowsThatCommandsHelp) {
    const std::string main = parseAs<HelpCommand>({}).text;
    const std::string render = parseAs<HelpCommand>({"help", "render"}).text;
    EXPECT_EQ(render, parseAs<HelpCommand>({"render", "--help"}).text);
    EXPECT_EQ(render, parseAs<HelpCommand>({"render", "-h"}).text);
    EXPECT_TRUE(mentions(render, "Usage: throng render")) << render;
    for (const char* option : {"--out", "-o,", "--characters", "-n,", "--width", "-W,", "--height", "-H,", "--path", "--scene"})
        EXPECT_TRUE(mentions(render, option)) << option << " not in:\n" << render;
    EXPECT_FALSE(mentions(render, "--screenshot"));
    EXPECT_NE(render, main);

    const std::string info = parseAs<HelpCommand>({"help", "bvh", "info"}).text;
    EXPECT_EQ(info, parseAs<HelpCommand>({"bvh", "info", "--help"}).text);
    EXPECT_TRUE(mentions(info, "Usage: throng bvh info"));
    EXPECT_TRUE(mentions(info, "--position-channels"));
    EXPECT_FALSE(mentions(info, "--out"));

    // `throng bvh --help` is bvh's own help, listing its commands.
    const std::string bvh = parseAs<HelpCommand>({"bvh", "--help"}).text;
    EXPECT_EQ(bvh, parseAs<HelpCommand>({"bvh", "-h"}).text);
    EXPECT_EQ(bvh, parseAs<HelpCommand>({"help", "bvh"}).text);
    EXPECT_TRUE(mentions(bvh, "Usage: throng bvh")) << bvh;
    for (const char* command : {"info", "bake", "bench"}) EXPECT_TRUE(mentions(bvh, command)) << command;
    EXPECT_NE(bvh, main);

    EXPECT_EQ(parseAs<HelpCommand>({"help"}).text, main);
    expectUsageError({"help", "frob"}, {"unknown command", "frob"});
    expectUsageError({"help", "bvh", "frob"}, {"unknown command", "bvh frob"});
}

TEST(CliParse, EveryCommandHelpListsItsOwnOptionsAndDefaults) {
    const std::string demo = parseAs<HelpCommand>({"demo", "--help"}).text;
    EXPECT_TRUE(mentions(demo, "Usage: throng demo"));
    for (const char* option : {"--screenshot", "--frames", "--no-vsync", "--script-resize", "--characters", "--path"})
        EXPECT_TRUE(mentions(demo, option)) << option;
    const std::string bench = parseAs<HelpCommand>({"bench", "-h"}).text;
    EXPECT_TRUE(mentions(bench, "Usage: throng bench"));
    for (const char* option : {"--sim-only", "--modes", "--warmup", "--csv", "-n,", "-W,", "-H,"})
        EXPECT_TRUE(mentions(bench, option)) << option;
    EXPECT_TRUE(mentions(parseAs<HelpCommand>({"devices", "--help"}).text, "Usage: throng devices"));
    EXPECT_TRUE(mentions(parseAs<HelpCommand>({"help", "bvh", "bench"}).text, "--repeat"));

    // Defaults come from the command structs, so they can't drift from what parsing does.
    const std::string render = parseAs<HelpCommand>({"help", "render"}).text;
    EXPECT_TRUE(mentions(render, "(default 2000)")) << render;
    EXPECT_TRUE(mentions(render, "(default 1280)"));
    // The path's default depends on the body and the device (app::emplaceOffscreen): the help
    // states the rule instead of one name.
    for (const std::string* help : {&render, &demo}) {
        EXPECT_TRUE(mentions(*help, "for skin and auto bodies, visibility on a CPU device")) << *help;
        EXPECT_TRUE(mentions(*help, "for bones, fast; for spheres, compute. In the demo")) << *help;
    }
    EXPECT_TRUE(mentions(parseAs<HelpCommand>({"help", "bvh", "bench"}).text, "(default 15)"));
}

TEST(CliParse, HelpWinsOverBadInputInEveryCommand) {
    const std::string render = parseAs<HelpCommand>({"render", "--help"}).text;
    EXPECT_EQ(parseAs<HelpCommand>({"render", "--characters", "0", "--bogus", "--help"}).text, render);
    EXPECT_EQ(parseAs<HelpCommand>({"render", "--scene", "s.json", "-n", "5", "-h"}).text, render);
    EXPECT_EQ(parseAs<HelpCommand>({"bench", "--modes", "warp", "--help"}).text, parseAs<HelpCommand>({"bench", "--help"}).text);
    EXPECT_EQ(parseAs<HelpCommand>({"demo", "--screenshot", "x.png", "-h"}).text, parseAs<HelpCommand>({"demo", "-h"}).text);
}

// --- Usage errors name the command's own help -------------------------------------------

TEST(CliParse, UsageErrorsNameTheCommandsHelp) {
    const auto hint = [](const Args& args) {
        auto result = parse(args);
        return result.ok() ? std::string("parsed") : result.error().message;
    };
    EXPECT_TRUE(mentions(hint({"render", "--characters", "0", "--out", "x.png"}), "(see 'throng render --help')"));
    EXPECT_TRUE(mentions(hint({"render", "--bogus"}), "(see 'throng render --help')"));
    EXPECT_TRUE(mentions(hint({"bvh", "info", "a.bvh", "--bogus"}), "(see 'throng bvh info --help')"));
    EXPECT_TRUE(mentions(hint({"bvh", "bake", "a.bvh"}), "(see 'throng bvh bake --help')"));
    EXPECT_TRUE(mentions(hint({"bvh", "frob"}), "(see 'throng bvh --help')"));
    EXPECT_TRUE(mentions(hint({"demo", "--frames", "0"}), "(see 'throng demo --help')"));
    EXPECT_TRUE(mentions(hint({"bench", "--modes", "warp"}), "(see 'throng bench --help')"));
    EXPECT_TRUE(mentions(hint({"frobnicate"}), "(see 'throng --help')"));
    for (const Args& args : {Args{"render", "--bogus"}, Args{"bvh", "info"}, Args{"bench", "-n", "0"}})
        EXPECT_EQ(hint(args).find('\n'), std::string::npos) << "one line: " << hint(args);
}

// --- render, demo, bench ----------------------------------------------------------------

TEST(CliParse, RenderDefaults) {
    const auto render = parseAs<RenderCommand>({"render", "--out", "x.png"});
    EXPECT_EQ(render.out, "x.png");
    EXPECT_EQ(render.crowd.characters, 2000);
    EXPECT_EQ(render.crowd.width, 1280U);
    EXPECT_EQ(render.crowd.height, 720U);
    // auto bodies, drawn by the fast path, seen from the street.
    EXPECT_EQ(render.crowd.body, throng::render::Body::Auto);
    EXPECT_EQ(render.crowd.path, RenderPath::Fast);
    EXPECT_EQ(render.crowd.view, throng::app::DefaultView::Street);
    EXPECT_EQ(render.crowd.msaa, 4U);
    EXPECT_FALSE(render.crowd.seed.has_value());
    EXPECT_TRUE(render.crowd.clips.empty());
}

TEST(CliParse, SphereOnlyChoicesKeepThePapersSpheresWithoutBody) {
    // Scripts written before auto became the default: another path, or a joint dump.
    const auto compute = parseAs<RenderCommand>({"render", "--out", "x.png", "--path", "compute"});
    EXPECT_EQ(compute.crowd.body, throng::render::Body::Spheres);
    EXPECT_EQ(compute.crowd.path, RenderPath::Compute);
    const auto dump = parseAs<RenderCommand>({"render", "--out", "x.png", "--dump-instances", "i.json"});
    EXPECT_EQ(dump.crowd.body, throng::render::Body::Spheres);
    const auto overview = parseAs<RenderCommand>({"render", "--out", "x.png", "--view", "overview"});
    EXPECT_EQ(overview.crowd.view, throng::app::DefaultView::Overview);
    EXPECT_EQ(overview.crowd.body, throng::render::Body::Auto);
}

TEST(CliParse, NameEqualsValueEverywhere) {
    const auto render = parseAs<RenderCommand>(
        {"render", "--out=x.png", "--characters=5", "--width=320", "--height=240", "--time=1.5", "--path=fast",
         "--mode=goals", "--area=10x20", "--seed=7", "--msaa=2", "--camera=1,2,3,0,0,0,50", "--lod-pixels=0",
         "--threads=2", "--device=llvm", "--bvh=a.bvh", "--bvh=b.bvh", "--dump-instances=i.json"});
    EXPECT_EQ(render.out, "x.png");
    EXPECT_EQ(render.crowd.characters, 5);
    EXPECT_EQ(render.crowd.width, 320U);
    EXPECT_EQ(render.crowd.height, 240U);
    EXPECT_DOUBLE_EQ(render.crowd.time, 1.5);
    EXPECT_EQ(render.crowd.path, RenderPath::Fast);
    EXPECT_EQ(render.crowd.mode, throng::crowd::Mode::Goals);
    ASSERT_TRUE(render.crowd.area.has_value());
    EXPECT_FLOAT_EQ(render.crowd.area->y, 20.0F);
    EXPECT_EQ(render.crowd.seed, std::optional<std::uint64_t>(7));
    EXPECT_EQ(render.crowd.msaa, 2U);
    ASSERT_TRUE(render.crowd.camera.has_value());
    EXPECT_FLOAT_EQ(render.crowd.camera->verticalFovDegrees, 50.0F);
    EXPECT_FLOAT_EQ(render.crowd.lodPixels, 0.0F);
    EXPECT_EQ(render.crowd.threads, 2U);
    EXPECT_EQ(render.crowd.device, "llvm");
    ASSERT_EQ(render.crowd.clips.size(), 2U);
    EXPECT_EQ(render.crowd.clips[0].path, "a.bvh");
    EXPECT_EQ(render.crowd.clips[1].path, "b.bvh");
    EXPECT_EQ(render.dumpInstances, std::optional<std::string>("i.json"));

    const auto info = parseAs<BvhInfoCommand>(
        {"bvh", "info", "a.bvh", "--json=-", "--units=0.01", "--loop=1:5", "--position-channels=add"});
    EXPECT_EQ(info.jsonOut, std::optional<std::string>("-"));
    EXPECT_DOUBLE_EQ(*info.bake.metresPerUnit, 0.01);
    EXPECT_EQ(info.bake.loop->last, 5);
    EXPECT_EQ(info.bake.positionChannels, PositionChannels::Add);
    const auto bake = parseAs<BvhBakeCommand>({"bvh", "bake", "a.bvh", "--json=o.json", "--frames=0,5"});
    EXPECT_EQ(bake.jsonOut, "o.json");
    EXPECT_EQ(*bake.frames, (std::vector<int>{0, 5}));
    EXPECT_EQ(parseAs<BvhBenchCommand>({"bvh", "bench", "--repeat=3"}).repeat, 3);

    const auto demo = parseAs<DemoCommand>({"demo", "--frames=10", "--screenshot=s.png", "--path=paper"});
    EXPECT_EQ(demo.frames, 10);
    EXPECT_EQ(demo.screenshot, std::optional<std::string>("s.png"));
    EXPECT_EQ(demo.crowd.path, RenderPath::Paper);
    const auto bench = parseAs<BenchCommand>({"bench", "--characters=10,20", "--modes=fast,cpu", "--frames=2", "--warmup=0",
                                              "--csv=-", "--json=b.json"});
    EXPECT_EQ(bench.characters, (std::vector<int>{10, 20}));
    EXPECT_EQ(bench.paths, (std::vector<RenderPath>{RenderPath::Fast, RenderPath::Cpu}));
    EXPECT_EQ(bench.frames, 2);
    EXPECT_EQ(bench.warmup, 0);
    EXPECT_EQ(bench.csv, std::optional<std::string>("-"));
    EXPECT_EQ(bench.json, std::optional<std::string>("b.json"));
}

TEST(CliParse, ShortForms) {
    const auto render = parseAs<RenderCommand>({"render", "-o", "x.png", "-n", "12", "-W", "320", "-H", "200"});
    EXPECT_EQ(render.out, "x.png");
    EXPECT_EQ(render.crowd.characters, 12);
    EXPECT_EQ(render.crowd.width, 320U);
    EXPECT_EQ(render.crowd.height, 200U);
    const auto demo = parseAs<DemoCommand>({"demo", "-n", "3", "-W", "640", "-H", "480"});
    EXPECT_EQ(demo.crowd.characters, 3);
    EXPECT_EQ(demo.crowd.width, 640U);
    EXPECT_EQ(demo.crowd.height, 480U);
    const auto bench = parseAs<BenchCommand>({"bench", "-n", "10,20", "-W", "64", "-H", "48"});
    EXPECT_EQ(bench.characters, (std::vector<int>{10, 20}));
    EXPECT_EQ(bench.width, 64U);
    EXPECT_EQ(bench.height, 48U);
    // Short options also take their value attached.
    EXPECT_EQ(parseAs<RenderCommand>({"render", "-ox.png", "-n7"}).crowd.characters, 7);
    // The short forms keep the long forms' checks and messages.
    expectUsageError({"render", "-o", "x.png", "-n", "0"}, {"--characters takes a count from 1"});
    expectUsageError({"render", "-o", "x.png", "-H", "8"}, {"--height takes pixels from 16"});
    expectUsageError({"bench", "-W", "100000"}, {"--width takes pixels from 16 to 8192"});
}

TEST(CliParse, RenderPathDefaults) {
    EXPECT_EQ(parseAs<DemoCommand>({"demo"}).crowd.path, RenderPath::Fast);
    EXPECT_EQ(parseAs<DemoCommand>({"demo", "--path", "compute"}).crowd.path, RenderPath::Compute);
    // The demo may pick the path for the device (the visibility path on a CPU) only when none is given.
    EXPECT_TRUE(parseAs<DemoCommand>({"demo"}).tunePath);
    EXPECT_FALSE(parseAs<DemoCommand>({"demo", "--path", "fast"}).tunePath);
    EXPECT_EQ(parseAs<RenderCommand>({"render", "-o", "x.png", "--path", "cpu"}).crowd.path, RenderPath::Cpu);
    expectUsageError({"demo", "--path", "Fast"}, {"--path takes paper, cpu, compute, fast or visibility", "Fast"});
}

TEST(CliParse, BenchModes) {
    // Bare: the default path and body (render's) at the sizes #14 states its targets for.
    const auto render = parseAs<BenchCommand>({"bench"});
    EXPECT_EQ(render.paths, (std::vector<RenderPath>{RenderPath::Fast}));
    EXPECT_EQ(render.bodies, (std::vector<Body>{Body::Auto}));
    EXPECT_TRUE(render.modes.empty());
    EXPECT_EQ(render.characters, (std::vector<int>{2000, 10000, 100000}));
    EXPECT_EQ(render.frames, 20);
    EXPECT_EQ(render.warmup, 3);
    // --modes all: the comparison of every path, with the paper's spheres, at sizes all can draw.
    const auto all = parseAs<BenchCommand>({"bench", "--modes", "all"});
    EXPECT_EQ(all.paths, (std::vector<RenderPath>{RenderPath::Paper, RenderPath::Cpu, RenderPath::Compute, RenderPath::Fast,
                                                  RenderPath::Visibility}));
    EXPECT_EQ(all.bodies, (std::vector<Body>{Body::Spheres}));
    EXPECT_EQ(all.characters, (std::vector<int>{250, 500, 1000, 2000, 4000, 8000}));
    // Any --modes keeps the sphere comparison's defaults; --body and -n still choose.
    EXPECT_EQ(parseAs<BenchCommand>({"bench", "--modes", "fast"}).bodies, (std::vector<Body>{Body::Spheres}));
    const auto chosen = parseAs<BenchCommand>({"bench", "--body", "bones", "-n", "7"});
    EXPECT_EQ(chosen.paths, (std::vector<RenderPath>{RenderPath::Fast}));
    EXPECT_EQ(chosen.bodies, (std::vector<Body>{Body::Bones}));
    EXPECT_EQ(chosen.characters, (std::vector<int>{7}));
    EXPECT_EQ(parseAs<BenchCommand>({"bench", "--sim-only", "--modes", "all"}).modes, (std::vector<std::string>{"group", "goals", "avoid"}));
    const auto sim = parseAs<BenchCommand>({"bench", "--sim-only"});
    EXPECT_TRUE(sim.paths.empty());
    EXPECT_EQ(sim.modes, (std::vector<std::string>{"group", "goals", "avoid"}));
    EXPECT_EQ(sim.characters, (std::vector<int>{1000, 10000, 100000}));
    EXPECT_EQ(sim.frames, 30);
    EXPECT_EQ(sim.warmup, 10);
    // --modes means locomotion modes with --sim-only, wherever --sim-only stands.
    EXPECT_EQ(parseAs<BenchCommand>({"bench", "--modes", "avoid", "--sim-only"}).modes, (std::vector<std::string>{"avoid"}));
    expectUsageError({"bench", "--modes", "warp"}, {"--modes takes paper, cpu, compute, fast or visibility", "warp"});
    expectUsageError({"bench", "--modes", "fast,,cpu"}, {"--modes takes"});
    expectUsageError({"bench", "--sim-only", "--modes", "fast"}, {"--modes takes group, goals, avoid (or all) with --sim-only", "fast"});
}

TEST(CliParse, ConflictsAndMissingPartners) {
    for (const char* shape : {"--bvh", "--characters", "-n", "--mode", "--area"}) {
        SCOPED_TRACE(shape);
        const char* value = std::string(shape) == "--mode" ? "goals" : std::string(shape) == "--area" ? "9x9" : "5";
        expectUsageError({"render", "-o", "x.png", "--scene", "s.json", shape, value}, {"don't combine it with --bvh, --characters"});
        expectUsageError({"demo", shape, value, "--scene", "s.json"}, {"don't combine it with --bvh, --characters"});
    }
    EXPECT_EQ(parseAs<RenderCommand>({"render", "-o", "x.png", "--scene", "s.json", "--seed", "4"}).crowd.scene,
              std::optional<std::string>("s.json"));
    expectUsageError({"demo", "--screenshot", "s.png"}, {"--screenshot", "--frames"});
    expectUsageError({"demo", "--script-resize"}, {"--script-resize needs --frames"});
    EXPECT_TRUE(parseAs<DemoCommand>({"demo", "--script-resize", "--frames", "5", "--no-vsync"}).scriptResize);
    expectUsageError({"render", "-n", "5"}, {"needs --out"});
    expectUsageError({"render", "--out", ""}, {"--out needs a file name"});
}

TEST(CliParse, LocomotionAndSpeedOnRenderAndBench) {
    const auto render = parseAs<RenderCommand>({"render", "-o", "x.png", "--locomotion", "a.bvh,b.bvh", "--speed", "0.5:2"});
    ASSERT_EQ(render.crowd.locomotion.size(), 2U);
    EXPECT_EQ(render.crowd.locomotion[1].path, "b.bvh");
    EXPECT_EQ(render.crowd.speed, std::optional<glm::vec2>(glm::vec2(0.5F, 2.0F)));
    // render blends the project's set without --bvh, so --speed alone is fine there.
    EXPECT_EQ(parseAs<RenderCommand>({"render", "-o", "x.png", "--speed", "1.2"}).crowd.speed,
              std::optional<glm::vec2>(glm::vec2(1.2F, 1.2F)));

    // bench takes the same options, for the render sweep and --sim-only alike.
    for (const Args& args : {Args{"bench", "--locomotion", "i.bvh,w.bvh,r.bvh", "--speed", "0:3"},
                             Args{"bench", "--sim-only", "--speed=0:3", "--locomotion=i.bvh,w.bvh,r.bvh"}}) {
        SCOPED_TRACE(joined(args));
        const auto bench = parseAs<BenchCommand>(args);
        ASSERT_EQ(bench.locomotion.size(), 3U);
        EXPECT_EQ(bench.locomotion[0].path, "i.bvh");
        EXPECT_EQ(bench.locomotion[2].path, "r.bvh");
        EXPECT_TRUE(bench.clips.empty());
        EXPECT_EQ(bench.speed, std::optional<glm::vec2>(glm::vec2(0.0F, 3.0F)));
    }
    const auto plain = parseAs<BenchCommand>({"bench", "--sim-only"});
    EXPECT_TRUE(plain.locomotion.empty()) << "without --locomotion the bench plays the single walk";
    EXPECT_FALSE(plain.speed.has_value());
    EXPECT_EQ(parseAs<BenchCommand>({"bench", "--locomotion", "w.bvh,r.bvh"}).speed, std::nullopt);

    for (const char* command : {"render", "bench"}) {
        SCOPED_TRACE(command);
        const Args out = std::string(command) == "render" ? Args{"-o", "x.png"} : Args{};
        const auto with = [&](Args extra) {
            extra.insert(extra.begin(), command);
            extra.insert(extra.end(), out.begin(), out.end());
            return extra;
        };
        expectUsageError(with({"--bvh", "w.bvh", "--locomotion", "w.bvh,r.bvh"}), {"--bvh plays each clip as it is", "give one or the other"});
        expectUsageError(with({"--bvh", "w.bvh", "--speed", "1"}), {"--speed needs a locomotion set to blend"});
        for (const char* speed : {"5:1", "nan", "-1", "21", "1:", "1e39", ""}) {
            SCOPED_TRACE(speed);
            expectUsageError(with({"--locomotion", "w.bvh,r.bvh", "--speed", speed}), {"--speed takes MIN[:MAX] in m/s"});
        }
    }
    // The bench's default is the single walk, not a set: --speed alone has nothing to blend.
    expectUsageError({"bench", "--speed", "1:2"}, {"--speed needs a locomotion set to blend (--locomotion)", "bench --help"});
    expectUsageError({"bench", "--sim-only", "--speed", "1:2"}, {"--speed needs a locomotion set to blend (--locomotion)"});
}

TEST(CliParse, RenderTakesAVideoWithItsRateAndAPartOfItsFrames) {
    const auto video = parseAs<RenderCommand>({"render", "-o", "v.mp4", "--duration", "2", "--fps", "25", "--frames", "10:19"});
    ASSERT_TRUE(video.duration.has_value());
    EXPECT_DOUBLE_EQ(*video.duration, 2.0);
    EXPECT_EQ(video.fps, 25);
    EXPECT_EQ(video.frameCount(), 50);
    ASSERT_TRUE(video.frames.has_value());
    EXPECT_EQ(video.frames->first, 10);
    EXPECT_EQ(video.frames->second, 19);
    const auto frames = parseAs<RenderCommand>({"render", "-o", "f/%05d.png", "--duration", "0.5"});
    EXPECT_EQ(frames.frameCount(), 15);  // the default 30 fps
    EXPECT_FALSE(frames.frames.has_value());
    expectUsageError({"render", "-o", "v.mp4", "--duration", "2", "--frames", "3"}, {"--frames takes A:B"});
    expectUsageError({"render", "-o", "v.mp4", "--duration", "0.01"}, {"less than half a frame"});
}

TEST(CliParse, UnknownOptionsAndStrayWords) {
    expectUsageError({"render", "-o", "x.png", "--bogus"}, {"unknown option", "--bogus", "render"});
    expectUsageError({"render", "-o", "x.png", "--screenshot", "s.png"}, {"unknown option", "--screenshot"});
    expectUsageError({"demo", "--out", "x.png"}, {"unknown option", "--out", "demo"});
    expectUsageError({"bench", "--sim"}, {"unknown option", "--sim", "bench"});
    expectUsageError({"render", "-o", "x.png", "extra"}, {"takes options only", "extra"});
    expectUsageError({"devices", "x"}, {"'devices' takes no arguments"});
    expectUsageError({"render", "--version"}, {"unknown option", "--version"});
    expectUsageError({"render", "-o"}, {"-o", "needs a value"});
    expectUsageError({"render", "--characters"}, {"--characters", "needs a value"});
    EXPECT_TRUE(std::holds_alternative<DevicesCommand>(parse({"devices"}).value()));
}

TEST(CliParse, ARepeatedOptionTakesItsLastValue) {
    EXPECT_EQ(parseAs<RenderCommand>({"render", "-o", "a.png", "-n", "5", "--characters", "7", "--out=b.png"}).crowd.characters, 7);
    EXPECT_EQ(parseAs<RenderCommand>({"render", "-o", "a.png", "-o", "b.png"}).out, "b.png");
}

TEST(CliParse, NumbersMustBeFiniteAndInRange) {
    const Args render{"render", "-o", "x.png"};
    const auto withRender = [&render](std::initializer_list<const char*> more) {
        Args args = render;
        args.insert(args.end(), more.begin(), more.end());
        return args;
    };
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e999", "-1e999", "0x10", "1;5", " 1", "1 ", ""}) {
        SCOPED_TRACE(bad);
        expectUsageError(withRender({"--time", bad}), {"--time takes seconds from 0 to 600"});
        expectUsageError(withRender({"--lod-pixels", bad}), {"--lod-pixels"});
        expectUsageError(withRender({"--area", (std::string(bad) + "x3").c_str()}), {"--area takes WIDTHxDEPTH"});
        expectUsageError(withRender({"--camera", (std::string("1,2,3,0,0,") + bad).c_str()}), {"--camera takes"});
        expectUsageError({"bvh", "info", "a.bvh", "--units", bad}, {"--units"});
    }
    // Whole numbers: overflow, fractions and signs are refused, not wrapped or truncated.
    for (const char* bad : {"99999999999", "4294967312", "18446744073709551616", "2.5", "1e3", "nan", "inf", "+5", "0x10"}) {
        SCOPED_TRACE(bad);
        expectUsageError(withRender({"--characters", bad}), {"--characters takes a count from 1 to 1000000"});
        expectUsageError(withRender({"--width", bad}), {"--width takes pixels from 16 to 8192"});
        expectUsageError(withRender({"--threads", bad}), {"--threads takes 1 to 256"});
        expectUsageError({"bench", "-n", (std::string("10,") + bad).c_str()}, {"--characters takes a list of counts"});
        expectUsageError({"bvh", "bench", "--repeat", bad}, {"--repeat"});
    }
    expectUsageError(withRender({"--seed", "18446744073709551616"}), {"--seed takes a non-negative whole number"});
    expectUsageError(withRender({"--seed", "-1"}), {"--seed"});
    EXPECT_EQ(parseAs<RenderCommand>(withRender({"--seed", "18446744073709551615"})).crowd.seed, UINT64_MAX);
    expectUsageError(withRender({"--time", "600.001"}), {"--time"});
    expectUsageError(withRender({"--time", "1,5"}), {"--time"});
    EXPECT_DOUBLE_EQ(parseAs<RenderCommand>(withRender({"--time", "600"})).crowd.time, 600.0);
    expectUsageError(withRender({"--width", "15"}), {"--width takes pixels from 16 to 8192"});
    EXPECT_EQ(parseAs<RenderCommand>(withRender({"--width", "8192"})).crowd.width, 8192U);
    expectUsageError(withRender({"--camera", "1,2,3,1,2,3"}), {"--camera eye and target must differ"});
    expectUsageError(withRender({"--camera", "1,2,3,0,0,0,170"}), {"--camera field of view"});
    expectUsageError(withRender({"--msaa", "16"}), {"--msaa takes 1, 2, 4 or 8"});
    expectUsageError({"demo", "--frames", "0"}, {"--frames takes a count from 1"});
    expectUsageError({"bench", "--frames", "100001"}, {"--frames takes a count from 1 to 100000"});
    expectUsageError({"bench", "--warmup", "-1"}, {"--warmup takes a count from 0 to 100000"});
    // The render sweep's options do nothing for the simulation alone: refused, not ignored.
    for (const auto& [option, value] : {std::pair{"--body", "bones"}, {"--msaa", "4"}, {"-W", "640"}, {"--device", "llvm"}})
        expectUsageError({"bench", "--sim-only", option, value}, {"is for the render sweep: --sim-only times the simulation alone"});
    expectUsageError({"bench", "--sim-only", "--overlap-simulation"}, {"--overlap-simulation is for the render sweep"});
}

}  // namespace
