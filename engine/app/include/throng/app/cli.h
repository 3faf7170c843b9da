#pragma once
// Command-line parsing for `throng`, as a pure function from arguments to a Command value:
// no globals and no I/O but one look-up (whether a `--bvh` argument names an existing file,
// so that a file name with ':' in it stays a path), so every flag combination is unit-testable.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "throng/core/error.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/baked_clip.h"
#include "throng/render/render_path.h"

namespace throng::app {

/// `throng bvh info FILE [--json OUT|-] [bake options]`
struct BvhInfoCommand {
    std::string file;
    /// --position-channels, --units, --loop, --keep-first-frame, --up, --root, --straighten,
    /// --no-foot-lock.
    motion::BakeOptions bake;
    std::optional<std::string> jsonOut;    ///< Also write the summary as JSON ("-" for stdout).
};

/// `throng bvh bake FILE --json OUT|- [--frames all|LIST] [--position-channels replace|add]`
struct BvhBakeCommand {
    std::string file;
    std::string jsonOut;                   ///< Path, or "-" for stdout.
    std::optional<std::vector<int>> frames;  ///< nullopt means every frame.
    motion::PositionChannels positionChannels = motion::PositionChannels::Replace;
};

/// `throng bvh bench [FILE...] [--repeat N]`: parse and bake timings (a benchmark, not a test).
struct BvhBenchCommand {
    std::vector<std::string> files;        ///< Empty means the default clip.
    int repeat = 15;                       ///< Timed repetitions per file; the median is reported.
};

/// A camera given on the command line: `--camera EX,EY,EZ,TX,TY,TZ[,FOV]`.
struct CameraSpec {
    glm::vec3 eye{0.0F};
    glm::vec3 target{0.0F};
    float verticalFovDegrees = 35.0F;
};

/// The first view when no camera is given (--view).
enum class DefaultView : std::uint8_t {
    Street,    ///< Across the crowd from a raised pedestrian's or a balcony's height (render::streetCamera).
    Overview,  ///< The whole crowd from above at an angle (render::frameCrowd).
};

/// Limits that keep a typo from asking for a terabyte; beyond them input is refused (exit 2).
/// The world's ranges are stated once, in throng/core/supported_range.h.
inline constexpr int kMaxCharacters = range::kMaxCharacters;
inline constexpr std::uint32_t kMaxImageSide = 8192;
inline constexpr double kMaxTimeSeconds = range::kMaxTimeSeconds;

/// One clip to load and how to bake it: `--bvh FILE[:key=value,...]` on the command line, or
/// one entry of a scene file's "clips" (see clip_spec.h for the keys).
struct ClipSpec {
    std::string path;          ///< The BVH file.
    motion::BakeOptions bake;  ///< This clip's overrides; BakeOptions' defaults where none is given.
};

/// Crowd, camera and device options shared by `throng render` and `throng demo`. `throng
/// simulate` reads only what shapes the crowd (clips, set, speeds, scene, size, mode, area,
/// seed, threads); the rest keeps its defaults there.
struct CrowdOptions {
    std::vector<ClipSpec> clips;             ///< --bvh, repeatable; empty (and no --locomotion) means the project's own set.
    std::vector<ClipSpec> locomotion;        ///< --locomotion FILE,FILE,...: one set the crowd blends by speed.
    std::optional<glm::vec2> speed;          ///< --speed MIN[:MAX]: desired ground speeds, m/s (needs a set).
    std::optional<std::string> scene;        ///< --scene FILE.json (excludes --bvh, --characters, --mode, --area).
    /// --trajectories FILE: one character per track of another tool's trajectories, following
    /// it (excludes --scene, --bvh, --characters, --mode, --area and --speed).
    std::optional<std::string> trajectories;
    crowd::TrajectoryOptions trajectoryReading;  ///< --trajectory-axes, --trajectory-units, --trajectory-fps.
    int characters = 2000;                   ///< --characters, 1..kMaxCharacters.
    crowd::Mode mode = crowd::Mode::Group;   ///< --mode group|goals|avoid.
    std::optional<glm::vec2> area;           ///< --area WxD metres; default grows with the crowd.
    double time = 0.0;                       ///< --time seconds of simulation before the (first) frame.
    std::uint32_t width = 1280, height = 720;  ///< --width, --height, 16..kMaxImageSide (window size for the demo).
    std::optional<std::uint64_t> seed;       ///< --seed (default 1, or the scene's).
    unsigned threads = 0;                    ///< --threads for the simulation; 0 = all cores.
    std::string device;                      ///< --device substring; empty picks the best device.
    std::optional<CameraSpec> camera;        ///< --camera; default: the --view.
    DefaultView view = DefaultView::Street;  ///< --view street|overview: the first view when no camera is given.
    std::uint32_t msaa = 4;                  ///< --msaa 1|2|4|8 (lowered to what the device has).
    bool validation = false;                 ///< --validation (or THRONG_VALIDATION=1).
    render::RenderPath path = render::RenderPath::Compute;  ///< --path: how joints reach the screen (the demo: Fast).
    float lodPixels = 48.0F;                 ///< --lod-pixels: fast path level of detail (0 turns it off).
    /// --body: what a character is drawn as. auto (skin, bones, spheres by screen size) unless a
    /// sphere-only choice is made without --body (--path paper|cpu|compute, --dump-instances):
    /// then the paper's joint spheres.
    render::Body body = render::Body::Auto;
};

/// `throng render ... --out FILE.png`: one headless frame of the crowd.
struct RenderCommand {
    CrowdOptions crowd;
    std::optional<std::string> dumpInstances;  ///< --dump-instances FILE.json.
    std::optional<std::string> dumpBodies;     ///< --dump-bodies FILE.json (bones, skin, auto).
    std::string out;                         ///< --out FILE.png (required); FILE.mp4 or a frame pattern (frames/%05d.png) with --duration.
    /// --duration SECONDS: a video of that length from --time on, to an MP4 or a frame pattern
    /// (render::videoKindOf); frame f shows time + f / fps, the crowd stepped 1/fps s between frames.
    std::optional<double> duration;
    int fps = 30;                            ///< --fps: video frames per second, 1..kMaxVideoFps.
    /// --frames A:B: only frames A to B (inclusive, 0-based) of the video, for renders split over
    /// jobs; the crowd is still stepped from frame 0, so the frames are those of a whole run.
    std::optional<std::pair<std::int64_t, std::int64_t>> frames;
    /// --camera-path FILE.json: the camera moves through the file's "camera_path" keyframes (a
    /// scene file, or one holding only them), by the crowd's clock; excludes --camera.
    std::optional<std::string> cameraPath;
    /// No --path given: the bodies' fast path gives way to the visibility path on a CPU device
    /// (app::emplaceOffscreen).
    bool choosePath = false;
    [[nodiscard]] std::int64_t frameCount() const;  ///< round(duration x fps), 0 without --duration.
};
inline constexpr int kMaxVideoFps = 240;

/// `throng demo ...`: the windowed, interactive demo.
struct DemoCommand {
    CrowdOptions crowd;
    int frames = 0;                          ///< --frames N: run N frames and exit 0; 0 runs until closed.
    std::optional<std::string> screenshot;   ///< --screenshot FILE.png: save the last frame.
    bool scriptResize = false;               ///< --script-resize: resize the window during a scripted run.
    bool vsync = true;                       ///< --no-vsync turns it off (MAILBOX or IMMEDIATE).
    bool hideUi = false;                     ///< --hide-ui: start with the HUD hidden (F1 or H shows it).
    std::optional<std::string> record;       ///< --record FILE.mp4|DIR/%05d.png: record from the first frame (R stops).
    /// Settings the user left at their defaults, which the demo may tune to the device (fewer
    /// characters, the visibility path and 1x MSAA on a CPU device). False once the option is given.
    bool tuneCharacters = true, tuneMsaa = true, tunePath = true;
};

/// Most samples per second `throng simulate` writes (--fps).
inline constexpr int kMaxSimulateFps = 1000;
/// Most rows in one CSV file of `throng simulate` (about 10 GB of trajectory rows); a run
/// that would write more is refused before it starts.
inline constexpr std::int64_t kMaxSimulateRows = 200'000'000;

/// `throng simulate [crowd options] --time T --fps F --out FILE.csv [--joints-out FILE.csv]`:
/// the crowd `throng render` would draw, stepped on the CPU (no Vulkan device) at 1/F s and
/// written as CSV, frames 0 (the spawn, time 0) to lastFrame().
struct SimulateCommand {
    CrowdOptions crowd;                    ///< The crowd-shaping options only (see CrowdOptions).
    double time = 0.0;                     ///< --time: seconds simulated, (0, kMaxTimeSeconds] (required).
    int fps = 0;                           ///< --fps: samples per second, 1..kMaxSimulateFps (required); the step is 1/fps s.
    /// --out FILE.csv (required; "-" is stdout): one row per character and frame; a follower of
    /// --trajectories has rows only while its track lasts, under its id in the file.
    std::string out;
    std::optional<std::string> jointsOut;  ///< --joints-out FILE.csv: one row per character, frame and joint.
    /// --format: what --out holds. Csv: Throng's own CSV; JuPedSim: the JuPedSim/PedPy text
    /// layout (ids from 1, a follower's its file's; ground x and -z as X and Y, Z 0), which PedPy
    /// and --trajectories read.
    enum class Format : std::uint8_t { Csv, JuPedSim } format = Format::Csv;
    /// The last frame written, round(time * fps); frame f is at f / fps seconds.
    [[nodiscard]] std::int64_t lastFrame() const;
};

/// `throng devices`: list the Vulkan devices.
struct DevicesCommand {};

/// `throng bench`: the rendering sweep (frame time per render path and crowd size), or with
/// --sim-only the crowd step per locomotion mode. --modes fills `paths` or, with --sim-only, `modes`.
struct BenchCommand {
    bool simOnly = false;                            ///< --sim-only: time Crowd::step instead of frames.
    bool noReadback = false;                         ///< --no-readback: frames end at the draw, as the probe's do.
    bool freshFrames = false;                        ///< --fresh-frames: nothing kept from the last frame (a moving camera's cost).
    bool overlapSimulation = false;                  ///< --overlap-simulation: the next frame's step runs while the GPU draws.
    /// --characters LIST (defaults differ per kind). With --scene: totals the scene's groups are
    /// scaled to (scaleScene); empty means the scene's own total.
    std::vector<int> characters;
    std::vector<render::RenderPath> paths;           ///< --modes LIST: render paths to sweep (empty with --sim-only)
    bool choosePath = false;                         ///< No --modes: each row draws with the path `throng render` picks for it
    /// --modes LIST with --sim-only: locomotion modes (valid names); with --scene only
    /// kSceneMode, as the scene's groups keep their own modes.
    std::vector<std::string> modes;
    /// --scene FILE.json: the crowd (clips, groups, sets, events, seed) from a scene file, as for
    /// `render`; excludes --bvh, --locomotion and --speed. Its camera is not used: every row frames the crowd.
    std::optional<std::string> scene;
    static constexpr std::string_view kSceneMode = "scene";  ///< The one --sim-only "mode" of a scene.
    /// --trajectories FILE (and how to read it): every row's crowd follows the file's tracks,
    /// as for render; rows of fewer characters take the first tracks. Excludes --scene, --bvh and --speed.
    std::optional<std::string> trajectories;
    crowd::TrajectoryOptions trajectoryReading;
    static constexpr std::string_view kFollowMode = "follow";  ///< The one --sim-only "mode" of trajectories.
    int frames = 0;                                  ///< --frames: timed frames or steps per row (0: default)
    int warmup = -1;                                 ///< --warmup: untimed first (-1: default)
    unsigned threads = 0;                            ///< --threads (simulation); 0 = all cores.
    std::vector<ClipSpec> clips;                     ///< --bvh; default clip when empty (and no --locomotion).
    std::vector<ClipSpec> locomotion;                ///< --locomotion FILE,...: a set every character blends by speed (not with --bvh).
    std::optional<glm::vec2> speed;                  ///< --speed MIN[:MAX]: desired ground speeds, m/s (needs --locomotion).
    std::uint32_t width = 1280, height = 720;        ///< --width, --height (render sweep)
    std::uint32_t msaa = 4;                          ///< --msaa (render sweep)
    std::string device;                              ///< --device (render sweep)
    float lodPixels = 48.0F;                         ///< --lod-pixels (render sweep, fast path)
    /// --body LIST: bodies to sweep; spheres on each path of --modes, the others on the fast path.
    std::vector<render::Body> bodies{render::Body::Spheres};
    std::optional<std::string> csv, json;            ///< --csv OUT|-, --json OUT|-
};

/// `--help`/`-h` anywhere, `throng help [COMMAND]`, or no arguments: print `text` to stdout and exit 0.
struct HelpCommand {
    std::string text;
};

struct VersionCommand {};

using Command = std::variant<HelpCommand, VersionCommand, BvhInfoCommand, BvhBakeCommand, BvhBenchCommand,
                             RenderCommand, DevicesCommand, BenchCommand, DemoCommand, SimulateCommand>;

/// Parses argv[1..]. Usage errors come back as BadInput errors: one line that ends with a hint
/// naming the help of the command concerned, e.g. "(see 'throng render --help')".
[[nodiscard]] Result<Command> parseCommandLine(std::span<const std::string> args);

}  // namespace throng::app
