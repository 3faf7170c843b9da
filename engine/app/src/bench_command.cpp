#include "bench_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "bench_motion.h"
#include "crowd_scene.h"
#include "output.h"
#include "path_choice.h"
#include "throng/core/log.h"
#include "throng/gpu/context.h"
#include "throng/motion/body_mesh.h"
#include "throng/render/offscreen.h"
#include "throng/render/scene_look.h"

#ifndef THRONG_BUILD_TYPE
#define THRONG_BUILD_TYPE "unknown"
#endif

namespace throng::app {
namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;
constexpr double kStep = 1.0 / 30.0;

// "bench: fast path, 2000 characters: 58.4 ms per frame (3/8, about 40 s left)"
class Progress {
public:
    explicit Progress(std::size_t rows) : rows_(rows), start_(Clock::now()) {}
    void starting(const std::string& row) const { log::report("bench: " + row + "..."); }
    void finished(const std::string& row, const std::string& result) {
        ++done_;
        const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
        const double left = elapsed / static_cast<double>(done_) * static_cast<double>(rows_ - done_);
        char eta[64];
        std::snprintf(eta, sizeof eta, " (%zu/%zu, about %.0f s left)", done_, rows_, left);
        log::report("bench: " + row + ": " + result + (done_ < rows_ ? eta : " (done)"));
    }

private:
    std::size_t rows_, done_ = 0;
    Clock::time_point start_;
};

double millisecondsSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }
// The clips of the bench's own crowd: the set of --locomotion, else the --bvh clips, else the project's walk.
std::vector<ClipSpec> benchClips(const BenchCommand& command) {
    if (!command.locomotion.empty()) return command.locomotion;
    return command.clips.empty() ? std::vector<ClipSpec>{{defaultClipPath(), {}}} : command.clips;
}

// The crowd as render would take it from these options: --scene, or the paper's crowd, where
// each character plays one clip (the project's walk by default) so figures stay comparable
// with earlier runs, or with --locomotion every one blends the set.
CrowdOptions benchOptions(const BenchCommand& command, int count, crowd::Mode mode) {
    CrowdOptions options;
    if (command.scene) {
        options.scene = command.scene;
    } else if (command.trajectories) {
        options.trajectories = command.trajectories;
        options.trajectoryReading = command.trajectoryReading;
        options.locomotion = command.locomotion;
    } else if (command.locomotion.empty()) {
        options.clips = benchClips(command);
    } else {
        options.locomotion = command.locomotion;
        options.speed = command.speed;
    }
    options.characters = count;
    options.mode = mode;
    options.threads = command.threads;
    return options;
}

// What every row starts from: the crowd described once, its clips baked and its sets checked
// (so a bad scene or set is refused before any device or row spends time), and the sizes the
// rows run: the command line's, or a scene's own total.
struct BenchSource {
    CrowdScene prepared;  ///< Not spawned.
    std::vector<int> sizes;
};

Result<BenchSource> prepareBench(const BenchCommand& command) {
    auto prepared = prepareCrowdScene(benchOptions(command, 1, crowd::Mode::Group));
    if (!prepared) return prepared.error();
    BenchSource source{std::move(prepared.value()), command.characters};
    if (source.sizes.empty()) source.sizes.push_back(static_cast<int>(source.prepared.plannedCharacters()));
    if (command.scene)
        for (const int count : source.sizes) {
            SceneDescription trial = source.prepared.description;
            if (auto refused = scaleScene(trial, count)) return *refused;
        }
    if (command.trajectories)
        for (const int count : source.sizes)
            if (count > source.prepared.plannedCharacters())
                return Error{Error::Kind::BadInput, "--characters " + std::to_string(count) + " is more than the " +
                                                        std::to_string(source.prepared.plannedCharacters()) + " tracks of " + *command.trajectories, {}};
    return source;
}

