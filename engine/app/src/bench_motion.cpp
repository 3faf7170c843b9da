#include "bench_motion.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "crowd_scene.h"

namespace throng::app {

using Json = nlohmann::ordered_json;

MotionNote describeMotion(const BenchCommand& command, std::span<const motion::BakedClip> clips) {
    Json files = Json::array();
    std::string names;
    for (const motion::BakedClip& clip : clips) {
        files.push_back(clip.name);
        names += (names.empty() ? "" : ", ") + std::filesystem::path(clip.name).filename().string();
    }
    // "scene" comes last, added after the others (which keep their names and places).
    const Json scene = command.scene ? Json(*command.scene) : Json(nullptr);
    if (command.scene)
        return {"motion: scene " + *command.scene + " (" + names + ")",
                Json{{"motion", "scene"}, {"clips", files}, {"ground_speed", nullptr}, {"scene", scene}}};
    if (command.trajectories)
        return {"motion: following " + *command.trajectories + ", posed by " + names,
                Json{{"motion", "trajectories"}, {"clips", files}, {"ground_speed", nullptr}, {"scene", scene},
                     {"trajectories", *command.trajectories}}};
    if (command.locomotion.empty())
        return {"motion: " + names + ", each clip as it is",
                Json{{"motion", "clips"}, {"clips", files}, {"ground_speed", nullptr}, {"scene", scene}}};
    const glm::vec2 speed = command.speed.value_or(kDefaultGroundSpeed);
    const auto rounded = [](float metresPerSecond) { return std::round(static_cast<double>(metresPerSecond) * 1e4) / 1e4; };
    char range[64];
    std::snprintf(range, sizeof range, "%g-%g m/s", rounded(speed.x), rounded(speed.y));
    return {"motion: blend of " + std::to_string(clips.size()) + " clips (" + names + ") at " + range,
            Json{{"motion", "blend"}, {"clips", files}, {"ground_speed", {rounded(speed.x), rounded(speed.y)}}, {"scene", scene}}};
}

}  // namespace throng::app
