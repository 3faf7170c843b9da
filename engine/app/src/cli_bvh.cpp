// `throng bvh info|bake|bench`: their options and checks.
#include <climits>
#include <memory>

#include "cli_internal.h"
#include "clip_spec.h"

namespace throng::app::detail {
namespace {

void addPositionChannels(CLI::App& app, motion::PositionChannels& target) {
    app.add_option_function<std::string>(
           "--position-channels",
           [&target](const std::string& text) {
               const std::optional<motion::PositionChannels> channels = positionChannelsFromName(text);
               if (!channels) refuse("--position-channels takes 'replace' or 'add', not '" + text + "'");
               target = *channels;
           },
           "How a joint's position channels combine with its OFFSET:\n"
           "replace (they are the whole translation, as Blender reads\n"
           "BVH) or add (as three.js does)")
        ->type_name("replace|add")
        ->default_str(target == motion::PositionChannels::Add ? "add" : "replace");
}

// Up axis, travel joint, straightening and foot lock: the choices the bake otherwise makes
// from the skeleton's structure, for a capture where it guesses wrong.
void addRootMotionOptions(CLI::App& app, motion::BakeOptions& bake) {
    app.add_option_function<std::string>(
           "--up",
           [&bake](const std::string& text) {
               const std::optional<motion::UpAxis> axis = motion::upAxisFromName(text);
               if (!axis) refuse("--up takes " + upAxisList() + ", not '" + text + "'");
               bake.upAxis = *axis;
           },
           "The file's up axis: " + upAxisList() + "\n(default: detected from the skeleton)")
        ->type_name("AXIS");
    addText(app, "--root", bake.travelJoint, "JOINT",
            "The joint whose ground track is the travel\n(default: the pelvis, found by structure)",
            "--root takes the name of a joint of the file");
    app.add_flag("--straighten", bake.straighten, "Take out the clip's own turning: walk a straight line");
    app.add_flag_callback(
        "--no-foot-lock", [&bake] { bake.footLock = false; }, "Let planted feet slide (no leg IK during contacts)");
}

// The options of every command that bakes a clip.
void addBakeOptions(CLI::App& app, motion::BakeOptions& bake) {
    addPositionChannels(app, bake.positionChannels);
    addNumber(app, "--units", bake.metresPerUnit,
              NumberRule<double>{kPositive<double>, kMaxMetresPerUnit, "--units takes a positive number of metres per file unit"},
              "Override the inferred unit scale (e.g. 0.01 for centimetres)")
        ->type_name("METRES_PER_UNIT");
    app.add_option_function<std::string>(
           "--loop",
           [&bake](const std::string& text) {
               const std::string_view all = text;
               const std::size_t colon = all.find(':');
               const std::optional<int> first = parseBounded(all.substr(0, colon), 0, INT_MAX);
               const std::optional<int> last =
                   colon == std::string_view::npos ? std::nullopt : parseBounded(all.substr(colon + 1), 0, INT_MAX);
               if (!first || !last || *last <= *first)
                   refuse("--loop takes FIRST:LAST frame indices with FIRST < LAST, not '" + text + "'");
               bake.loop = motion::LoopRange{*first, *last};
           },
           "Override the detected loop range (frame indices)")
        ->type_name("FIRST:LAST");
    app.add_flag_callback(
        "--keep-first-frame", [&bake] { bake.skipFirstFrame = false; }, "Never treat frame 0 as a synthetic T-pose");
    addRootMotionOptions(app, bake);
}

CommandDefinition defineInfo(CLI::App& bvh, ParseState& state) {
    auto command = std::make_shared<BvhInfoCommand>();
    CLI::App* app = addCommand(bvh, "info", "Summarise a BVH clip: skeleton, channels, frames, height, units, loop.", state);
    app->footer("Prints the joints with their parents and channels, frame count, frame time, duration,\n"
                "skeleton height and stature, the unit guess, up axis, travel joint, speed and turn rate,\n"
                "the detected loop range and the bake's warnings.");
    app->add_option("FILE", command->file, "The BVH file (required)")->type_name("");
    addText(*app, "--json", command->jsonOut, "OUT|-", "Also write the summary as JSON to OUT (- for stdout)");
    addBakeOptions(*app, command->bake);
    return {app,
            [app, command]() -> Result<Command> {
                if (command->file.empty()) return usage("'bvh info' needs a BVH FILE", *app);
                return Command{*command};
            },
            [](const std::string& word) { return "'bvh info' takes one FILE, got a second: '" + word + "'"; }};
}

CommandDefinition defineBake(CLI::App& bvh, ParseState& state) {
    auto command = std::make_shared<BvhBakeCommand>();
    CLI::App* app = addCommand(bvh, "bake", "Write the raw forward kinematics of a BVH clip as JSON.", state);
    app->footer("Writes the world position of every joint (End Sites excluded) in the BVH's own units and\n"
                "axes, with no root-motion removal and no scaling:\n"
                "  {\"joints\": [...], \"parents\": [...], \"frame_time\": s, \"frame_count\": n,\n"
                "   \"frames\": {\"0\": [[x, y, z], ...], ...}}");
    app->add_option("FILE", command->file, "The BVH file (required)")->type_name("");
    addText(*app, "--json", command->jsonOut, "OUT|-", "Output path, or - for stdout (required)");
    app->add_option_function<std::string>(
           "--frames",
           [command](const std::string& text) {
               if (text == "all") {
                   command->frames.reset();
                   return;
               }
               command->frames = checkedList(
                   text, NumberRule<int>{0, INT_MAX, "--frames takes 'all' or a comma-separated list of frame indices"});
           },
           "Frames to write: all, or a list like 0,5,17")
        ->type_name("all|LIST")
        ->default_str("all");
    addPositionChannels(*app, command->positionChannels);
    return {app,
            [app, command]() -> Result<Command> {
                if (command->file.empty()) return usage("'bvh bake' needs a BVH FILE", *app);
                if (app->count("--json") == 0) return usage("'bvh bake' needs --json OUT (or --json - for stdout)", *app);
                return Command{*command};
            },
            [](const std::string& word) { return "'bvh bake' takes one FILE, got a second: '" + word + "'"; }};
}

CommandDefinition defineBvhBench(CLI::App& bvh, ParseState& state) {
    auto command = std::make_shared<BvhBenchCommand>();
    CLI::App* app = addCommand(bvh, "bench", "Time parsing and baking (median of repeated runs).", state);
    app->footer("Times parsing and baking of each FILE (default: the project's clip) and prints the median\n"
                "and spread. A benchmark: it prints figures and asserts nothing.");
    app->add_option("FILE", command->files, "BVH files to time")->type_name("");
    addNumber(*app, "--repeat", command->repeat, NumberRule<int>{1, 100000, "--repeat takes a count from 1 to 100000"},
              "Timed repetitions per file");
    return {app, [command]() -> Result<Command> { return Command{*command}; },
            [](const std::string& word) { return "'bvh bench' cannot use '" + word + "'"; }};
}

}  // namespace

std::vector<CommandDefinition> defineBvhCommands(CLI::App& bvh, ParseState& state) {
    return {defineInfo(bvh, state), defineBake(bvh, state), defineBvhBench(bvh, state)};
}

}  // namespace throng::app::detail