// One row's crowd, spawned at time 0 (where a scene's events at time 0 apply; every frame
// then steps before it renders).
Result<CrowdScene> crowdFor(const BenchCommand& command, const CrowdScene& source, int count, crowd::Mode mode) {
    if (!command.scene && !command.trajectories) return loadCrowdScene(benchOptions(command, count, mode), source.clips);
    // A scene keeps its groups' modes, sets and events, and trajectories their tracks (the
    // first `count`); only their sizes change.
    CrowdScene scene{source.description, source.clips, std::nullopt, {}};
    if (auto refused = scaleScene(scene.description, count)) return *refused;
    if (auto spawned = scene.respawn(0.0); !spawned) return spawned.error();
    return scene;
}

// Prints the table, then writes the CSV (after a "# caption" line) and JSON forms asked for.
// When either goes to stdout, the table goes to stderr so stdout holds only that format.
int emit(const BenchCommand& command, const std::string& baseCaption, const Table& table, Json header,
         std::span<const motion::BakedClip> clips) {
    const MotionNote motion = describeMotion(command, clips);
    const std::string caption = baseCaption + ", " + motion.caption;
    header.update(motion.fields);
    const bool stdoutTaken = command.csv == "-" || command.json == "-";
    std::fprintf(stdoutTaken ? stderr : stdout, "%s\n%s", caption.c_str(), table.text().c_str());
    if (command.csv)
        if (const int code = writeOutput(*command.csv, "# " + caption + "\n" + table.csv())) return code;
    if (command.json) {
        header["rows"] = table.json();
        if (const int code = writeOutput(*command.json, jsonText(header, 2) + "\n")) return code;
    }
    return 0;
}

int runSimulationBench(const BenchCommand& command, const BenchSource& source) {
    Table table({{"mode", "", 0},
                 {"characters", "", 0},
                 {"step_ms_median", "median_ms"},
                 {"step_ms_min", "min_ms"},
                 {"step_ms_max", "max_ms"},
                 {"us_per_character", "us/character"},
                 {"threads", "", 0, ColumnUse::DataOnly},
                 {"blend_share", "", 3, ColumnUse::DataOnly},
                 {"transition_share", "", 3, ColumnUse::DataOnly}});
    const std::vector<motion::BakedClip>& clips = *source.prepared.clips;
    unsigned threads = 0;
    Progress progress(command.modes.size() * source.sizes.size());
    for (const std::string& name : command.modes)
        for (int count : source.sizes) {
            const std::string row = name + ", " + std::to_string(count) + " characters";
            progress.starting(row);
            // A scene's "mode" (BenchCommand::kSceneMode) names none: its groups keep their own.
            auto scene = crowdFor(command, source.prepared, count, crowd::modeFromName(name).value_or(crowd::Mode::Group));
            if (!scene) return reportError(scene.error());
            crowd::Crowd& people = *scene.value().crowd;
            threads = people.threadCount();
            for (int s = 0; s < command.warmup; ++s) people.step(clips, kStep);
            std::vector<double> times;
            MotionShares shares;
            for (int s = 0; s < command.frames; ++s) {
                const auto start = Clock::now();
                people.step(clips, kStep);
                times.push_back(millisecondsSince(start));
                shares.count(people);
            }
            const Summary step = summarize(times);
            table.addRow({name, std::int64_t{count}, step.median, step.min, step.max, step.median * 1000.0 / count, std::int64_t{threads},
                          shares.blend(), shares.transition()});
            char result[64];
            std::snprintf(result, sizeof result, "%.3f ms per step", step.median);
            progress.finished(row, result);
        }
    char caption[160];
    std::snprintf(caption, sizeof caption, "crowd step, %u thread(s), %d timed steps of 1/30 s after %d warm-up", threads, command.frames,
                  command.warmup);
    return emit(command, caption, table, Json{{"benchmark", "crowd-step"}, {"threads", threads}, {"step_seconds", kStep}}, clips);
}

// A row of the rendering sweep, a Summary per FrameTimings figure: `frames` frames after `warmup`, each followed
// by one that times its passes with GPU timestamps (lavapipe flushes its work at each: frame figures come from the others).
struct RenderRow {
    Summary frame, sim, upload, compute, draw, readback, visibility, shading;
    MotionShares shares;
};

