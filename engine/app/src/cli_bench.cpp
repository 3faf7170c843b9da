// `throng bench`: its options and checks.
#include <memory>

#include <sstream>

#include "cli_internal.h"

namespace throng::app::detail {
namespace {

/// What a sweep runs when the command line doesn't say.
struct Sweep {
    std::vector<int> characters;
    int frames;
    int warmup;
};
// Bare `throng bench`: the default path and body (those of `throng render`) at the sizes #14
// states its targets for. With --modes, the comparison of paths, at sizes every path can draw.
const Sweep kRenderSweep{{2000, 10000, 100000}, 20, 3};
const Sweep kComparisonSweep{{250, 500, 1000, 2000, 4000, 8000}, 20, 3};
const Sweep kSimulationSweep{{1000, 10000, 100000}, 30, 10};
constexpr render::RenderPath kDefaultPath = render::RenderPath::Fast;  // as `throng render`'s

std::string joined(const std::vector<int>& values) {
    std::string text;
    for (const int value : values) text += (text.empty() ? "" : ",") + std::to_string(value);
    return text;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// --modes names render paths, or with --sim-only locomotion modes; `all` stands for all of
// them. Without --modes: the default path (render), or every locomotion mode (--sim-only).
Result<bool> resolveModes(BenchCommand& command, const std::vector<std::string_view>& names, const CLI::App& app) {
    for (const std::string_view name : names) {
        if (name == "all") {
            const std::vector<std::string> everyMode = modeNames();
            if (command.simOnly) command.modes.insert(command.modes.end(), everyMode.begin(), everyMode.end());
            else command.paths.insert(command.paths.end(), render::kRenderPaths.begin(), render::kRenderPaths.end());
            continue;
        }
        if (command.simOnly) {
            if (!crowd::modeFromName(name))
                return usage("--modes takes " + joined(modeNames()) + " (or all) with --sim-only, not '" + std::string(name) + "'", app);
            command.modes.emplace_back(name);
        } else {
            const std::optional<render::RenderPath> path = render::renderPathFromName(name);
            if (!path) return usage("--modes takes " + render::renderPathList() + " (or all), not '" + std::string(name) + "'", app);
            command.paths.push_back(*path);
        }
    }
    if (names.empty() && command.simOnly) command.modes = modeNames();
    if (names.empty() && !command.simOnly) {
        command.paths = {kDefaultPath};
        command.choosePath = true;  // the visibility path instead, where `throng render` takes it
        // The default body too, unless --body says otherwise (as `throng render`).
        if (app.count("--body") == 0) command.bodies = {render::Body::Auto};
    }
    return true;
}

// --body LIST: the bodies the render sweep draws.
void addBodyList(CLI::App& app, BenchCommand& command) {
    app.add_option_function<std::string>(
           "--body",
           [&command](const std::string& text) {
               command.bodies.clear();
               std::stringstream list(text);
               for (std::string name; std::getline(list, name, ',');) {
                   const std::optional<render::Body> body = render::bodyFromName(name);
                   if (!body) refuse("--body takes a list of spheres, bones, skin and auto, not '" + name + "'");
                   command.bodies.push_back(*body);
               }
               if (command.bodies.empty()) refuse("--body needs at least one body");
           },
           "Bodies to sweep, comma-separated: spheres (on each path of\n--modes), bones, skin, auto (on the fast and visibility paths\namong --modes, else fast). Default: auto without --modes,\nelse spheres")
        ->type_name("LIST");
}

// What a timed frame includes: the readback, and what it keeps of the frame before.
void addFrameFlags(CLI::App& app, BenchCommand& command) {
    app.add_flag("--no-readback", command.noReadback,
                 "Don't copy each frame's image back to the host (as\n../shared/probe's timed frames don't); readback reads 0");
    app.add_flag("--fresh-frames", command.freshFrames,
                 "Draw every frame from scratch: the visibility path keeps\nnothing of the last frame, as with a camera moving every frame");
    app.add_flag("--overlap-simulation", command.overlapSimulation,
                 "Step the crowd for the next frame while the GPU draws this\none, as the demo's frames in flight do (on a CPU device the\ntwo share its cores)");
}

// What --sim-only cannot take: the render sweep's options (taken, they would do nothing), and
// --modes (locomotion modes there) beside a crowd whose modes are given otherwise.
std::optional<Error> simOnlyConflicts(const CLI::App& app, const BenchCommand& command, bool modesGiven) {
    for (const char* option : {"--body", "--msaa", "--lod-pixels", "--width", "--height", "--device", "--no-readback", "--fresh-frames",
                               "--overlap-simulation"})
        if (app.count(option) > 0)
            return usage(std::string(option) + " is for the render sweep: --sim-only times the simulation alone, with no device", app);
    if (command.trajectories && modesGiven)
        return usage("--modes with --sim-only names locomotion modes, and characters following --trajectories have none: give one or the other", app);
    if (command.scene && modesGiven)
        return usage("--modes with --sim-only names locomotion modes, and a scene's groups keep their own: give --modes or --scene, not both", app);
    return std::nullopt;
}

}  // namespace

CommandDefinition defineBench(CLI::App& parent, ParseState& state) {
    auto command = std::make_shared<BenchCommand>();
    auto modes = std::make_shared<std::optional<std::string>>();  // --modes as given: its meaning depends on --sim-only
    CLI::App* app = addCommand(parent, "bench", "Benchmark frames per render path and crowd size (--sim-only: the simulation).", state);
    app->footer("Renders frames offscreen per render path and crowd size and prints where the time goes:\n"
                "the whole frame (wall clock), CPU simulation, upload, compute and draw (GPU timestamps) and\n"
                "readback; median, min and max. With --sim-only it times Crowd::step per locomotion mode\n"
                "instead. Characters play the walk as it is, or with --locomotion blend a set by speed\n"
                "(--speed), or with --scene do what a scene file says (groups, sets, events); the\n"
                "caption and JSON header say which. A benchmark: it prints figures and asserts\n"
                "nothing. Progress goes to stderr.");
    app->add_flag("--sim-only", command->simOnly, "Time the crowd simulation only");
    addFrameFlags(*app, *command);
    app->add_option_function<std::string>(
           "-n,--characters",
           [command](const std::string& text) {
               command->characters = checkedList(
                   text, NumberRule<int>{1, kMaxCharacters,
                                         "--characters takes a list of counts from 1 to " + std::to_string(kMaxCharacters)});
           },
           "Crowd sizes (default " + joined(kRenderSweep.characters) + ";\nwith --modes " +
               joined(kComparisonSweep.characters) + ";\nwith --sim-only " + joined(kSimulationSweep.characters) +
               "); with --scene the totals\nits groups are scaled to in proportion\n(default: the scene's own)")
        ->type_name("LIST");
    addText(*app, "--modes", *modes, "LIST",
            "Render paths " + render::renderPathList() + ", or all\n(default: the path render picks for each row, with --body auto);\n"
            "with --sim-only the locomotion modes " + joined(modeNames()) + ", or all\n(default all)");
    const NumberRule<int> frames{1, 100000, "--frames takes a count from 1 to 100000"};
    addNumber(*app, "--frames", command->frames, frames,
              "Timed frames per row, each followed by one that times its\npasses with GPU timestamps (default " + std::to_string(kRenderSweep.frames) +
                  "; --sim-only: " + std::to_string(kSimulationSweep.frames) + " steps)")
        ->default_str("");
    addNumber(*app, "--warmup", command->warmup, NumberRule<int>{0, 100000, "--warmup takes a count from 0 to 100000"},
              "Untimed frames first (default " + std::to_string(kRenderSweep.warmup) + "; --sim-only: " +
                  std::to_string(kSimulationSweep.warmup) + ")")
        ->default_str("");
    addImageSize(*app, command->width, command->height, "Frame");
    addMsaa(*app, command->msaa, "Multisampling: 1, 2, 4 or 8");
    addNumber(*app, "--lod-pixels", command->lodPixels, kLodPixelsRule, "fast path level of detail (0: off)");
    addBodyList(*app, *command);
    addText(*app, "--device", command->device, "NAME", "Vulkan device by name substring");
    addNumber(*app, "--threads", command->threads, kThreadsRule, "Simulation threads (default: all cores)")->default_str("");
    addClipOption(*app, command->clips, "Clip(s) to walk with (default: assets/walk.bvh)");
    addLocomotionOptions(*app, command->locomotion, command->speed, "default: none; the bench's\ncharacters play the walk as it is, as before");
    addText(*app, "--scene", command->scene, "FILE.json",
            "The crowd from a scene file, as for render: clips, groups,\nlocomotion sets, events, seed (not its camera: rows frame\n"
            "the crowd); excludes --bvh, --locomotion and --speed",
            "--scene needs a file name");
    addTrajectoryOptions(*app, command->trajectories, command->trajectoryReading,
                         "Rows of fewer characters take the first\ntracks; more than the file has is refused. Excludes --scene,\n--bvh and --speed");
    addText(*app, "--csv", command->csv, "OUT|-", "Also write the rows as CSV");
    addText(*app, "--json", command->json, "OUT|-", "Also write the rows as JSON");
    return {app,
            [app, command, modes]() -> Result<Command> {
                if (auto conflict = sceneConflicts(*app, command->scene.has_value(), {"--bvh", "--locomotion", "--speed"})) return *conflict;
                if (auto alone = trajectoryReadingAlone(*app, command->trajectories.has_value())) return *alone;
                if (command->simOnly)
                    if (auto conflict = simOnlyConflicts(*app, *command, modes->has_value())) return *conflict;
                if (command->trajectories && (command->scene || !command->clips.empty() || command->speed))
                    return usage("--trajectories gives the characters and where they walk; don't combine it with --scene, --bvh or --speed", *app);
                if (auto conflict = locomotionConflicts(*app, command->clips, command->locomotion, command->speed.has_value(),
                                                        !command->locomotion.empty(),
                                                        "(--locomotion); without one each character plays its clip at its own pace"))
                    return *conflict;
                auto resolved = resolveModes(*command, *modes ? splitList(**modes) : std::vector<std::string_view>{}, *app);
                if (!resolved) return resolved.error();
                const Sweep& sweep = command->simOnly ? kSimulationSweep : (*modes ? kComparisonSweep : kRenderSweep);
                if (command->characters.empty() && !command->scene && !command->trajectories) command->characters = sweep.characters;
                if (command->scene && command->simOnly) command->modes = {std::string(BenchCommand::kSceneMode)};
                if (command->trajectories && command->simOnly) command->modes = {std::string(BenchCommand::kFollowMode)};
                if (command->frames == 0) command->frames = sweep.frames;
                if (command->warmup < 0) command->warmup = sweep.warmup;
                return Command{*command};
            },
            [](const std::string& word) { return "'bench' takes options only, got '" + word + "'"; }};
}

}  // namespace throng::app::detail
