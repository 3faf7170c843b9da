#include "scene_file.h"

#include "throng/core/input_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace throng::app {
namespace {

using Json = nlohmann::json;

// Thrown inside the reader, caught once at the boundary: the message is "at /json/path: ...".
struct SceneError {
    std::string message;
};

[[noreturn]] void fail(const std::string& pointer, const std::string& message) {
    throw SceneError{"at " + (pointer.empty() ? std::string("/") : pointer) + ": " + message};
}

const char* typeName(const Json& value) { return value.type_name(); }

const Json& member(const Json& object, const std::string& pointer, const char* key) {
    if (!object.contains(key)) fail(pointer, std::string("missing required field \"") + key + "\"");
    return object.at(key);
}

double number(const Json& value, const std::string& pointer, const char* what) {
    if (!value.is_number()) fail(pointer, std::string("expected ") + what + ", found " + typeName(value));
    const double d = value.get<double>();
    if (!std::isfinite(d)) fail(pointer, std::string("expected ") + what + ", found a non-finite number");
    return d;
}

glm::vec2 pair(const Json& value, const std::string& pointer, const char* what) {
    if (!value.is_array() || value.size() != 2) fail(pointer, std::string("expected ") + what + " as [x, z]");
    return {static_cast<float>(number(value[0], pointer + "/0", "a number")),
            static_cast<float>(number(value[1], pointer + "/1", "a number"))};
}

glm::vec3 triple(const Json& value, const std::string& pointer, const char* what) {
    if (!value.is_array() || value.size() != 3) fail(pointer, std::string("expected ") + what + " as [x, y, z]");
    return {static_cast<float>(number(value[0], pointer + "/0", "a number")),
            static_cast<float>(number(value[1], pointer + "/1", "a number")),
            static_cast<float>(number(value[2], pointer + "/2", "a number"))};
}

glm::vec2 positiveSize(const Json& value, const std::string& pointer) {
    const glm::vec2 size = pair(value, pointer, "a size in metres");
    if (!(size.x > 0 && size.y > 0 && size.x <= 100000 && size.y <= 100000))
        fail(pointer, "sizes must be positive and at most 100000 m");
    return size;
}

// "clips": paths or {"name", "path"} objects; fills the paths and the name -> index map.
void readClips(const Json& root, const std::filesystem::path& directory, SceneDescription& scene,
               std::map<std::string, std::uint32_t>& clipIndex) {
    const Json& clips = member(root, "", "clips");
    if (!clips.is_array() || clips.empty()) fail("/clips", "expected a non-empty array of clips");
    for (std::size_t i = 0; i < clips.size(); ++i) {
        const std::string at = "/clips/" + std::to_string(i);
        const Json& clip = clips[i];
        std::string path, name;
        if (clip.is_string()) {
            path = clip.get<std::string>();
        } else if (clip.is_object()) {
            const Json& p = member(clip, at, "path");
            if (!p.is_string()) fail(at + "/path", std::string("expected a file path, found ") + typeName(p));
            path = p.get<std::string>();
            if (clip.contains("name")) {
                if (!clip["name"].is_string()) fail(at + "/name", "expected a string");
                name = clip["name"].get<std::string>();
            }
        } else {
            fail(at, std::string("expected a path or {\"name\", \"path\"}, found ") + typeName(clip));
        }
        const std::filesystem::path resolved = std::filesystem::path(path).is_absolute() ? std::filesystem::path(path) : directory / path;
        if (!std::filesystem::is_regular_file(resolved)) fail(at, "clip file '" + resolved.string() + "' does not exist");
        if (name.empty()) name = std::filesystem::path(path).stem().string();
        if (clipIndex.count(name)) fail(at, "clip name '" + name + "' is used twice");
        clipIndex[name] = static_cast<std::uint32_t>(i);
        scene.clipPaths.push_back(resolved.string());
    }
}

// One entry of "groups". `total` counts characters over all groups so far.
crowd::GroupSpec readGroup(const Json& group, const std::string& at, const std::map<std::string, std::uint32_t>& clipIndex,
                           long long& total) {
    if (!group.is_object()) fail(at, std::string("expected an object, found ") + typeName(group));
    crowd::GroupSpec spec;
    const Json& count = member(group, at, "count");
    if (!count.is_number_integer()) fail(at + "/count", std::string("expected a whole number, found ") + typeName(count));
    const long long n = count.get<long long>();
    if (n < 1 || n > kMaxCharacters) fail(at + "/count", "expected a count from 1 to " + std::to_string(kMaxCharacters) + ", found " + std::to_string(n));
    total += n;
    if (total > kMaxCharacters) fail(at + "/count", "the scene has more than " + std::to_string(kMaxCharacters) + " characters");
    spec.count = static_cast<int>(n);
    if (group.contains("mode")) {
        const Json& mode = group["mode"];
        const auto parsed = mode.is_string() ? crowd::modeFromName(mode.get<std::string>()) : std::nullopt;
        if (!parsed) fail(at + "/mode", "expected \"group\", \"goals\" or \"avoid\"");
        spec.mode = *parsed;
    }
    if (group.contains("clips")) {
        const Json& names = group["clips"];
        if (!names.is_array() || names.empty()) fail(at + "/clips", "expected a non-empty array of clip names");
        for (std::size_t c = 0; c < names.size(); ++c) {
            const std::string cat = at + "/clips/" + std::to_string(c);
            if (!names[c].is_string()) fail(cat, std::string("expected a clip name, found ") + typeName(names[c]));
            const auto found = clipIndex.find(names[c].get<std::string>());
            if (found == clipIndex.end()) fail(cat, "no clip is named '" + names[c].get<std::string>() + "'");
            spec.clips.push_back(found->second);
        }
    }
    const Json& region = member(group, at, "region");
    if (!region.is_object()) fail(at + "/region", std::string("expected an object, found ") + typeName(region));
    spec.region.centre = pair(member(region, at + "/region", "centre"), at + "/region/centre", "a centre");
    spec.region.size = positiveSize(member(region, at + "/region", "size"), at + "/region/size");
    if (group.contains("speed")) {
        spec.speedRange = pair(group["speed"], at + "/speed", "a playback speed range [min, max]");
        if (!(spec.speedRange.x > 0 && spec.speedRange.y >= spec.speedRange.x && spec.speedRange.y <= 4))
            fail(at + "/speed", "expected 0 < min <= max <= 4");
    }
    if (group.contains("heading")) spec.heading = glm::radians(static_cast<float>(number(group["heading"], at + "/heading", "degrees")));
    return spec;
}

CameraSpec readCamera(const Json& camera) {
    if (!camera.is_object()) fail("/camera", std::string("expected an object, found ") + typeName(camera));
    CameraSpec spec;
    spec.eye = triple(member(camera, "/camera", "eye"), "/camera/eye", "an eye position");
    spec.target = triple(member(camera, "/camera", "target"), "/camera/target", "a target");
    if (camera.contains("fov")) spec.verticalFovDegrees = static_cast<float>(number(camera["fov"], "/camera/fov", "degrees"));
    if (!(spec.verticalFovDegrees > 1 && spec.verticalFovDegrees < 170)) fail("/camera/fov", "expected 1 to 170 degrees");
    if (glm::length(spec.eye - spec.target) < 1e-3F) fail("/camera", "eye and target must differ");
    return spec;
}

SceneDescription read(const Json& root, const std::filesystem::path& directory) {
    if (!root.is_object()) fail("", std::string("expected an object, found ") + typeName(root));
    SceneDescription scene;
    std::map<std::string, std::uint32_t> clipIndex;
    readClips(root, directory, scene, clipIndex);
    crowd::CrowdSetup& setup = scene.setup;
    if (root.contains("seed")) {
        const Json& seed = root["seed"];
        if (!seed.is_number_unsigned()) fail("/seed", std::string("expected a non-negative whole number, found ") + typeName(seed));
        setup.seed = seed.get<std::uint64_t>();
    }
    const Json& groups = member(root, "", "groups");
    if (!groups.is_array() || groups.empty()) fail("/groups", "expected a non-empty array of groups");
    long long total = 0;
    glm::vec2 lo(1e30F), hi(-1e30F);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        crowd::GroupSpec spec = readGroup(groups[g], "/groups/" + std::to_string(g), clipIndex, total);
        lo = glm::min(lo, spec.region.centre - 0.5F * spec.region.size);
        hi = glm::max(hi, spec.region.centre + 0.5F * spec.region.size);
        setup.groups.push_back(std::move(spec));
    }
    // Random goals fall in the given area, or else in the box around all spawn regions.
    setup.area = {0.5F * (lo + hi), hi - lo};
    if (root.contains("area")) setup.area.size = positiveSize(root["area"], "/area");
    if (root.contains("waypoints")) {
        const Json& points = root["waypoints"];
        if (!points.is_array()) fail("/waypoints", std::string("expected an array of [x, z], found ") + typeName(points));
        for (std::size_t w = 0; w < points.size(); ++w)
            setup.waypoints.push_back(pair(points[w], "/waypoints/" + std::to_string(w), "a waypoint"));
    }
    if (root.contains("camera")) scene.camera = readCamera(root["camera"]);
    return scene;
}

}  // namespace

Result<SceneDescription> loadScene(const std::string& path) {
    constexpr std::uint64_t kMaxSceneBytes = 64ULL << 20;  // a scene is a page of JSON; this is generous
    auto file = readInputFile(path, kMaxSceneBytes, "scene file");
    if (!file) return file.error();
    const std::string& text = file.value();
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::parse_error& e) {
        // nlohmann reports a byte offset; users want a line and column.
        int line = 1, column = 1;
        for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::string what = e.what();
        const std::size_t cut = what.find("syntax error");
        return Error{Error::Kind::BadInput, "invalid JSON: " + (cut == std::string::npos ? what : what.substr(cut)), {path, line, column}};
    }
    try {
        return read(root, std::filesystem::path(path).parent_path());
    } catch (const SceneError& e) {
        return Error{Error::Kind::BadInput, e.message, {path, 0, 0}};
    }
}

}  // namespace throng::app