RenderRow timeFrames(const BenchCommand& command, CrowdScene& scene, render::OffscreenRenderer& offscreen,
                     const render::SceneUniforms& uniforms) {
    std::array<std::vector<double>, 8> figures;  // in RenderRow's order
    MotionShares shares;
    const auto timedStep = [&scene] {
        const auto start = Clock::now();
        scene.step(kStep);
        return millisecondsSince(start);
    };
    // Overlapped, each frame draws the step taken during the frame before (the first, one taken
    // here), and takes the next one while the GPU draws: the crowd drawn is the same as serially.
    if (command.overlapSimulation) timedStep();
    for (int f = 0; f < 2 * (command.warmup + command.frames); ++f) {
        const bool timesPasses = f % 2 == 1;  // then the figures from RenderRow's fourth on
        const bool timed = f >= 2 * command.warmup;
        double simMs = 0.0;
        if (!command.overlapSimulation) simMs = timedStep();
        if (timed && !timesPasses) shares.count(*scene.crowd);  // what this frame's compute pass mixes
        const render::FrameTimings t =
            command.overlapSimulation ? offscreen.render(scene.source(), uniforms, timesPasses, [&] { simMs = timedStep(); })
                                      : offscreen.render(scene.source(), uniforms, timesPasses);
        if (!timed) continue;
        const double frameMs = command.overlapSimulation ? t.frameMs : simMs + t.frameMs;
        const std::array<double, 8> frame{frameMs, simMs, t.uploadMs, t.computeMs, t.drawMs, t.readbackMs, t.visibilityMs, t.shadingMs};
        for (std::size_t i = timesPasses ? 3 : 0; i < (timesPasses ? frame.size() : 3); ++i) figures[i].push_back(frame[i]);
    }
    const auto at = [&](std::size_t i) { return summarize(figures[i]); };
    return {at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7), shares};
}

// The rendering sweep's columns; the last ones are data only.
Table renderTable() {
    return Table({{"mode", "", 0},
                  {"characters", "", 0},
                  {"frame_ms_median", "frame_ms", 2},
                  {"frame_ms_min", "min", 2},
                  {"frame_ms_max", "max", 2},
                  {"fps", "", 2},
                  {"sim_ms_median", "sim_ms"},
                  {"upload_ms_median", "upload_ms"},
                  {"compute_ms_median", "gpu_comp"},
                  {"draw_ms_median", "gpu_draw", 2},
                  {"readback_ms_median", "readback"},
                  {"gpu_bytes_per_character", "", 0, ColumnUse::DataOnly},
                  {"blend_share", "", 3, ColumnUse::DataOnly},
                  {"transition_share", "", 3, ColumnUse::DataOnly},
                  {"body", "", 0, ColumnUse::DataOnly},
                  {"visibility_ms_median", "gpu_vis"},  // the visibility path's passes in gpu_comp and gpu_draw (0 on others)
                  {"shading_ms_median", "gpu_shade"}});
}

