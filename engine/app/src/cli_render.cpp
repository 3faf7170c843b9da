// Parsing of `throng render` and `throng devices`; see cli.cpp for the shared helpers' twins.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "cli_internal.h"

namespace throng::app::detail {
namespace {

template <typename Number>
std::optional<Number> parseNumber(const std::string& text) {
    Number value{};
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

Result<CameraSpec> parseCamera(const std::string& text) {
    std::vector<float> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const auto value = parseNumber<float>(text.substr(start, comma - start));
        if (!value || !std::isfinite(*value)) break;
        values.push_back(*value);
        start = comma + 1;
    }
    if ((values.size() != 6 && values.size() != 7) || start <= text.size())
        return usage("--camera takes EX,EY,EZ,TX,TY,TZ[,FOV] (eye, target in metres; vertical field of view in degrees), not '" +
                     text + "'");
    CameraSpec camera{{values[0], values[1], values[2]}, {values[3], values[4], values[5]}, 35.0F};
    if (values.size() == 7) camera.verticalFovDegrees = values[6];
    if (!(camera.verticalFovDegrees > 1.0F && camera.verticalFovDegrees < 170.0F))
        return usage("--camera field of view must be between 1 and 170 degrees");
    if (glm::length(camera.eye - camera.target) < 1e-3F) return usage("--camera eye and target must differ");
    return camera;
}

}  // namespace

// Options shared by render and demo. Returns false when `option` isn't one of them.
Result<bool> parseCrowdOption(const std::string& option, const std::string& value, CrowdOptions& command) {
    if (option == "--bvh") {
        command.clips.push_back(value);
    } else if (option == "--scene") {
        command.scene = value;
    } else if (option == "--mode") {
        const auto mode = crowd::modeFromName(value);
        if (!mode) return usage("--mode takes group, goals or avoid, not '" + value + "'");
        command.mode = *mode;
    } else if (option == "--area") {
        const std::size_t x = value.find('x');
        const auto w = parseNumber<float>(value.substr(0, x));
        const auto d = x == std::string::npos ? std::nullopt : parseNumber<float>(value.substr(x + 1));
        if (!w || !d || !(*w > 0 && *d > 0 && *w <= 100000 && *d <= 100000))
            return usage("--area takes WIDTHxDEPTH in metres (e.g. 40x30), not '" + value + "'");
        command.area = glm::vec2(*w, *d);
    } else if (option == "--threads") {
        const auto threads = parseNumber<unsigned>(value);
        if (!threads || *threads < 1 || *threads > 256) return usage("--threads takes 1 to 256, not '" + value + "'");
        command.threads = *threads;
    } else if (option == "--characters") {
        const auto n = parseNumber<long long>(value);
        if (!n || *n < 1 || *n > kMaxCharacters)
            return usage("--characters takes a count from 1 to " + std::to_string(kMaxCharacters) + ", not '" + value + "'");
        command.characters = static_cast<int>(*n);
    } else if (option == "--time") {
        const auto t = parseNumber<double>(value);
        if (!t || !(*t >= 0.0 && *t <= kMaxTimeSeconds))
            return usage("--time takes seconds from 0 to " + std::to_string(static_cast<int>(kMaxTimeSeconds)) + ", not '" + value + "'");
        command.time = *t;
    } else if (option == "--width" || option == "--height") {
        const auto side = parseNumber<long long>(value);
        if (!side || *side < 16 || *side > static_cast<long long>(kMaxImageSide))
            return usage(option + " takes pixels from 16 to " + std::to_string(kMaxImageSide) + ", not '" + value + "'");
        (option == "--width" ? command.width : command.height) = static_cast<std::uint32_t>(*side);
    } else if (option == "--seed") {
        const auto seed = parseNumber<std::uint64_t>(value);
        if (!seed) return usage("--seed takes a non-negative whole number, not '" + value + "'");
        command.seed = *seed;
    } else if (option == "--device") {
        command.device = value;
    } else if (option == "--camera") {
        auto camera = parseCamera(value);
        if (!camera) return camera.error();
        command.camera = camera.value();
    } else if (option == "--lod-pixels") {
        const auto pixels = parseNumber<float>(value);
        if (!pixels || !(*pixels >= 0.0F && *pixels <= 100000.0F)) return usage("--lod-pixels takes 0 (off) or a height in pixels, not '" + value + "'");
        command.lodPixels = *pixels;
    } else if (option == "--path") {
        const auto path = render::renderPathFromName(value);
        if (!path) return usage("--path takes " + render::renderPathList() + ", not '" + value + "'");
        command.path = *path;
    } else if (option == "--msaa") {
        const auto samples = parseNumber<std::uint32_t>(value);
        if (!samples || (*samples != 1 && *samples != 2 && *samples != 4 && *samples != 8))
            return usage("--msaa takes 1, 2, 4 or 8, not '" + value + "'");
        command.msaa = *samples;
    } else {
        return false;
    }
    return true;
}

namespace {

// Walks `args`: flags without values first, then options with one value, shared ones last.
template <typename Command, typename Flag, typename Own>
Result<Command> parseWithCrowd(std::span<const std::string> args, const char* name, Flag&& flag, Own&& own) {
    Command command;
    bool crowdShape = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& option = args[i];
        if (option == "--validation") {
            command.crowd.validation = true;
            continue;
        }
        if (flag(option, command)) continue;
        if (!option.starts_with("--")) return usage(std::string("'") + name + "' takes options only, got '" + option + "'");
        if (i + 1 >= args.size()) return usage("option " + option + " needs a value");
        const std::string& value = args[++i];
        if (option == "--bvh" || option == "--characters" || option == "--mode" || option == "--area") crowdShape = true;
        auto shared = parseCrowdOption(option, value, command.crowd);
        if (!shared) return shared.error();
        if (shared.value()) continue;
        auto mine = own(option, value, command);
        if (!mine) return mine.error();
        if (!mine.value()) return usage("unknown option '" + option + "' for '" + name + "'");
    }
    if (command.crowd.scene && crowdShape)
        return usage("--scene describes the clips and the crowd; don't combine it with --bvh, --characters, --mode or --area");
    return command;
}

}  // namespace

