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
//               "speed": [0.9, 1.1], "heading": 0},              speed and heading optional
//              {"count": 50, "mode": "goals",                    a group may blend a locomotion set
//               "locomotion": {"idle": "idle", "walk": "walk", "run": "run"},   instead of "clips"
//               "ground_speed": [0.8, 2.4],                      m/s, or one number (default [1, 1.6])
//               "region": {"centre": [0, 30], "size": [20, 20]}}],
//   "waypoints": [[-10, 0], [10, 0]],                            optional: goals in turn
//   "events": [{"time": 2, "group": 0, "play": "run", "fade": 0.3},          optional: at "time" s,
//              {"time": 4, "group": 1, "locomotion": {"walk": "walk", "run": "run"},  a group crossfades
//               "ground_speed": [2, 2.5]},                                    to a clip or a set
//              {"time": 6, "group": 1, "ground_speed": 0.6}],                and/or takes new speeds
//   "camera": {"eye": [0, 12, -30], "target": [0, 0, 0], "fov": 40},  optional
//   "camera_path": [{"time": 0, "eye": [...], "target": [...], "fov": 40}, ...]   optional: a
//                  moving camera for render (keyframes by rising time; see cameraAt)
// }
//
// A group's "locomotion" names clips of "clips" by part: "idle" (a clip that stands) and the
// gaits "slow_walk", "walk", "jog" and "run", any subset with at least one gait. It excludes "clips" and
// the playback "speed" (a set is played at the speed its blend walks), and "ground_speed" (0 <=
// min <= max <= 20 m/s, range::kLargestSpeed) needs it. Groups naming the same clips share one
// set. Once the clips are baked (makeSceneLocomotionSets) each set must be one that
// motion::makeLocomotionSet accepts, and each part what it is called: the idle stands, a gait
// walks, and the gaits' speeds rise in the order slow_walk, walk, jog, run; a refusal names
// the file and the group's JSON path.
//
// A group's "pause" ([min, max] or one number, 0 to 600 s; default [0, 3]) is how long its
// characters stand at each goal, when they blend a set with an idle in goals or avoid mode.
// An event's "group" is an index into "groups"; "play" names a clip, "locomotion" a set as a
// group's does; "fade" is the crossfade in seconds (0 to 10, default 0.3; 0 cuts). Clips an
// event brings in must have the group's skeleton (checked when the crowd spawns).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "throng/app/cli.h"
#include "throng/crowd/crowd.h"

namespace throng::app {

/// One group's "locomotion": which clip plays each part of its set.
struct SceneLocomotion {
    struct Part {
        std::string role;      ///< "idle", "slow_walk", "walk", "jog" or "run".
        std::string clipName;  ///< As the scene names it.
        std::uint32_t clip = 0;  ///< Index into SceneDescription::clips.
    };
    std::string at;            ///< JSON path of the field, e.g. "/groups/2/locomotion".
    std::uint32_t set = 0;     ///< Index into SceneDescription::locomotionMembers (and the group's GroupSpec::locomotion).
    std::vector<Part> parts;   ///< In the order of kLocomotionParts.
};

/// The parts a scene's set may name, slowest first: an idle, then gaits by rising speed.
inline constexpr std::array<std::string_view, 5> kLocomotionParts{"idle", "slow_walk", "walk", "jog", "run"};

/// One keyframe of a camera path: where the camera is at a time (seconds since spawn, the
/// clock of --time).
struct CameraKey {
    double time = 0.0;
    CameraSpec camera;
};

struct SceneDescription {
    std::vector<ClipSpec> clips;         ///< Paths resolved against the scene file's directory.
    std::vector<std::string> clipNames;  ///< Per clip, what to call it: the scene's "name", else the file's stem.
    crowd::CrowdSetup setup;             ///< Groups refer to clips by index into `clips`.
    /// Per locomotion set (GroupSpec::locomotion), its clips by index into `clips`: made into
    /// setup.locomotion once the clips are baked (prepareCrowdScene).
    std::vector<std::vector<std::uint32_t>> locomotionMembers;
    /// Each scene group's "locomotion" as written (empty without a scene file), to check the
    /// clips against their parts once they are baked.
    std::vector<SceneLocomotion> locomotionGroups;
    std::optional<CameraSpec> camera;
    std::vector<CameraKey> cameraPath;   ///< "camera_path": keyframes by rising time; empty: none.
    std::string source;                  ///< The scene file's path; empty when the command line described the crowd.
};

/// Reads and checks the scene file at `path`.
[[nodiscard]] Result<SceneDescription> loadScene(const std::string& path);
/// The same for scene text already in memory; `path` names it in errors and locates its clips.
[[nodiscard]] Result<SceneDescription> parseScene(std::string_view text, const std::string& path);

/// The "camera_path" of the JSON file at `path`: a scene file, or a file holding only
/// {"camera_path": [...]}. BadInput naming the file and the JSON path of a bad keyframe.
[[nodiscard]] Result<std::vector<CameraKey>> loadCameraPath(const std::string& path);
/// The camera at `time` on `path` (not empty): held at the first and last keyframes, and
/// between them a Catmull-Rom curve through the eyes and the targets (smooth, exact at every
/// keyframe) with the field of view eased linearly.
[[nodiscard]] CameraSpec cameraAt(std::span<const CameraKey> path, double time);

/// Scales `scene`'s groups to `total` characters in all, each in proportion to its count: the
/// largest remainders round, so the counts sum to `total` exactly (the scene's own total
/// changes nothing) and every group keeps at least one character. A group's spawn region
/// grows or shrinks with the square root of its count's change, so the crowd's density stays.
/// BadInput, changing nothing, when `total` is below the number of groups or above
/// kMaxCharacters. What `throng bench --scene -n` and the demo's [ and ] keys do.
[[nodiscard]] std::optional<Error> scaleScene(SceneDescription& scene, std::int64_t total);

/// The locomotion sets of `scene` (SceneDescription::locomotionMembers) over its baked clips,
/// in order. A set motion::makeLocomotionSet refuses, or a scene part that is not what it is
/// called, is BadInput naming scene.source and the JSON path of the first group that names it;
/// a set from the command line fails with makeLocomotionSet's own line.
[[nodiscard]] Result<std::vector<motion::LocomotionSet>> makeSceneLocomotionSets(const SceneDescription& scene,
                                                                                 std::span<const motion::BakedClip> clips);

}  // namespace throng::app
