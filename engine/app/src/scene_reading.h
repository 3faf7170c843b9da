#pragma once
// Internals of the scene-file reader, shared by its translation units: scene_file.cpp reads
// the document and the crowd, scene_clips.cpp the "clips", scene_locomotion.cpp the groups'
// locomotion sets. A bad field throws SceneError, which parseScene turns into one Error
// naming the file and the JSON path.

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "scene_file.h"

namespace throng::app::scene_detail {

using Json = nlohmann::json;

/// Thrown inside the reader, caught once at the boundary: the message is "at /json/path: ...".
struct SceneError {
    std::string message;
};

/// Refuses the field at `pointer` ("" is the document).
[[noreturn]] void fail(const std::string& pointer, const std::string& message);
/// `object[key]`, or fail() naming the missing field.
const Json& member(const Json& object, const std::string& pointer, const char* key);
/// Refuses any field of `object` (at `pointer`) not in `fields`: a misspelt field would
/// otherwise be read as absent, with no word said. `what` names the object ("a group").
void onlyFields(const Json& object, const std::string& pointer, std::initializer_list<std::string_view> fields, const char* what);
/// A number as messages show it ("1e+39", "0.01").
std::string shown(double value);
/// A finite number, or fail() saying it expected `what`.
double number(const Json& value, const std::string& pointer, const char* what);

/// A camera object {"eye": [x, y, z], "target": [x, y, z], "fov": degrees} at `at`.
CameraSpec readCamera(const Json& camera, const std::string& at);
/// A "camera_path" at `at`: keyframes {"time": s, "eye", "target", "fov"} by rising time
/// (scene_camera.cpp).
std::vector<CameraKey> readCameraPath(const Json& keys, const std::string& at);
/// The JSON document in `text`, or BadInput naming `path` with the line and column.
Result<Json> parseJsonText(const std::string& path, std::string_view text);

/// Reads "clips": paths or objects with a path, a name and bake overrides. Fills scene.clips
/// and `clipIndex` (clip name -> index), checking that each file exists.
void readClips(const Json& root, const std::filesystem::path& directory, SceneDescription& scene,
               std::map<std::string, std::uint32_t>& clipIndex);

/// "ground_speed" at `at`: [min, max] or one number, 0 <= min <= max <= range::kLargestSpeed m/s.
glm::vec2 readGroundSpeed(const Json& value, const std::string& at);
/// A group's "pause" at its goals: [min, max] or one number of seconds, 0 to kMaxTimeSeconds
/// (scene_events.cpp).
void readGroupPause(const Json& group, const std::string& at, crowd::GroupSpec& spec);
/// Reads "events" (scene_events.cpp) into scene.setup.events; groups are read already.
void readEvents(const Json& root, const std::map<std::string, std::uint32_t>& clipIndex, SceneDescription& scene);

/// Reads a group's "locomotion" and "ground_speed" into `spec` (scene_locomotion.cpp): the set
/// is added to scene.locomotionMembers unless a group before named the same clips, and the
/// parts to scene.locomotionGroups. Refuses "ground_speed" without a set, and "clips" or
/// "speed" with one.
void readGroupLocomotion(const Json& group, const std::string& at, const std::map<std::string, std::uint32_t>& clipIndex,
                         SceneDescription& scene, crowd::GroupSpec& spec);

}  // namespace throng::app::scene_detail