Result<Command> parseRender(std::span<const std::string> args) {
    auto parsed = parseWithCrowd<RenderCommand>(
        args, "render", [](const std::string&, RenderCommand&) { return false; },
        [](const std::string& option, const std::string& value, RenderCommand& command) -> Result<bool> {
            if (option == "--dump-instances") {
                command.dumpInstances = value;
            } else if (option == "--out") {
                if (value.empty()) return usage("--out needs a file name");
                command.out = value;
            } else {
                return false;
            }
            return true;
        });
    if (!parsed) return parsed.error();
    if (parsed.value().out.empty()) return usage("'render' needs --out FILE.png");
    return Command{parsed.value()};
}

Result<Command> parseDemo(std::span<const std::string> args) {
    // The demo is interactive, so it defaults to the fast path; --path still chooses.
    const bool pathGiven = std::find(args.begin(), args.end(), std::string("--path")) != args.end();
    auto parsed = parseWithCrowd<DemoCommand>(
        args, "demo",
        [](const std::string& option, DemoCommand& command) {
            if (option == "--no-vsync") command.vsync = false;
            else if (option == "--script-resize") command.scriptResize = true;
            else return false;
            return true;
        },
        [](const std::string& option, const std::string& value, DemoCommand& command) -> Result<bool> {
            if (option == "--frames") {
                const auto n = parseNumber<int>(value);
                if (!n || *n < 1 || *n > 10'000'000) return usage("--frames takes a count from 1, not '" + value + "'");
                command.frames = *n;
            } else if (option == "--screenshot") {
                if (value.empty()) return usage("--screenshot needs a file name");
                command.screenshot = value;
            } else {
                return false;
            }
            return true;
        });
    if (!parsed) return parsed.error();
    if (parsed.value().screenshot && parsed.value().frames == 0)
        return usage("--screenshot saves the last frame of a scripted run: give --frames N too (P saves one interactively)");
    if (parsed.value().scriptResize && parsed.value().frames == 0) return usage("--script-resize needs --frames N");
    if (!pathGiven) parsed.value().crowd.path = render::RenderPath::Fast;
    return Command{parsed.value()};
}

