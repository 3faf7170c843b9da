#include "bench_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bvh_commands.h"
#include "crowd_setup.h"
#include "throng/core/atomic_file.h"
#include "throng/gpu/context.h"
#include "throng/render/headless.h"

#ifndef THRONG_BUILD_TYPE
#define THRONG_BUILD_TYPE "unknown"
#endif

namespace throng::app {
namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;
constexpr double kStep = 1.0 / 30.0;

struct Spread {
    double median = 0, min = 0, max = 0;
};

Spread spread(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    if (values.empty()) return {};
    return {values[values.size() / 2], values.front(), values.back()};
}

int emit(const std::string& text, const std::string& out) {
    if (out == "-") {
        std::fputs(text.c_str(), stdout);
        return 0;
    }
    auto written = writeFileAtomically(out, text);
    return written ? 0 : reportError(written.error());
}

CrowdOptions crowdFor(const BenchCommand& command, int count, crowd::Mode mode) {
    CrowdOptions options;
    options.clips = command.clips;
    options.characters = count;
    options.mode = mode;
    options.threads = command.threads;
    return options;
}

Result<crowd::Crowd> spawnFor(const BenchCommand& command, std::span<const motion::BakedClip> clips, int count, crowd::Mode mode) {
    auto description = describeCrowd(crowdFor(command, count, mode));
    if (!description) return description.error();
    return crowd::Crowd::spawn(clips, description.value().setup);
}

int runSimulationBench(const BenchCommand& command, std::span<const motion::BakedClip> clips) {
    struct Row {
        std::string mode;
        int characters;
        Spread step;
    };
    std::vector<Row> rows;
    unsigned threads = 0;
    for (const std::string& name : command.modes)
        for (int count : command.characters) {
            std::fprintf(stderr, "bench: %s, %d characters...\n", name.c_str(), count);
            auto spawned = spawnFor(command, clips, count, *crowd::modeFromName(name));
            if (!spawned) return reportError(spawned.error());
            crowd::Crowd& people = spawned.value();
            threads = people.threadCount();
            for (int s = 0; s < command.warmup; ++s) people.step(clips, kStep);
            std::vector<double> times;
            for (int s = 0; s < command.frames; ++s) {
                const auto start = Clock::now();
                people.step(clips, kStep);
                times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            }
            rows.push_back({name, count, spread(times)});
        }
    std::printf("crowd step, %u thread(s), %d timed steps of 1/30 s after %d warm-up\n", threads, command.frames, command.warmup);
    std::printf("%-6s %11s %11s %9s %9s %14s\n", "mode", "characters", "median_ms", "min_ms", "max_ms", "us/character");
    for (const Row& r : rows)
        std::printf("%-6s %11d %11.3f %9.3f %9.3f %14.3f\n", r.mode.c_str(), r.characters, r.step.median, r.step.min, r.step.max,
                    r.step.median * 1000.0 / r.characters);
    if (command.csv) {
        std::ostringstream csv;
        csv << "mode,characters,step_ms_median,step_ms_min,step_ms_max,threads\n";
        for (const Row& r : rows) csv << r.mode << ',' << r.characters << ',' << r.step.median << ',' << r.step.min << ',' << r.step.max << ',' << threads << '\n';
        if (const int code = emit(csv.str(), *command.csv)) return code;
    }
    if (command.json) {
        Json json;
        json["benchmark"] = "crowd-step";
        json["threads"] = threads;
        json["step_seconds"] = kStep;
        json["rows"] = Json::array();
        for (const Row& r : rows)
            json["rows"].push_back({{"mode", r.mode}, {"characters", r.characters}, {"step_ms_median", r.step.median},
                                    {"step_ms_min", r.step.min}, {"step_ms_max", r.step.max}});
        if (const int code = emit(json.dump(2) + "\n", *command.json)) return code;
    }
    return 0;
}

int runRenderBench(const BenchCommand& command, std::span<const motion::BakedClip> clips) {
    const gpu::Context context({.deviceFilter = command.device, .validation = false, .synchronizationValidation = false,
                                .instanceExtensions = {}, .createSurface = {}});
    const render::Palette palette(context, clips);
    const std::uint32_t k = palette.jointsPerCharacter();
    const char* lpThreads = std::getenv("LP_NUM_THREADS");
    struct Row {
        std::string mode;
        int characters;
        Spread frame, sim, upload, compute, draw, readback;
        std::uint64_t gpuBytesPerCharacter;
    };
    std::vector<Row> rows;
    for (const render::RenderPath path : command.paths)
        for (int count : command.characters) {
            const std::string name(render::renderPathName(path));
            std::fprintf(stderr, "bench: %s path, %d characters...\n", name.c_str(), count);
            auto spawned = spawnFor(command, clips, count, crowd::Mode::Group);
            if (!spawned) return reportError(spawned.error());
            crowd::Crowd& people = spawned.value();
            std::vector<crowd::CharacterState> packed(static_cast<std::size_t>(people.size()));
            people.pack(packed);
            const float aspect = static_cast<float>(command.width) / static_cast<float>(command.height);
            const CrowdView view = frameView(packed, clips, aspect, std::nullopt);  // the camera frames the crowd
            const render::SceneUniforms scene = render::makeScene(view.camera, {command.width, command.height}, view.reach + 40.0F);
            render::OffscreenRenderer offscreen(context, palette, clips, static_cast<std::uint32_t>(count),
                                                {.width = command.width, .height = command.height, .msaa = command.msaa,
                                                 .path = path, .lodPixels = command.lodPixels});
            std::vector<double> frame, sim, upload, compute, draw, readback;
            for (int f = 0; f < command.warmup + command.frames; ++f) {
                const auto start = Clock::now();
                people.step(clips, kStep);
                people.pack(packed);
                const double simMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                const render::FrameTimings t = offscreen.render(packed, scene);
                if (f < command.warmup) continue;
                frame.push_back(simMs + t.frameMs);
                sim.push_back(simMs);
                upload.push_back(t.uploadMs);
                compute.push_back(t.computeMs);
                draw.push_back(t.drawMs);
                readback.push_back(t.readbackMs);
            }
            // Per character on the GPU: its state, its instances (and the fast path's owner
            // index per instance); the palette is shared by the whole crowd.
            const std::uint64_t perCharacter = sizeof(crowd::CharacterState) + std::uint64_t{k} * sizeof(render::InstanceGpu) +
                                               (path == render::RenderPath::Fast ? std::uint64_t{k} * 8 : 0);
            rows.push_back({name, count, spread(frame), spread(sim), spread(upload), spread(compute), spread(draw), spread(readback),
                            path == render::RenderPath::Paper ? sizeof(crowd::CharacterState) : perCharacter});
        }
    std::printf("device %s (%s), LP_NUM_THREADS=%s, %ux%u, %ux MSAA, %u joints, fast-path LOD under %.0f px, %s build, palette %zu bytes\n",
                context.description().name.c_str(), context.description().driver.c_str(), lpThreads ? lpThreads : "unset",
                command.width, command.height, command.msaa, k, static_cast<double>(command.lodPixels), THRONG_BUILD_TYPE, palette.poseBytes());
    std::printf("%-8s %10s %10s %8s %8s %7s %8s %9s %8s %9s %9s\n", "mode", "characters", "frame_ms", "min", "max", "fps", "sim_ms",
                "upload_ms", "gpu_comp", "gpu_draw", "readback");
    for (const Row& r : rows)
        std::printf("%-8s %10d %10.2f %8.2f %8.2f %7.2f %8.3f %9.3f %8.3f %9.2f %9.3f\n", r.mode.c_str(), r.characters, r.frame.median,
                    r.frame.min, r.frame.max, 1000.0 / r.frame.median, r.sim.median, r.upload.median, r.compute.median, r.draw.median,
                    r.readback.median);
    if (command.csv) {
        std::ostringstream csv;
        csv << "mode,characters,frame_ms_median,frame_ms_min,frame_ms_max,fps,sim_ms_median,upload_ms_median,compute_ms_median,"
               "draw_ms_median,readback_ms_median,gpu_bytes_per_character\n";
        for (const Row& r : rows)
            csv << r.mode << ',' << r.characters << ',' << r.frame.median << ',' << r.frame.min << ',' << r.frame.max << ','
                << 1000.0 / r.frame.median << ',' << r.sim.median << ',' << r.upload.median << ',' << r.compute.median << ','
                << r.draw.median << ',' << r.readback.median << ',' << r.gpuBytesPerCharacter << '\n';
        if (const int code = emit(csv.str(), *command.csv)) return code;
    }
    if (command.json) {
        Json json;
        json["device"] = context.description().name;
        json["driver"] = context.description().driver;
        json["threads"] = lpThreads ? lpThreads : "unset";
        json["width"] = command.width;
        json["height"] = command.height;
        json["joints"] = k;
        json["msaa"] = command.msaa;
        json["lod_pixels"] = command.lodPixels;
        json["build_type"] = THRONG_BUILD_TYPE;
        json["palette_bytes"] = palette.poseBytes();
        json["rows"] = Json::array();
        for (const Row& r : rows)
            json["rows"].push_back({{"mode", r.mode}, {"characters", r.characters}, {"frame_ms_median", r.frame.median},
                                    {"frame_ms_min", r.frame.min}, {"frame_ms_max", r.frame.max}, {"fps", 1000.0 / r.frame.median},
                                    {"sim_ms_median", r.sim.median}, {"upload_ms_median", r.upload.median},
                                    {"compute_ms_median", r.compute.median}, {"draw_ms_median", r.draw.median},
                                    {"readback_ms_median", r.readback.median}, {"gpu_bytes_per_character", r.gpuBytesPerCharacter}});
        if (const int code = emit(json.dump(2) + "\n", *command.json)) return code;
    }
    return 0;
}

}  // namespace

int runBench(const BenchCommand& command) {
    auto clips = loadClips(command.clips.empty() ? std::vector<std::string>{defaultClipPath()} : command.clips);
    if (!clips) return reportError(clips.error());
    return command.simOnly ? runSimulationBench(command, clips.value()) : runRenderBench(command, clips.value());
}

}  // namespace throng::app
