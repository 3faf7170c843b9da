#pragma once
// Internals of the scene-file reader, shared by its translation units: scene_file.cpp reads
// the document and the crowd, scene_clips.cpp the "clips". A bad field throws SceneError,
// which parseScene turns into one Error naming the file and the JSON path.

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

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
/// A number as messages show it ("1e+39", "0.01").
std::string shown(double value);

/// Reads "clips": paths or objects with a path, a name and bake overrides. Fills scene.clips
/// and `clipIndex` (clip name -> index), checking that each file exists.
void readClips(const Json& root, const std::filesystem::path& directory, SceneDescription& scene,
               std::map<std::string, std::uint32_t>& clipIndex);

}  // namespace throng::app::scene_detail
