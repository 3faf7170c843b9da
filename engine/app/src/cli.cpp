#include "throng/app/cli.h"

#include <charconv>

#include "cli_internal.h"
#include <string_view>

namespace throng::app {
namespace {

constexpr const char* kMainHelp = R"(throng - GPU crowd animation from motion capture

Usage: throng <command> [options]

Commands:
  bvh info FILE        Summarise a BVH clip: skeleton, channels, frames, height, units, loop.
  bvh bake FILE        Write the raw forward kinematics of a BVH clip as JSON.
  bvh bench [FILE...]  Time parsing and baking (median of repeated runs).
  render --out F.png   Render the crowd offscreen to a PNG (headless; lavapipe works).
  demo                 Open a window and watch the crowd (needs a display).
  devices              List the Vulkan devices.
  bench                Benchmark frames per render path and crowd size (--sim-only: the simulation).
  help, --help         Show this help. Every command takes --help.
  --version            Print the version.

Exit codes: 0 success, 1 runtime failure, 2 bad usage or bad input.
)";

constexpr const char* kInfoHelp = R"(Usage: throng bvh info FILE [options]

Prints the joints with their parents and channels, frame count, frame time, duration,
skeleton height, the unit guess and the detected loop range.

Options:
  --json OUT|-                     Also write the summary as JSON to OUT (- for stdout).
  --position-channels replace|add  How position channels combine with OFFSET (default replace).
  --units METRES_PER_UNIT          Override the inferred unit scale (e.g. 0.01 for centimetres).
  --loop FIRST:LAST                Override the detected loop range (frame indices).
  --keep-first-frame               Never treat frame 0 as a synthetic T-pose.
)";

constexpr const char* kBakeHelp = R"(Usage: throng bvh bake FILE --json OUT|- [options]

Writes the raw forward kinematics: world positions of every joint (End Sites excluded) in
the BVH's own units and axes, with no root-motion removal and no scaling.
JSON: {"joints": [...], "parents": [...], "frame_time": s, "frame_count": n,
       "frames": {"0": [[x, y, z], ...], ...}}

Options:
  --json OUT|-                     Output path, or - for stdout (required).
  --frames all|LIST                Frames to write: all (default) or a list like 0,5,17.
  --position-channels replace|add  How position channels combine with OFFSET (default replace).
)";

constexpr const char* kRenderHelp = R"(Usage: throng render [options] --out FILE.png

Renders one frame of the crowd offscreen and writes it as a PNG (atomically).

Options:
  --bvh FILE            A clip to animate; repeat for several (default: assets/walk.bvh).
  --characters N        Crowd size, 1 to 1000000 (default 2000).
  --mode MODE           group (the paper's: one shared heading), goals (each to its own goal),
                        or avoid (goals plus collision avoidance). Default group.
  --area WxD            Spawn and goal area in metres (default grows with the crowd).
  --scene FILE.json     Clips, groups, goals and camera from a scene file (see README).
  --threads N           Simulation threads (default: all cores).
  --time SECONDS        Simulated seconds before the frame, 0 to 600 (default 0).
  --width W, --height H Image size in pixels, 16 to 8192 (default 1280 x 720).
  --seed S              Crowd layout, start frames and colours (default 1).
  --device NAME         Pick the Vulkan device whose name contains NAME (see 'throng devices').
  --camera EX,EY,EZ,TX,TY,TZ[,FOV]
                        Eye and target in metres, vertical FOV in degrees (default: frame the crowd).
  --msaa N              Multisampling: 1, 2, 4 or 8 (default 4, or the most the device has).
  --path PATH           compute (default): compute pass + sphere meshes; fast: culling compute
                        pass + ray-cast point sprites; paper: no compute pass, the vertex shader
                        reads the baked table; cpu: joints resolved on the CPU each frame.
  --lod-pixels N        fast path: characters under N pixels tall draw only their major
                        joints (default 48; 0 turns level of detail off).
  --validation          Enable the Khronos validation layer; any message fails the run (exit 1).
                        THRONG_VALIDATION=1 does the same.
  --dump-instances F    Also write the GPU-resolved joint positions of every character as JSON.
)";

constexpr const char* kDemoHelp = R"(Usage: throng demo [crowd options] [options]

Opens a resizable window and animates the crowd live, with a HUD.

Crowd options as for 'throng render': --bvh, --characters, --mode, --area, --scene,
--time, --seed, --threads, --device, --camera, --msaa, --path, --lod-pixels, --validation,
--width, --height.

Options:
  --path PATH           As for render, but the demo defaults to fast.
  --no-vsync            Present with MAILBOX or IMMEDIATE instead of FIFO, where supported.
  --frames N            Run N frames (fixed 1/60 s steps) and exit 0.
  --screenshot F.png    With --frames: save the last frame.
  --script-resize       With --frames: resize the window a few times during the run.

