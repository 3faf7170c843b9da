#include "bench_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bvh_commands.h"
#include "throng/core/atomic_file.h"
#include "throng/motion/bvh_parser.h"

namespace throng::app {
namespace {

struct Row {
    std::string mode;
    int characters = 0;
    double medianMs = 0, minMs = 0, maxMs = 0;
};

int emit(const std::string& text, const std::string& out) {
    if (out == "-") {
        std::fputs(text.c_str(), stdout);
        return 0;
    }
    auto written = writeFileAtomically(out, text);
    return written ? 0 : reportError(written.error());
}

}  // namespace

int runBench(const BenchCommand& command) {
    std::vector<motion::BakedClip> clips;
    for (const std::string& path : command.clips.empty() ? std::vector<std::string>{defaultClipPath()} : command.clips) {
        auto raw = motion::loadBvhFile(path);
        if (!raw) return reportError(raw.error());
        auto clip = motion::bake(raw.value());
        if (!clip) return reportError(clip.error());
        clips.push_back(std::move(clip.value()));
    }
    constexpr double kStep = 1.0 / 30.0;
    constexpr float kSquareMetresPerCharacter = 2.56F;  // the paper's density, as `throng render`
    std::vector<Row> rows;
    unsigned threads = 0;
    for (crowd::Mode mode : command.modes)
        for (int count : command.characters) {
            std::fprintf(stderr, "bench: %s, %d characters...\n", crowd::modeName(mode), count);
            const float side = std::sqrt(static_cast<float>(count) * kSquareMetresPerCharacter);
            crowd::CrowdSetup setup;
            setup.groups.push_back({.count = count, .clips = {}, .region = {glm::vec2(0.0F), glm::vec2(side)}, .mode = mode,
                                    .speedRange = {1.0F, 1.0F}, .heading = 0.0F});
            setup.area = {glm::vec2(0.0F), glm::vec2(side)};
            setup.threads = command.threads;
            auto spawned = crowd::Crowd::spawn(clips, setup);
            if (!spawned) return reportError(spawned.error());
            crowd::Crowd& people = spawned.value();
            threads = people.threadCount();
            for (int s = 0; s < command.warmup; ++s) people.step(clips, kStep);
            std::vector<double> times;
            for (int s = 0; s < command.steps; ++s) {
                const auto start = std::chrono::steady_clock::now();
                people.step(clips, kStep);
                times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            }
            std::sort(times.begin(), times.end());
            rows.push_back({crowd::modeName(mode), count, times[times.size() / 2], times.front(), times.back()});
        }
    std::printf("crowd step, %u thread(s), %d timed steps of 1/30 s after %d warm-up\n", threads, command.steps, command.warmup);
    std::printf("%-6s %11s %11s %9s %9s %14s\n", "mode", "characters", "median_ms", "min_ms", "max_ms", "us/character");
    for (const Row& r : rows)
        std::printf("%-6s %11d %11.3f %9.3f %9.3f %14.3f\n", r.mode.c_str(), r.characters, r.medianMs, r.minMs, r.maxMs,
                    r.medianMs * 1000.0 / r.characters);
    if (command.csv) {
        std::ostringstream csv;
        csv << "mode,characters,step_ms_median,step_ms_min,step_ms_max,threads\n";
        for (const Row& r : rows) csv << r.mode << ',' << r.characters << ',' << r.medianMs << ',' << r.minMs << ',' << r.maxMs << ',' << threads << '\n';
        if (const int code = emit(csv.str(), *command.csv)) return code;
    }
    if (command.json) {
        nlohmann::ordered_json json;
        json["benchmark"] = "crowd-step";
        json["threads"] = threads;
        json["step_seconds"] = kStep;
        json["rows"] = nlohmann::ordered_json::array();
        for (const Row& r : rows)
            json["rows"].push_back({{"mode", r.mode}, {"characters", r.characters}, {"step_ms_median", r.medianMs},
                                    {"step_ms_min", r.minMs}, {"step_ms_max", r.maxMs}});
        if (const int code = emit(json.dump(2) + "\n", *command.json)) return code;
    }
    return 0;
}

}  // namespace throng::app