Result<Command> parseBench(std::span<const std::string> args) {
    BenchCommand command;
    const auto list = [](const std::string& value) {
        std::vector<std::string> items;
        for (std::size_t start = 0; start <= value.size();) {
            const std::size_t comma = std::min(value.find(',', start), value.size());
            items.push_back(value.substr(start, comma - start));
            start = comma + 1;
        }
        return items;
    };
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& option = args[i];
        if (option == "--sim-only") {
            command.simOnly = true;
            continue;
        }
        if (!option.starts_with("--")) return usage("'bench' takes options only, got '" + option + "'");
        if (i + 1 >= args.size()) return usage("option " + option + " needs a value");
        const std::string& value = args[++i];
        if (option == "--characters") {
            for (const std::string& item : list(value)) {
                const auto n = parseNumber<int>(item);
                if (!n || *n < 1 || *n > kMaxCharacters)
                    return usage("--characters takes a list of counts from 1 to " + std::to_string(kMaxCharacters) + ", not '" + value + "'");
                command.characters.push_back(*n);
            }
        } else if (option == "--modes") {
            command.modes = list(value);
        } else if (option == "--frames" || option == "--warmup") {
            const auto n = parseNumber<int>(value);
            if (!n || *n < (option == "--frames" ? 1 : 0) || *n > 100000) return usage(option + " takes a count up to 100000, not '" + value + "'");
            (option == "--frames" ? command.frames : command.warmup) = *n;
        } else if (option == "--threads") {
            const auto threads = parseNumber<unsigned>(value);
            if (!threads || *threads < 1 || *threads > 256) return usage("--threads takes 1 to 256, not '" + value + "'");
            command.threads = *threads;
        } else if (option == "--width" || option == "--height") {
            const auto side = parseNumber<std::uint32_t>(value);
            if (!side || *side < 16 || *side > kMaxImageSide) return usage(option + " takes pixels from 16 to 8192, not '" + value + "'");
            (option == "--width" ? command.width : command.height) = *side;
        } else if (option == "--msaa") {
            const auto samples = parseNumber<std::uint32_t>(value);
            if (!samples || (*samples != 1 && *samples != 2 && *samples != 4 && *samples != 8)) return usage("--msaa takes 1, 2, 4 or 8");
            command.msaa = *samples;
        } else if (option == "--device") {
            command.device = value;
        } else if (option == "--lod-pixels") {
            const auto pixels = parseNumber<float>(value);
            if (!pixels || !(*pixels >= 0.0F && *pixels <= 100000.0F)) return usage("--lod-pixels takes 0 (off) or a height in pixels");
            command.lodPixels = *pixels;
        } else if (option == "--bvh") {
            command.clips.push_back(value);
        } else if (option == "--csv") {
            command.csv = value;
        } else if (option == "--json") {
            command.json = value;
        } else {
            return usage("unknown option '" + option + "' for 'bench'");
        }
    }
    for (const std::string& mode : command.modes) {
        if (command.simOnly && !crowd::modeFromName(mode)) return usage("--modes takes group, goals, avoid with --sim-only, not '" + mode + "'");
        if (command.simOnly) continue;
        const auto path = render::renderPathFromName(mode);
        if (!path) return usage("--modes takes " + render::renderPathList() + ", not '" + mode + "'");
        command.paths.push_back(*path);
    }
    if (!command.simOnly && command.paths.empty()) command.paths.assign(render::kRenderPaths.begin(), render::kRenderPaths.end());
    if (command.characters.empty())
        command.characters = command.simOnly ? std::vector<int>{1000, 10000, 100000} : std::vector<int>{250, 500, 1000, 2000, 4000, 8000};
    if (command.modes.empty())
        command.modes = command.simOnly ? std::vector<std::string>{"group", "goals", "avoid"}
                                        : std::vector<std::string>{"paper", "cpu", "compute", "fast"};
    if (command.frames == 0) command.frames = command.simOnly ? 30 : 20;
    if (command.warmup < 0) command.warmup = command.simOnly ? 10 : 3;
    return Command{command};
}

}  // namespace throng::app::detail