Controls: left mouse orbit, right/middle mouse pan, wheel zoom, WASD/QE fly, F frame the
crowd, C follow the next character, space pause, +/- playback speed, [ ] halve/double the
crowd, M next locomotion mode, P save a screenshot, Esc quit.
)";

constexpr const char* kDevicesHelp = R"(Usage: throng devices

Lists the Vulkan devices with their type, API version and driver.
)";

constexpr const char* kCrowdBenchHelp = R"(Usage: throng bench [options]

Renders frames offscreen per render path and crowd size and prints where the time goes:
the whole frame (wall clock), CPU simulation, upload, compute and draw (GPU timestamps) and
readback; median, min and max. With --sim-only it times Crowd::step per locomotion mode
instead. A benchmark: it prints figures and asserts nothing. Progress goes to stderr.

Options:
  --characters LIST     Crowd sizes (default 250,500,1000,2000,4000,8000;
                        with --sim-only 1000,10000,100000).
  --modes LIST          Render paths paper, cpu, compute, fast (default all);
                        with --sim-only the locomotion modes group, goals, avoid.
  --frames N            Timed frames per row (default 20; --sim-only: 30 steps).
  --warmup N            Untimed frames first (default 3; --sim-only: 10).
  --width W, --height H Frame size (default 1280 x 720).
  --msaa N              1, 2, 4 or 8 (default 4).
  --lod-pixels N        fast path level of detail (default 48; 0 off).
  --device NAME         Vulkan device by name substring.
  --threads N           Simulation threads (default: all cores).
  --bvh FILE            Clip(s) to walk with (default: assets/walk.bvh).
  --sim-only            Time the crowd simulation only.
  --csv OUT|-           Also write the rows as CSV.
  --json OUT|-          Also write the rows as JSON.
)";

constexpr const char* kBenchHelp = R"(Usage: throng bvh bench [FILE...] [--repeat N]

Times parsing and baking of each file (default: the project's clip) and prints the median
and spread of N runs (default 15). A benchmark: it prints figures and asserts nothing.
)";

using detail::usage;

// Walks the argument list; every option that takes a value reads it through here, so a
// missing value is reported the same way everywhere.
class ArgCursor {
public:
    explicit ArgCursor(std::span<const std::string> args) : args_(args) {}
    [[nodiscard]] bool done() const { return index_ >= args_.size(); }
    const std::string& take() { return args_[index_++]; }
    Result<std::string> value(const std::string& option) {
        if (done()) return usage("option " + option + " needs a value");
        return take();
    }

private:
    std::span<const std::string> args_;
    std::size_t index_ = 0;
};

bool wantsHelp(std::span<const std::string> args) {
    for (const std::string& a : args)
        if (a == "--help" || a == "-h") return true;
    return false;
}

