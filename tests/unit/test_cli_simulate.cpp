// `throng simulate`'s command line: required options, the ranges of --time and --fps, the
// crowd options shared with render (one definition, the same checks), and help.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

#include "throng/app/cli.h"

namespace {

using throng::Error;
using throng::app::Command;
using throng::app::HelpCommand;
using throng::app::RenderCommand;
using throng::app::SimulateCommand;

using Args = std::vector<std::string>;

Args simulateWith(std::initializer_list<const char*> more) {
    Args args{"simulate", "--time", "2", "--fps", "30", "--out", "t.csv"};
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

std::string joined(const Args& args) {
    std::string out;
    for (const std::string& a : args) out += (out.empty() ? "" : " ") + a;
    return out;
}

SimulateCommand parseSimulate(const Args& args) {
    auto result = throng::app::parseCommandLine(args);
    if (!result.ok()) {
        ADD_FAILURE() << "'" << joined(args) << "' failed: " << result.error().describe();
        return {};
    }
    const auto* command = std::get_if<SimulateCommand>(&result.value());
    if (command == nullptr) ADD_FAILURE() << "'" << joined(args) << "' gave another command";
    return command != nullptr ? *command : SimulateCommand{};
}

// A usage error: BadInput, one line, mentioning every word, ending with simulate's help.
void expectRefused(const Args& args, std::initializer_list<const char*> words) {
    SCOPED_TRACE(joined(args));
    auto result = throng::app::parseCommandLine(args);
    ASSERT_FALSE(result.ok()) << "parsed, but should be a usage error";
    const Error& e = result.error();
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    for (const char* word : words) EXPECT_NE(e.message.find(word), std::string::npos) << "'" << word << "' not in: " << e.message;
    const std::string hint = "(see 'throng simulate --help')";
    EXPECT_TRUE(e.message.size() >= hint.size() && e.message.compare(e.message.size() - hint.size(), hint.size(), hint) == 0)
        << e.message;
    EXPECT_EQ(e.message.find('\n'), std::string::npos) << e.message;
}

TEST(CliSimulate, TheIssuesExample) {
    const auto command = parseSimulate({"simulate", "--characters", "1", "--mode", "group", "--speed", "1.8", "--time", "8", "--fps",
                                        "60", "--out", "t.csv", "--joints-out", "j.csv"});
    EXPECT_EQ(command.crowd.characters, 1);
    EXPECT_EQ(command.crowd.mode, throng::crowd::Mode::Group);
    ASSERT_TRUE(command.crowd.speed.has_value());
    EXPECT_FLOAT_EQ(command.crowd.speed->x, 1.8F);
    EXPECT_FLOAT_EQ(command.crowd.speed->y, 1.8F);
    EXPECT_DOUBLE_EQ(command.time, 8.0);
    EXPECT_EQ(command.fps, 60);
    EXPECT_EQ(command.out, "t.csv");
    EXPECT_EQ(command.jointsOut, std::optional<std::string>("j.csv"));
    EXPECT_EQ(command.lastFrame(), 480);
}

TEST(CliSimulate, DefaultsAreRendersCrowd) {
    const auto command = parseSimulate(simulateWith({}));
    const auto render = std::get<RenderCommand>(throng::app::parseCommandLine(Args{"render", "-o", "x.png"}).value());
    EXPECT_EQ(command.crowd.characters, render.crowd.characters);
    EXPECT_EQ(command.crowd.mode, render.crowd.mode);
    EXPECT_FALSE(command.crowd.seed.has_value());
    EXPECT_TRUE(command.crowd.clips.empty());
    EXPECT_TRUE(command.crowd.locomotion.empty());
    EXPECT_FALSE(command.jointsOut.has_value());
    EXPECT_DOUBLE_EQ(command.crowd.time, 0.0);  // simulate's --time is its own field
}

TEST(CliSimulate, EveryCrowdOptionIsRendersOwn) {
    const auto command = parseSimulate(simulateWith({"--bvh=a.bvh", "--bvh", "b.bvh", "-n", "7", "--mode", "avoid", "--area", "12x8",
                                                     "--seed", "9", "--threads", "2", "-o", "u.csv"}));
    ASSERT_EQ(command.crowd.clips.size(), 2U);
    EXPECT_EQ(command.crowd.clips[1].path, "b.bvh");
    EXPECT_EQ(command.crowd.characters, 7);
    EXPECT_EQ(command.crowd.mode, throng::crowd::Mode::Avoid);
    ASSERT_TRUE(command.crowd.area.has_value());
    EXPECT_FLOAT_EQ(command.crowd.area->x, 12.0F);
    EXPECT_EQ(command.crowd.seed, std::optional<std::uint64_t>(9));
    EXPECT_EQ(command.crowd.threads, 2U);
    EXPECT_EQ(command.out, "u.csv");
    EXPECT_EQ(parseSimulate(simulateWith({"--locomotion", "i.bvh,w.bvh"})).crowd.locomotion.size(), 2U);
    EXPECT_EQ(parseSimulate(simulateWith({"--scene", "s.json"})).crowd.scene, std::optional<std::string>("s.json"));
    // The same checks and messages as render's, naming simulate's help.
    expectRefused(simulateWith({"-n", "0"}), {"--characters takes a count from 1"});
    expectRefused(simulateWith({"--mode", "flock"}), {"--mode takes group, goals or avoid"});
    expectRefused(simulateWith({"--speed", "nan"}), {"--speed takes MIN[:MAX]"});
    expectRefused(simulateWith({"--threads", "0"}), {"--threads takes 1 to 256"});
    expectRefused(simulateWith({"--scene", "s.json", "-n", "5"}), {"don't combine it with --bvh, --characters"});
    expectRefused(simulateWith({"--bvh", "a.bvh", "--speed", "1"}), {"--speed needs a locomotion set"});
    // Options that only draw are not simulate's.
    for (const char* drawing : {"--width", "--camera", "--msaa", "--path", "--device", "--dump-instances"})
        expectRefused(simulateWith({drawing, "1"}), {"unknown option", drawing});
}

TEST(CliSimulate, TimeMustBePositiveFiniteAndAtMostTheLimit) {
    EXPECT_DOUBLE_EQ(parseSimulate({"simulate", "--time=600", "--fps=1", "-o", "t.csv"}).time, 600.0);
    EXPECT_DOUBLE_EQ(parseSimulate({"simulate", "--time", "0.25", "--fps", "4", "-o", "t.csv"}).time, 0.25);
    for (const char* bad : {"0", "-0", "-1", "nan", "inf", "-inf", "1e9", "600.001", "1e999", "", "2s", "1,5"}) {
        SCOPED_TRACE(bad);
        expectRefused({"simulate", "--time", bad, "--fps", "30", "-o", "t.csv"}, {"--time takes seconds, more than 0 and at most 600"});
    }
}

TEST(CliSimulate, FpsIsAWholeNumberFrom1To1000) {
    EXPECT_EQ(parseSimulate({"simulate", "--time", "1", "--fps", "1000", "-o", "t.csv"}).fps, 1000);
    EXPECT_EQ(parseSimulate({"simulate", "--time", "1", "--fps", "1", "-o", "t.csv"}).lastFrame(), 1);
    for (const char* bad : {"0", "-30", "1001", "100000", "nan", "29.97", "1e2", "", "4294967326"}) {
        SCOPED_TRACE(bad);
        expectRefused({"simulate", "--time", "1", "--fps", bad, "-o", "t.csv"}, {"--fps takes whole samples per second from 1 to 1000"});
    }
}

TEST(CliSimulate, FramesAreRoundedAndAtLeastOne) {
    EXPECT_EQ(parseSimulate({"simulate", "--time", "0.55", "--fps", "10", "-o", "t.csv"}).lastFrame(), 6);  // round(5.5)
    EXPECT_EQ(parseSimulate({"simulate", "--time", "0.01", "--fps", "60", "-o", "t.csv"}).lastFrame(), 1);  // round(0.6)
    expectRefused({"simulate", "--time", "0.005", "--fps", "60", "-o", "t.csv"}, {"--time 0.005", "less than half a frame", "--fps 60"});
}

TEST(CliSimulate, RequiredOptions) {
    expectRefused({"simulate", "--time", "1", "--fps", "30"}, {"'simulate' needs --out"});
    expectRefused({"simulate", "--fps", "30", "-o", "t.csv"}, {"'simulate' needs --time"});
    expectRefused({"simulate", "--time", "1", "-o", "t.csv"}, {"'simulate' needs --fps"});
    expectRefused(simulateWith({"--out", ""}), {"--out needs a file name"});
    expectRefused(simulateWith({"--joints-out", ""}), {"--joints-out needs a file name"});
    expectRefused(simulateWith({"--joints-out"}), {"--joints-out", "needs a value"});
    expectRefused(simulateWith({"stray"}), {"'simulate' takes options only", "stray"});
}

TEST(CliSimulate, Help) {
    const std::string help = std::get<HelpCommand>(throng::app::parseCommandLine(Args{"simulate", "--help"}).value()).text;
    EXPECT_EQ(help, std::get<HelpCommand>(throng::app::parseCommandLine(Args{"help", "simulate"}).value()).text);
    EXPECT_EQ(help, std::get<HelpCommand>(throng::app::parseCommandLine(Args{"simulate", "--fps", "0", "-h"}).value()).text);
    for (const char* word : {"Usage: throng simulate", "--time", "--fps", "--out", "--joints-out", "--characters", "--locomotion",
                             "--speed", "--scene", "--seed", "--threads", "id,frame,time,x,y,z,heading,speed",
                             "id,frame,time,joint,name,x,y,z"})
        EXPECT_NE(help.find(word), std::string::npos) << word << " not in:\n" << help;
    const std::string main = std::get<HelpCommand>(throng::app::parseCommandLine(Args{"--help"}).value()).text;
    EXPECT_NE(main.find("simulate"), std::string::npos) << main;
}

}  // namespace