// The rendering sweep's caption and JSON header: the device and settings the rows ran with.
int emitRenderSweep(const BenchCommand& command, const gpu::Context& context, const render::Palette& palette, const Table& table,
                    unsigned simulationThreads, std::span<const motion::BakedClip> clips, bool visibilityDrawn) {
    const std::uint32_t msaa = static_cast<std::uint32_t>(context.sampleCount(command.msaa));  // what the device really uses
    const std::uint32_t k = palette.jointsPerCharacter();
    const char* lpThreads = std::getenv("LP_NUM_THREADS");
    char caption[640];
    std::snprintf(caption, sizeof caption,
                  "device %s (%s), LP_NUM_THREADS=%s, %ux%u, %ux MSAA, %u joints, fast-path LOD under %.0f px, %s build, palette %zu bytes; frames timed without GPU timestamps, passes in as many between them%s",
                  context.description().name.c_str(), context.description().driver.c_str(), lpThreads ? lpThreads : "unset", command.width,
                  command.height, msaa, k, static_cast<double>(command.lodPixels), THRONG_BUILD_TYPE, palette.poseBytes(), command.freshFrames ? "; every frame from scratch" : "");
    if (command.overlapSimulation)
        std::strncat(caption, "; the next frame's step overlapped with each frame's GPU work", sizeof caption - std::strlen(caption) - 1);
    // "threads" is the simulation's thread count in both benchmarks; lavapipe's rasteriser threads are "lp_threads" (null when unset: all cores).
    const Json lp = lpThreads ? Json(std::atoi(lpThreads)) : Json(nullptr);
    Json header{{"device", context.description().name}, {"driver", context.description().driver},
                {"threads", simulationThreads}, {"lp_threads", lp}, {"width", command.width}, {"height", command.height},
                {"joints", k}, {"msaa", msaa}, {"lod_pixels", command.lodPixels}, {"build_type", THRONG_BUILD_TYPE},
                {"palette_bytes", palette.poseBytes()}, {"readback", !command.noReadback}, {"fresh_frames", command.freshFrames}, {"overlap_simulation", command.overlapSimulation}, {"passes_timed_apart", true}};
    if (command.noReadback) std::strncat(caption, "; no readback", sizeof caption - std::strlen(caption) - 1);
    if (msaa > 1 && visibilityDrawn) {
        // Its rows drew with one sample (render::samplesFor): say so beside the sweep's MSAA.
        std::strncat(caption, "; visibility rows 1x MSAA (rims smoothed analytically)", sizeof caption - std::strlen(caption) - 1);
        header["visibility_msaa"] = 1;
    }
    return emit(command, caption, table, header, clips);
}

// What one character costs to draw at each level of `body`, per distinct skeleton: the skinned
// mesh's vertices and triangles, the bones' quads (two triangles each, ray-cast) and the joint
// spheres' point sprites.
void reportBodySizes(std::span<const motion::BakedClip> clips, const render::Palette& palette, render::Body body) {
    for (const std::size_t first : palette.skeletonClips()) {
        const motion::BakedClip& clip = clips[first];
        std::string text = "bench: " + std::string(render::bodyName(body)) + " bodies of " + clip.name + ": ";
        if ((body == render::Body::Skin || body == render::Body::Auto) && motion::skinnable(clip)) {
            const motion::BodyMesh mesh = motion::makeBodyMesh(clip);
            text += "skin " + std::to_string(mesh.vertices.size()) + " vertices, " + std::to_string(mesh.indices.size() / 3) + " triangles; ";
        }
        text += "bones " + std::to_string(clip.body.size()) + " quads (" + std::to_string(2 * clip.body.size()) + " triangles)";
        if (body == render::Body::Auto) text += "; spheres " + std::to_string(clip.jointCount()) + " point sprites";
        text += " per character";
        log::report(text);
    }
}

