// `throng render`, `throng demo` and `throng devices`: their options and checks, and the
// crowd-shaping options that `throng simulate` shares with them.
#include <algorithm>
#include <cstdint>
#include <memory>

#include "cli_internal.h"
#include "demo_tuning.h"
#include "output.h"
#include "throng/render/video.h"
#include "throng/viewer/controls.h"

namespace throng::app::detail {

std::vector<std::string> modeNames() {
    std::vector<std::string> names;
    for (const crowd::Mode mode : {crowd::Mode::Group, crowd::Mode::Goals, crowd::Mode::Avoid}) names.emplace_back(crowd::modeName(mode));
    return names;
}

std::vector<std::string> renderPathNames() {
    std::vector<std::string> names;
    for (const render::RenderPath path : render::kRenderPaths) names.emplace_back(render::renderPathName(path));
    return names;
}

namespace {

CameraSpec parseCamera(const std::string& text) {
    std::vector<float> values;
    for (const std::string_view item : splitList(text)) {
        const std::optional<float> value = parseNumber<float>(item);
        if (!value) {
            values.clear();
            break;
        }
        values.push_back(*value);
    }
    if (values.size() != 6 && values.size() != 7)
        refuse("--camera takes EX,EY,EZ,TX,TY,TZ[,FOV] (eye, target in metres; vertical field of view in degrees), not '" +
               text + "'");
    for (std::size_t i = 0; i < 6; ++i)
        if (!range::isCoordinate(values[i]))
            refuse(std::string("--camera takes eye and target coordinates ") + range::kCoordinateText + ", not '" + text + "'");
    CameraSpec camera{{values[0], values[1], values[2]}, {values[3], values[4], values[5]}, 35.0F};
    if (values.size() == 7) camera.verticalFovDegrees = values[6];
    if (!(camera.verticalFovDegrees > 1.0F && camera.verticalFovDegrees < 170.0F))
        refuse("--camera field of view must be between 1 and 170 degrees");
    if (glm::length(camera.eye - camera.target) < 1e-3F) refuse("--camera eye and target must differ");
    return camera;
}

glm::vec2 parseArea(const std::string& text) {
    const std::string_view all = text;
    const std::size_t x = all.find('x');
    constexpr auto kSmallest = static_cast<float>(range::kMinSize), kLargest = static_cast<float>(range::kMaxSize);
    const std::optional<float> width = parseBounded(all.substr(0, x), kSmallest, kLargest);
    const std::optional<float> depth = x == std::string_view::npos ? std::nullopt : parseBounded(all.substr(x + 1), kSmallest, kLargest);
    if (!width || !depth)
        refuse("--area takes WIDTHxDEPTH in metres, each " + std::string(range::kSizeText) + " (e.g. 40x30), not '" + text + "'");
    return {*width, *depth};
}

// What decides which characters there are; a scene file decides that itself.
void addCrowdMembers(CLI::App& app, CrowdOptions& crowd) {
    addClipOption(app, crowd.clips, "A clip to animate; repeat for several\n(default: the project's locomotion set, see --locomotion)");
    addLocomotionOptions(app, crowd.locomotion, crowd.speed, "default without --bvh: assets/idle.bvh,\nslow_walk.bvh, walk.bvh, run.bvh");
    addNumber(app, "-n,--characters", crowd.characters, kCharactersRule, "Crowd size, 1 to " + std::to_string(kMaxCharacters));
    app.add_option_function<std::string>(
           "--mode",
           [&crowd](const std::string& text) {
               const std::optional<crowd::Mode> mode = crowd::modeFromName(text);
               if (!mode) refuse("--mode takes " + orList(modeNames()) + ", not '" + text + "'");
               crowd.mode = *mode;
           },
           "group (the paper's: one shared heading), goals (each to\n"
           "its own goal) or avoid (goals plus collision avoidance)")
        ->type_name("MODE")
        ->default_str(crowd::modeName(crowd.mode));
    app.add_option_function<std::string>(
           "--area", [&crowd](const std::string& text) { crowd.area = parseArea(text); },
           "Spawn and goal area in metres (default: grows with the crowd)")
        ->type_name("WxD");
}

void addRenderPath(CLI::App& app, render::RenderPath& target) {
    app.add_option_function<std::string>(
           "--path",
           [&target](const std::string& text) {
               const std::optional<render::RenderPath> path = render::renderPathFromName(text);
               if (!path) refuse("--path takes " + orList(renderPathNames()) + ", not '" + text + "'");
               target = *path;
           },
           "How joints reach the screen. compute: compute pass + sphere\n"
           "meshes; fast: culling compute pass + ray-cast point sprites;\n"
           "paper: no compute pass, the vertex shader reads the baked\n"
           "table; cpu: joints resolved on the CPU each frame;\n"
           "visibility: the fast path's culling, then bodies splatted by\n"
           "compute passes and shaded in one full-screen pass (one sample,\n"
           "rims smoothed analytically; one storage buffer's crowd at most).\n"
           "Default: for skin and auto bodies, visibility on a CPU device\n"
           "(fast for a crowd past one storage buffer) and fast on a GPU;\n"
           "for bones, fast; for spheres, compute. In the demo: visibility\n"
           "on a CPU device (bones alone: fast), fast on a GPU")
        ->type_name("PATH");
}

// The options `throng render` and `throng demo` share.
void addCrowdOptions(CLI::App& app, CrowdOptions& crowd, const std::string& imageWhat) {
    addCrowdShapeOptions(app, crowd);
    addTime(app, crowd.time, false, "Simulated seconds before the first frame, 0 to " + std::to_string(static_cast<int>(kMaxTimeSeconds)));
    addImageSize(app, crowd.width, crowd.height, imageWhat);
    addText(app, "--device", crowd.device, "NAME",
            "Pick the Vulkan device whose name contains NAME\n(see 'throng devices')");
    app.add_option_function<std::string>(
           "--camera", [&crowd](const std::string& text) { crowd.camera = parseCamera(text); },
           "Eye and target in metres, vertical field of view in degrees\n(default: frame the crowd)")
        ->type_name("EX,EY,EZ,TX,TY,TZ[,FOV]");
    addMsaa(app, crowd.msaa, "Multisampling: 1, 2, 4 or 8; lowered to what the device has");
    addRenderPath(app, crowd.path);
    addNumber(app, "--lod-pixels", crowd.lodPixels, kLodPixelsRule,
              "fast path: characters under N pixels tall draw only their\nmajor joints; 0 turns level of detail off");
    app.add_option_function<std::string>(
           "--body",
           [&crowd](const std::string& text) {
               const std::optional<render::Body> body = render::bodyFromName(text);
               if (!body) refuse("--body takes spheres, bones, skin or auto, not '" + text + "'");
               crowd.body = *body;
           },
           "What a character is drawn as. spheres: a sphere per joint\n"
           "(the paper's look, every path); bones: a tapered capsule per\n"
           "bone, sized by body part, ray-cast; skin: a mesh generated\n"
           "from the bones, skinned on the GPU; auto: skin for characters\n"
           "at least 140 pixels tall, bones down to 24, joint spheres for\n"
           "smaller ones. bones, skin and auto are drawn by the fast and\n"
           "visibility paths (see --path). Without --body: auto, or spheres\n"
           "when --path paper, cpu or compute or --dump-instances is given")
        ->type_name("BODY")
        ->default_str("auto");
    app.add_option_function<std::string>(
           "--view",
           [&crowd](const std::string& text) {
               if (text != "street" && text != "overview") refuse("--view takes street or overview, not '" + text + "'");
               crowd.view = text == "street" ? DefaultView::Street : DefaultView::Overview;
           },
           "The first view when no --camera is given. street: across the\n"
           "crowd from a raised pedestrian's or a balcony's height;\n"
           "overview: the whole crowd from above at an angle")
        ->type_name("VIEW")
        ->default_str("street");
    app.add_flag("--validation", crowd.validation,
                 "Enable the Khronos validation layer; any message fails\n"
                 "the run (exit 1). THRONG_VALIDATION=1 does the same");
}

}  // namespace

void addCrowdShapeOptions(CLI::App& app, CrowdOptions& crowd) {
    addCrowdMembers(app, crowd);
    addText(app, "--scene", crowd.scene, "FILE.json",
            "Clips, groups, goals and camera from a scene file (see README);\n"
            "excludes --bvh, --characters, --mode, --area, --locomotion\nand --speed");
    addTrajectoryOptions(app, crowd);
    addNumber(app, "--seed", crowd.seed, NumberRule<std::uint64_t>{0, UINT64_MAX, "--seed takes a non-negative whole number"},
              "Crowd layout, start frames and colours (default 1, or the scene's)");
    addNumber(app, "--threads", crowd.threads, kThreadsRule, "Simulation threads (default: all cores)")->default_str("");
}

CLI::Option* addTime(CLI::App& app, double& seconds, bool positive, const std::string& description) {
    const std::string most = std::to_string(static_cast<int>(kMaxTimeSeconds));
    const NumberRule<double> rule = positive ? NumberRule<double>{kPositive<double>, kMaxTimeSeconds,
                                                                  "--time takes seconds, more than 0 and at most " + most}
                                             : NumberRule<double>{0.0, kMaxTimeSeconds, "--time takes seconds from 0 to " + most};
    return addNumber(app, "--time", seconds, rule, description)->type_name("SECONDS");
}

std::optional<Error> sceneConflicts(const CLI::App& app, bool scene, const std::vector<std::string>& replaced) {
    const bool given = std::any_of(replaced.begin(), replaced.end(), [&](const std::string& name) { return app.count(name) > 0; });
    if (!scene || !given) return std::nullopt;
    return usage("--scene describes the clips and the crowd; don't combine it with " + orList(replaced), app);
}

// Bone and skinned bodies are drawn by the fast path: it becomes the default, and another --path
// is refused. With no --body, a sphere-only choice (another --path, --dump-instances) keeps the
// paper's joint spheres, so scripts written before auto became the default run as they did.
std::optional<Error> chooseBodyPath(const CLI::App& app, CrowdOptions& crowd, bool wantsSpheres) {
    const bool drawsBodies = crowd.path == render::RenderPath::Fast || crowd.path == render::RenderPath::Visibility;
    if (app.count("--body") == 0 && (wantsSpheres || (app.count("--path") > 0 && !drawsBodies)))
        crowd.body = render::Body::Spheres;
    if (crowd.body == render::Body::Spheres) return std::nullopt;
    if (app.count("--path") > 0 && !drawsBodies)
        return usage("--body " + std::string(render::bodyName(crowd.body)) + " is drawn by the fast and visibility paths: give --path fast or visibility, or leave --path out", app);
    if (app.count("--path") == 0) crowd.path = render::RenderPath::Fast;
    return std::nullopt;
}

std::optional<Error> crowdConflicts(const CLI::App& app, const CrowdOptions& crowd) {
    if (auto conflict = trajectoryConflicts(app, crowd)) return conflict;
    if (auto conflict = sceneConflicts(app, crowd.scene.has_value(), {"--bvh", "--characters", "--mode", "--area", "--locomotion", "--speed"}))
        return conflict;
    return locomotionConflicts(app, crowd.clips, crowd.locomotion, crowd.speed.has_value(), crowd.clips.empty(),
                               "(--locomotion, or no --bvh for the project's own); a --bvh clip plays at its own pace");
}

std::function<std::string(const std::string&)> optionsOnly(const std::string& name) {
    return [name](const std::string& word) { return "'" + name + "' takes options only, got '" + word + "'"; };
}

CommandDefinition defineRender(CLI::App& parent, ParseState& state) {
    auto command = std::make_shared<RenderCommand>();
    CLI::App* app = addCommand(parent, "render", "Render the crowd offscreen to a PNG, or with --duration to a video (headless; lavapipe works).",
                               state);
    app->footer("Writes its output atomically: a failed run leaves no file behind.");
    addText(*app, "-o,--out", command->out, "FILE",
            "What to write (required): a PNG (- writes it to stdout);\nwith --duration an MP4, a GIF or a frame pattern such as\nframes/%05d.png",
            "--out needs a file name");
    addCrowdOptions(*app, command->crowd, "Image");
    addText(*app, "--dump-instances", command->dumpInstances, "FILE.json",
            "Also write the GPU-resolved joint positions of every\ncharacter as JSON");
    addText(*app, "--dump-bodies", command->dumpBodies, "FILE.json",
            "With --body bones, skin or auto: also write, per character,\n"
            "the level it was drawn at, its height on screen and its\n"
            "bones as drawn, as JSON");
    addVideoOptions(*app, *command);
    return {app,
            [app, command]() -> Result<Command> {
                if (auto conflict = crowdConflicts(*app, command->crowd)) return *conflict;
                if (auto conflict = videoConflicts(*app, *command)) return *conflict;
                if (auto conflict = chooseBodyPath(*app, command->crowd, command->dumpInstances.has_value())) return *conflict;
                if (command->dumpInstances && command->crowd.body != render::Body::Spheres)
                    return usage("--dump-instances writes joint spheres: give --body spheres with it (its default when --body is not given)", *app);
                if (command->dumpBodies && command->crowd.body == render::Body::Spheres)
                    return usage("--dump-bodies writes bone and skinned bodies: give --body bones, skin or auto with it (--dump-instances for spheres)", *app);
                if (command->out.empty()) return usage("'render' needs --out FILE.png", *app);
                command->choosePath = app->count("--path") == 0;
                return Command{*command};
            },
            optionsOnly("render")};
}


CommandDefinition defineDemo(CLI::App& parent, ParseState& state) {
    auto command = std::make_shared<DemoCommand>();
    command->crowd.path = render::RenderPath::Fast;  // the demo is interactive; --path still chooses
    CLI::App* app = addCommand(parent, "demo", "Open a window and watch the crowd (needs a display).", state);
    app->footer(viewer::controlsHelpText());  // the same table the window and the HUD read
    addCrowdOptions(*app, command->crowd, "Window");
    // On a CPU device the demo picks a smaller crowd and no multisampling (tuneForDevice).
    app->get_option("--characters")->default_str(std::to_string(command->crowd.characters) + "; " + std::to_string(kCpuDemoCharacters) + " on a CPU device");
    app->get_option("--msaa")->default_str(std::to_string(command->crowd.msaa) + "; " + std::to_string(kCpuDemoMsaa) + " on a CPU device");
    app->add_flag_callback("--no-vsync", [command] { command->vsync = false; },
                           "Present with MAILBOX or IMMEDIATE instead of FIFO,\nwhere supported");
    addNumber(*app, "--frames", command->frames, NumberRule<int>{1, 10'000'000, "--frames takes a count from 1"},
              "Run N frames (fixed 1/60 s steps) and exit 0 (default: until closed)")
        ->default_str("");
    addText(*app, "--screenshot", command->screenshot, "FILE.png", "With --frames: save the last frame",
            "--screenshot needs a file name");
    app->add_flag("--script-resize", command->scriptResize, "With --frames: resize the window a few times");
    app->add_flag("--hide-ui", command->hideUi, "Start with the HUD hidden (F1 or H shows it)");
    addText(*app, "--record", command->record, "FILE.mp4",
            "Record what the window shows from the first frame, to\nFILE.mp4, FILE.gif or DIR/%05d.png (R stops; R again records to\nthrong-recording-N.mp4)",
            "--record needs a file name");
    return {app,
            [app, command]() -> Result<Command> {
                if (auto conflict = crowdConflicts(*app, command->crowd)) return *conflict;
                if (auto conflict = chooseBodyPath(*app, command->crowd, false)) return *conflict;
                // Without these options the demo picks what suits the device (see runDemo).
                command->tuneCharacters = app->count("--characters") == 0 && !command->crowd.scene && !command->crowd.trajectories;
                command->tuneMsaa = app->count("--msaa") == 0;
                command->tunePath = app->count("--path") == 0;
                if (command->screenshot && command->frames == 0)
                    return usage("--screenshot saves the last frame of a scripted run: give --frames N too "
                                 "(P saves one interactively)",
                                 *app);
                if (command->scriptResize && command->frames == 0) return usage("--script-resize needs --frames N", *app);
                if (command->record && !render::videoKindOf(*command->record))
                    return usage("--record writes a video: give FILE.mp4, FILE.gif or a frame pattern such as frames/%05d.png, not '" +
                                     *command->record + "'", *app);
                if (command->record)
                    if (auto problem = render::videoPathProblem(*command->record)) return usage("--record: " + *problem, *app);
                if (command->screenshot && !namesPngImage(*command->screenshot))
                    return usage("--screenshot writes PNG images only: give a FILE.png, not '" + *command->screenshot + "'", *app);
                return Command{*command};
            },
            optionsOnly("demo")};
}

CommandDefinition defineDevices(CLI::App& parent, ParseState& state) {
    CLI::App* app = addCommand(parent, "devices", "List the Vulkan devices.", state);
    app->footer("Lists the Vulkan devices with their type, API version and driver.");
    return {app, []() -> Result<Command> { return Command{DevicesCommand{}}; },
            [](const std::string&) { return std::string("'devices' takes no arguments"); }};
}

}  // namespace throng::app::detail