template <typename Number>
std::optional<Number> parseWhole(std::string_view text) {
    Number value{};
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

Result<motion::PositionChannels> parsePositionChannels(const std::string& text) {
    if (text == "replace") return motion::PositionChannels::Replace;
    if (text == "add") return motion::PositionChannels::Add;
    return usage("--position-channels takes 'replace' or 'add', not '" + text + "'");
}

Result<std::optional<std::vector<int>>> parseFrameList(const std::string& text) {
    if (text == "all") return std::optional<std::vector<int>>{};
    std::vector<int> frames;
    std::string_view rest = text;
    while (true) {
        const std::size_t comma = rest.find(',');
        const std::optional<int> frame = parseWhole<int>(rest.substr(0, comma));
        if (!frame || *frame < 0) return usage("--frames takes 'all' or a comma-separated list of frame indices, not '" + text + "'");
        frames.push_back(*frame);
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    return std::optional<std::vector<int>>(std::move(frames));
}

// Options shared by the commands that bake. Returns false if `option` isn't one of them.
Result<bool> parseBakeOption(const std::string& option, ArgCursor& cursor, motion::BakeOptions& bake) {
    if (option == "--position-channels") {
        auto text = cursor.value(option);
        if (!text) return text.error();
        auto mode = parsePositionChannels(text.value());
        if (!mode) return mode.error();
        bake.positionChannels = mode.value();
    } else if (option == "--units") {
        auto text = cursor.value(option);
        if (!text) return text.error();
        double scale = 0;
        auto [end, ec] = std::from_chars(text.value().data(), text.value().data() + text.value().size(), scale);
        if (ec != std::errc() || end != text.value().data() + text.value().size() || !(scale > 0) || scale > 1e6)
            return usage("--units takes a positive number of metres per file unit, not '" + text.value() + "'");
        bake.metresPerUnit = scale;
    } else if (option == "--loop") {
        auto text = cursor.value(option);
        if (!text) return text.error();
        const std::size_t colon = text.value().find(':');
        const auto first = parseWhole<int>(std::string_view(text.value()).substr(0, colon));
        const auto last = colon == std::string::npos ? std::nullopt
                                                     : parseWhole<int>(std::string_view(text.value()).substr(colon + 1));
        if (!first || !last || *first < 0 || *last <= *first)
            return usage("--loop takes FIRST:LAST frame indices with FIRST < LAST, not '" + text.value() + "'");
        bake.loop = motion::LoopRange{*first, *last};
    } else if (option == "--keep-first-frame") {
        bake.skipFirstFrame = false;
    } else {
        return false;
    }
    return true;
}

Result<Command> parseInfo(ArgCursor cursor) {
    BvhInfoCommand command;
    while (!cursor.done()) {
        const std::string& arg = cursor.take();
        auto handled = parseBakeOption(arg, cursor, command.bake);
        if (!handled) return handled.error();
        if (handled.value()) continue;
        if (arg == "--json") {
            auto out = cursor.value(arg);
            if (!out) return out.error();
            command.jsonOut = out.value();
        } else if (arg.starts_with("-") && arg != "-") {
            return usage("unknown option '" + arg + "' for 'bvh info'");
        } else if (command.file.empty()) {
            command.file = arg;
        } else {
            return usage("'bvh info' takes one FILE, got a second: '" + arg + "'");
        }
    }
    if (command.file.empty()) return usage("'bvh info' needs a BVH FILE");
    return Command{command};
}

Result<Command> parseBake(ArgCursor cursor) {
    BvhBakeCommand command;
    bool haveJson = false;
    while (!cursor.done()) {
        const std::string& arg = cursor.take();
        if (arg == "--json" || arg == "--frames" || arg == "--position-channels") {
            auto text = cursor.value(arg);
            if (!text) return text.error();
            if (arg == "--json") {
                command.jsonOut = text.value();
                haveJson = true;
            } else if (arg == "--frames") {
                auto frames = parseFrameList(text.value());
                if (!frames) return frames.error();
                command.frames = frames.value();
            } else {
                auto mode = parsePositionChannels(text.value());
                if (!mode) return mode.error();
                command.positionChannels = mode.value();
            }
        } else if (arg.starts_with("-")) {
            return usage("unknown option '" + arg + "' for 'bvh bake'");
        } else if (command.file.empty()) {
            command.file = arg;
        } else {
            return usage("'bvh bake' takes one FILE, got a second: '" + arg + "'");
        }
    }
    if (command.file.empty()) return usage("'bvh bake' needs a BVH FILE");
    if (!haveJson) return usage("'bvh bake' needs --json OUT (or --json - for stdout)");
    return Command{command};
}

Result<Command> parseBench(ArgCursor cursor) {
    BvhBenchCommand command;
    while (!cursor.done()) {
        const std::string& arg = cursor.take();
        if (arg == "--repeat") {
            auto text = cursor.value(arg);
            if (!text) return text.error();
            const auto repeat = parseWhole<int>(text.value());
            if (!repeat || *repeat < 1 || *repeat > 100000)
                return usage("--repeat takes a count from 1 to 100000, not '" + text.value() + "'");
            command.repeat = *repeat;
        } else if (arg.starts_with("-")) {
            return usage("unknown option '" + arg + "' for 'bvh bench'");
        } else {
            command.files.push_back(arg);
        }
    }
    return Command{command};
}

}  // namespace

Result<Command> parseCommandLine(std::span<const std::string> args) {
    if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") return Command{HelpCommand{kMainHelp}};
    if (args[0] == "--version") return Command{VersionCommand{}};
    if (args[0] == "render")
        return wantsHelp(args.subspan(1)) ? Command{HelpCommand{kRenderHelp}} : detail::parseRender(args.subspan(1));
    if (args[0] == "demo")
        return wantsHelp(args.subspan(1)) ? Command{HelpCommand{kDemoHelp}} : detail::parseDemo(args.subspan(1));
    if (args[0] == "bench")
        return wantsHelp(args.subspan(1)) ? Command{HelpCommand{kCrowdBenchHelp}} : detail::parseBench(args.subspan(1));
    if (args[0] == "devices") {
        if (wantsHelp(args.subspan(1))) return Command{HelpCommand{kDevicesHelp}};
        if (args.size() > 1) return usage("'devices' takes no arguments");
        return Command{DevicesCommand{}};
    }
    if (args[0] == "bvh") {
        if (args.size() < 2) return usage("'bvh' needs a subcommand: info, bake or bench");
        const std::string& sub = args[1];
        const auto rest = args.subspan(2);
        if (sub == "info") return wantsHelp(rest) ? Command{HelpCommand{kInfoHelp}} : parseInfo(ArgCursor(rest));
        if (sub == "bake") return wantsHelp(rest) ? Command{HelpCommand{kBakeHelp}} : parseBake(ArgCursor(rest));
        if (sub == "bench") return wantsHelp(rest) ? Command{HelpCommand{kBenchHelp}} : parseBench(ArgCursor(rest));
        if (sub == "--help" || sub == "-h") return Command{HelpCommand{kMainHelp}};
        return usage("unknown 'bvh' subcommand '" + sub + "'");
    }
    return usage("unknown command '" + args[0] + "'");
}

}  // namespace throng::app