int runRenderBench(const BenchCommand& command, const BenchSource& source) {
    const std::span<const motion::BakedClip> clips = source.prepared.clipSpan();
    const gpu::Context context({.deviceFilter = command.device, .validation = false, .synchronizationValidation = false, .instanceExtensions = {}, .createSurface = {}});
    const render::Palette palette(context, clips);
    // Every size is checked against the device's memory before the first row spends any time (past one storage buffer, in batches).
    const std::uint64_t heap = context.largestDeviceHeap();
    for (const render::Body body : command.bodies) {
        const std::uint64_t most = heap / render::CrowdRenderer::bytesPerCharacter(clips, body);
        for (const int count : source.sizes)
            if (static_cast<std::uint64_t>(count) > most)
                return reportError(Error{Error::Kind::BadInput,
                                         "--characters " + std::to_string(count) + " with --body " + std::string(render::bodyName(body)) +
                                             ": more than this device's " + std::to_string(heap >> 20) + " MiB of memory holds (about " +
                                             std::to_string(most) + " characters)", {}});
    }
    Table table = renderTable();
    // Spheres on every path asked for; the other bodies on those of them that draw bodies (fast,
    // visibility), or on the fast path when none does.
    std::vector<std::pair<render::Body, render::RenderPath>> rows;
    const auto drawsBodies = [](render::RenderPath path) { return path == render::RenderPath::Fast || path == render::RenderPath::Visibility; };
    const bool anyDrawsBodies = std::any_of(command.paths.begin(), command.paths.end(), drawsBodies);
    for (const render::Body body : command.bodies) {
        for (const render::RenderPath path : command.paths)
            if (body == render::Body::Spheres || drawsBodies(path)) rows.emplace_back(body, path);
        if (body != render::Body::Spheres && !anyDrawsBodies) rows.emplace_back(body, render::RenderPath::Fast);
        if (body != render::Body::Spheres) reportBodySizes(clips, palette, body);
    }
    Progress progress(rows.size() * source.sizes.size());
    unsigned simulationThreads = 0;
    bool visibilityDrawn = false;
    // A frame past the visibility path's buffer is said once, not for every row (each then draws with `fast`).
    const bool picks = command.choosePath && (!visibilitySuits(context) || visibilityHoldsFrame(context, {command.width, command.height}, "bench: ", "frame"));
    for (const auto& [body, asked] : rows)
        for (int count : source.sizes) {
            auto scene = crowdFor(command, source.prepared, count, crowd::Mode::Group);
            if (!scene) return reportError(scene.error());
            // The camera frames the crowd.
            const CrowdView view = frameView(scene.value(), static_cast<float>(command.width) / static_cast<float>(command.height), std::nullopt);
            const render::SceneUniforms uniforms = render::makeScene(view.camera, {command.width, command.height}, view.reach + 40.0F, true);
            // Bare, the path `throng render` would pick for this crowd (which may differ by size).
            std::optional<render::OffscreenRenderer> drawn;
            emplaceOffscreen(drawn, context, palette, clips,
                             {.width = command.width, .height = command.height, .msaa = command.msaa, .path = asked,
                              .lodPixels = command.lodPixels, .body = body, .readBack = !command.noReadback, .keepLastFrame = !command.freshFrames},
                             static_cast<std::size_t>(count), picks && body != render::Body::Spheres);
            render::OffscreenRenderer& offscreen = *drawn;
            const render::RenderPath path = offscreen.renderer().path();
            visibilityDrawn = visibilityDrawn || path == render::RenderPath::Visibility;
            const std::string name = std::string(render::renderPathName(path)) + (body == render::Body::Spheres ? "" : "/" + std::string(render::bodyName(body)));
            const std::string label = name + " path, " + std::to_string(count) + " characters";
            progress.starting(label);
            const RenderRow row = timeFrames(command, scene.value(), offscreen, uniforms);
            table.addRow({name, std::int64_t{count}, row.frame.median, row.frame.min, row.frame.max, 1000.0 / row.frame.median,
                          row.sim.median, row.upload.median, row.compute.median, row.draw.median, row.readback.median,
                          static_cast<std::int64_t>(offscreen.renderer().instanceLayout().gpuBytesPerCharacter), row.shares.blend(),
                          row.shares.transition(), std::string(render::bodyName(body)), row.visibility.median, row.shading.median});
            simulationThreads = scene.value().crowd->threadCount();
            char result[64];
            std::snprintf(result, sizeof result, "%.1f ms per frame (%.1f fps)", row.frame.median, 1000.0 / row.frame.median);
            progress.finished(label, result);
        }
    return emitRenderSweep(command, context, palette, table, simulationThreads, clips, visibilityDrawn);
}

// The table's files, checked before a row runs: a sweep can take minutes to find that its
// CSV has nowhere to go.
std::optional<Error> checkBenchOutputs(const BenchCommand& command) {
    if (command.csv)
        if (auto problem = checkOutputPath(*command.csv, "--csv")) return problem;
    if (command.json)
        if (auto problem = checkOutputPath(*command.json, "--json")) return problem;
    if (command.csv && command.json && sameFile(*command.csv, *command.json))
        return Error{Error::Kind::BadInput, "--csv and --json name the same file", {*command.json, 0, 0}};
    return std::nullopt;
}

}  // namespace

int runBench(const BenchCommand& command) {
    if (auto problem = checkBenchOutputs(command)) return reportError(*problem);
    auto source = prepareBench(command);
    if (!source) return reportError(source.error());
    return command.simOnly ? runSimulationBench(command, source.value()) : runRenderBench(command, source.value());
}

}  // namespace throng::app
