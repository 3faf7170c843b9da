#pragma once
// Scene files: JSON describing clips, crowd groups, goals and a camera. A bad file is an
// Error that names the file and the JSON path of the bad field (exit code 2).
//
// {
//   "clips":  [{"name": "walk", "path": "walk.bvh"}],         paths relative to the scene file
//   "area":   [40, 40],                                          metres, for random goals (optional)
//   "seed":   7,                                                 optional
//   "groups": [{"count": 100, "mode": "avoid", "clips": ["walk"],
//               "region": {"centre": [0, 0], "size": [20, 20]},
//               "speed": [0.9, 1.1], "heading": 0}],             speed and heading optional
//   "waypoints": [[-10, 0], [10, 0]],                            optional: goals in turn
//   "camera": {"eye": [0, 12, -30], "target": [0, 0, 0], "fov": 40}   optional
// }

#include <optional>
#include <string>
#include <vector>

#include "throng/app/cli.h"
#include "throng/crowd/crowd.h"

namespace throng::app {

struct SceneDescription {
    std::vector<std::string> clipPaths;  ///< Resolved against the scene file's directory.
    crowd::CrowdSetup setup;             ///< Groups refer to clips by index into clipPaths.
    std::optional<CameraSpec> camera;
};

[[nodiscard]] Result<SceneDescription> loadScene(const std::string& path);

}  // namespace throng::app
