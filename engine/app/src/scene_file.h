#pragma once
// Scene files: JSON describing clips, crowd groups, goals and a camera. A bad file is an
// Error that names the file and the JSON path of the bad field (exit code 2), or the line
// and column of invalid JSON (a number that overflows a double, such as 1e999, included).
// Every number is checked as a double against throng/core/supported_range.h before it is
// stored as a float: coordinates within +-1e6 m, sizes in (0, 1e5] m, speeds in (0, 4],
// fov in (1, 170) degrees, any finite heading (reduced modulo 360), at most 10000
// waypoints, nesting at most 64 deep, at most 16 MiB of text.
//
// {
//   "clips":  [{"name": "walk", "path": "walk.bvh"}],         paths relative to the scene file;
//                                                                a clip may add bake overrides:
//             "units": 0.01, "up": "z", "root": "Hips", "loop": [10, 50], "straighten": true,
//             "foot_lock": false, "position_channels": "add", "keep_first_frame": true
//             (the rules of `--bvh FILE:key=value`, clip_spec.h; any other field is refused)
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
#include <string_view>
#include <vector>

#include "throng/app/cli.h"
#include "throng/crowd/crowd.h"

namespace throng::app {

struct SceneDescription {
    std::vector<ClipSpec> clips;         ///< Paths resolved against the scene file's directory.
    crowd::CrowdSetup setup;             ///< Groups refer to clips by index into `clips`.
    /// Per locomotion set (GroupSpec::locomotion), its clips by index into `clips`: made into
    /// setup.locomotion once the clips are baked (prepareCrowdScene).
    std::vector<std::vector<std::uint32_t>> locomotionMembers;
    std::optional<CameraSpec> camera;
};

/// Reads and checks the scene file at `path`.
[[nodiscard]] Result<SceneDescription> loadScene(const std::string& path);
/// The same for scene text already in memory; `path` names it in errors and locates its clips.
[[nodiscard]] Result<SceneDescription> parseScene(std::string_view text, const std::string& path);

}  // namespace throng::app
