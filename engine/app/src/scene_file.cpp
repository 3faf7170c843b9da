#include "scene_file.h"

#include "scene_reading.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <new>
#include <set>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>

#include "throng/core/input_file.h"
#include "throng/core/supported_range.h"

namespace throng::app {
namespace scene_detail {

void fail(const std::string& pointer, const std::string& message) {
    throw SceneError{"at " + (pointer.empty() ? std::string("/") : pointer) + ": " + message};
}

std::string shown(double value) {
    // The shortest text that reads back as `value`: rounded to six digits, a limit's
    // 1000000.1 was shown as 1e+06, as if it were in range.
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc() ? std::string(text, end) : std::string("?");
}

const Json& member(const Json& object, const std::string& pointer, const char* key) {
    if (!object.contains(key)) fail(pointer, std::string("missing required field \"") + key + "\"");
    return object.at(key);
}

void onlyFields(const Json& object, const std::string& pointer, std::initializer_list<std::string_view> fields, const char* what) {
    for (const auto& [key, value] : object.items()) {
        if (std::find(fields.begin(), fields.end(), key) != fields.end()) continue;
        std::string list;
        for (const std::string_view field : fields) list += (list.empty() ? "" : ", ") + std::string(field);
        fail(pointer + "/" + excerpt(key), "unknown field \"" + excerpt(key) + "\" (" + what + " takes " + list + ")");
    }
}

double number(const Json& value, const std::string& pointer, const char* what) {
    if (!value.is_number()) fail(pointer, std::string("expected ") + what + ", found " + value.type_name());
    const double d = value.get<double>();
    if (!std::isfinite(d)) fail(pointer, std::string("expected ") + what + ", found a non-finite number");
    return d;
}

}  // namespace scene_detail

using scene_detail::fail;
using scene_detail::Json;
using scene_detail::member;
using scene_detail::number;
using scene_detail::onlyFields;
using scene_detail::SceneError;
using scene_detail::shown;

namespace {

constexpr int kMaxNesting = 64;  // a scene is a few levels deep; deeper nesting is an attack on memory

const char* typeName(const Json& value) { return value.type_name(); }

// What a value that should be a whole number is: its type, or for a number JSON reads as a
// fraction (5.0, 1e6), the number and how to write it whole.
std::string wholeOrType(const Json& value) {
    if (value.is_number_float()) return excerpt(value.dump()) + " (a whole number is written without a point or an exponent)";
    if (value.is_number_integer()) return value.dump();  // negative, where only non-negative ones are taken
    return typeName(value);
}

// A world coordinate, checked as a double: 1e39 is finite there but infinite as a float.
float coordinate(const Json& value, const std::string& pointer) {
    const double d = number(value, pointer, "a coordinate in metres");
    if (!range::isCoordinate(d))
        fail(pointer, std::string("expected a coordinate ") + range::kCoordinateText + ", found " + shown(d));
    return static_cast<float>(d);
}

void expectArray(const Json& value, std::size_t size, const std::string& pointer, const char* what, const char* shape) {
    if (!value.is_array() || value.size() != size) fail(pointer, std::string("expected ") + what + " as " + shape);
}

glm::vec2 position2(const Json& value, const std::string& pointer, const char* what) {
    expectArray(value, 2, pointer, what, "[x, z]");
    return {coordinate(value[0], pointer + "/0"), coordinate(value[1], pointer + "/1")};
}

glm::vec3 position3(const Json& value, const std::string& pointer, const char* what) {
    expectArray(value, 3, pointer, what, "[x, y, z]");
    return {coordinate(value[0], pointer + "/0"), coordinate(value[1], pointer + "/1"), coordinate(value[2], pointer + "/2")};
}

glm::vec2 positiveSize(const Json& value, const std::string& pointer) {
    expectArray(value, 2, pointer, "a size in metres", "[x, z]");
    glm::vec2 size;
    for (int axis = 0; axis < 2; ++axis) {
        const std::string at = pointer + "/" + std::to_string(axis);
        const double d = number(value[static_cast<std::size_t>(axis)], at, "a size in metres");
        if (!range::isSize(d)) fail(at, std::string("sizes must be positive, ") + range::kSizeText + ", found " + shown(d));
        size[axis] = static_cast<float>(d);
    }
    return size;
}

// "count" of one group, added to `total` (all groups so far).
int readCount(const Json& group, const std::string& at, long long& total) {
    const Json& count = member(group, at, "count");
    if (!count.is_number_integer()) fail(at + "/count", "expected a whole number, found " + wholeOrType(count));
    const long long n = count.is_number_unsigned() ? static_cast<long long>(std::min<std::uint64_t>(count.get<std::uint64_t>(), INT64_MAX))
                                                   : count.get<long long>();
    if (n < 1 || n > kMaxCharacters) fail(at + "/count", "expected a count from 1 to " + std::to_string(kMaxCharacters) + ", found " + count.dump());
    total += n;
    if (total > kMaxCharacters) fail(at + "/count", "the scene has more than " + std::to_string(kMaxCharacters) + " characters");
    return static_cast<int>(n);
}

void readGroupClips(const Json& group, const std::string& at, const std::map<std::string, std::uint32_t>& clipIndex, crowd::GroupSpec& spec) {
    const Json& names = group["clips"];
    if (!names.is_array() || names.empty()) fail(at + "/clips", "expected a non-empty array of clip names");
    if (names.size() > 256) fail(at + "/clips", "expected at most 256 clip names");
    for (std::size_t c = 0; c < names.size(); ++c) {
        const std::string cat = at + "/clips/" + std::to_string(c);
        if (!names[c].is_string()) fail(cat, std::string("expected a clip name, found ") + typeName(names[c]));
        const auto found = clipIndex.find(names[c].get<std::string>());
        if (found == clipIndex.end()) fail(cat, "no clip is named '" + names[c].get<std::string>() + "'");
        spec.clips.push_back(found->second);
    }
}

// One entry of "groups". `total` counts characters over all groups so far.
crowd::GroupSpec readGroup(const Json& group, const std::string& at, const std::map<std::string, std::uint32_t>& clipIndex,
                           SceneDescription& scene, long long& total) {
    if (!group.is_object()) fail(at, std::string("expected an object, found ") + typeName(group));
    onlyFields(group, at, {"count", "mode", "region", "clips", "speed", "heading", "locomotion", "ground_speed", "pause"}, "a group");
    crowd::GroupSpec spec;
    spec.count = readCount(group, at, total);
    scene_detail::readGroupLocomotion(group, at, clipIndex, scene, spec);
    if (group.contains("mode")) {
        const Json& mode = group["mode"];
        const auto parsed = mode.is_string() ? crowd::modeFromName(mode.get<std::string>()) : std::nullopt;
        if (!parsed) fail(at + "/mode", "expected \"group\", \"goals\" or \"avoid\"");
        spec.mode = *parsed;
    }
    if (group.contains("clips")) readGroupClips(group, at, clipIndex, spec);
    scene_detail::readGroupPause(group, at, spec);
    const Json& region = member(group, at, "region");
    if (!region.is_object()) fail(at + "/region", std::string("expected an object, found ") + typeName(region));
    onlyFields(region, at + "/region", {"centre", "size"}, "a region");
    spec.region.centre = position2(member(region, at + "/region", "centre"), at + "/region/centre", "a centre");
    spec.region.size = positiveSize(member(region, at + "/region", "size"), at + "/region/size");
    if (group.contains("speed")) {
        const Json& speed = group["speed"];
        expectArray(speed, 2, at + "/speed", "a playback speed range [min, max]", "[min, max]");
        const double lo = number(speed[0], at + "/speed/0", "a number"), hi = number(speed[1], at + "/speed/1", "a number");
        if (!(lo > 0 && hi >= lo && hi <= range::kMaxPlaybackSpeed)) fail(at + "/speed", "expected 0 < min <= max <= 4");
        if (!(static_cast<float>(lo) > 0.0F)) fail(at + "/speed/0", "expected a speed above 0 as a float holds it, found " + shown(lo));
        spec.speedRange = {static_cast<float>(lo), static_cast<float>(hi)};
    }
    // Any finite heading is a direction: reduced modulo 360 degrees in double, before float.
    if (group.contains("heading"))
        spec.heading = static_cast<float>(glm::radians(range::reduceDegrees(number(group["heading"], at + "/heading", "degrees"))));
    return spec;
}

void readWaypoints(const Json& points, crowd::CrowdSetup& setup) {
    if (!points.is_array()) fail("/waypoints", std::string("expected an array of [x, z], found ") + typeName(points));
    if (points.size() > range::kMaxWaypoints)
        fail("/waypoints", "expected at most " + std::to_string(range::kMaxWaypoints) + " waypoints, found " + std::to_string(points.size()));
    for (std::size_t w = 0; w < points.size(); ++w)
        setup.waypoints.push_back(position2(points[w], "/waypoints/" + std::to_string(w), "a waypoint"));
}

SceneDescription read(const Json& root, const std::filesystem::path& directory) {
    if (!root.is_object()) fail("", std::string("expected an object, found ") + typeName(root));
    onlyFields(root, "", {"clips", "groups", "seed", "area", "waypoints", "events", "camera", "camera_path"}, "a scene");
    SceneDescription scene;
    std::map<std::string, std::uint32_t> clipIndex;
    scene_detail::readClips(root, directory, scene, clipIndex);
    crowd::CrowdSetup& setup = scene.setup;
    if (root.contains("seed")) {
        const Json& seed = root["seed"];
        if (!seed.is_number_unsigned()) fail("/seed", "expected a non-negative whole number, found " + wholeOrType(seed));
        setup.seed = seed.get<std::uint64_t>();
    }
    const Json& groups = member(root, "", "groups");
    if (!groups.is_array() || groups.empty()) fail("/groups", "expected a non-empty array of groups");
    if (groups.size() > 10'000) fail("/groups", "expected at most 10000 groups, found " + std::to_string(groups.size()));
    long long total = 0;
    glm::vec2 lo(1e30F), hi(-1e30F);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        crowd::GroupSpec spec = readGroup(groups[g], "/groups/" + std::to_string(g), clipIndex, scene, total);
        lo = glm::min(lo, spec.region.centre - 0.5F * spec.region.size);
        hi = glm::max(hi, spec.region.centre + 0.5F * spec.region.size);
        setup.groups.push_back(std::move(spec));
    }
    // Random goals fall in the given area, or else in the box around all spawn regions.
    setup.area = {0.5F * (lo + hi), hi - lo};
    if (root.contains("area")) setup.area.size = positiveSize(root["area"], "/area");
    if (root.contains("waypoints")) readWaypoints(root["waypoints"], setup);
    scene_detail::readEvents(root, clipIndex, scene);
    if (root.contains("camera")) {
        if (root["camera"].is_object()) onlyFields(root["camera"], "/camera", {"eye", "target", "fov"}, "a camera");
        scene.camera = scene_detail::readCamera(root["camera"], "/camera");
    }
    if (root.contains("camera_path")) scene.cameraPath = scene_detail::readCameraPath(root["camera_path"], "/camera_path");
    return scene;
}

SourceLocation locate(const std::string& path, std::string_view text, std::size_t offset) {
    // A 1-based line and column (bytes) for a byte offset.
    SourceLocation where{path, 1, 1};
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++where.line;
            where.column = 1;
        } else {
            ++where.column;
        }
    }
    return where;
}

// Nesting deeper than kMaxNesting, found before the parser builds it (a file of 16 MB of
// '[' would otherwise become 16 million nested arrays); and NUL characters, raw or escaped as
// \u0000. The parser takes a raw NUL for the end of the text (what follows was ignored), and a
// NUL inside a clip's path cut it short: "walk.bvh\u0000x" opened walk.bvh.
std::optional<Error> checkRawText(const std::string& path, std::string_view text) {
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\0') return Error{Error::Kind::BadInput, "a NUL byte: a scene file is JSON text", locate(path, text, i)};
        if (inString) {
            if (c == '\\' && text.substr(i + 1, 5) == "u0000")
                return Error{Error::Kind::BadInput, "a string holds a NUL character (\\u0000)", locate(path, text, i)};
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting)
                return Error{Error::Kind::BadInput, "JSON nested deeper than " + std::to_string(kMaxNesting) + " levels", locate(path, text, i)};
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::nullopt;
}

// Finds the first error with its byte offset: nlohmann reports overflow ("1e999") without
// one in its exception, but hands it to a SAX parser. Also a key given twice in one object,
// which the parser would take the last of silently, named by its JSON path (`duplicate`).
class JsonChecker : public nlohmann::json_sax<Json> {
public:
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(true); }
    bool key(string_t& name) override {
        Level& object = levels_.back();
        if (!object.keys.insert(name).second) {
            duplicate = "at " + pointer() + ": the key '" + excerpt(name) + "' is given twice";
            return false;
        }
        object.key = name;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) override {
        offset = position == 0 ? 0 : position - 1;
        std::string what = e.what();
        const std::size_t syntax = what.find("syntax error");
        const std::size_t tag = what.find("] ");
        message = syntax != std::string::npos ? what.substr(syntax) : tag != std::string::npos ? what.substr(tag + 2) : what;
        return false;
    }
    std::size_t offset = 0;
    std::string message;
    std::string duplicate;  ///< "at /groups/0: the key 'count' is given twice", or empty.

private:
    // An object's keys so far and the one whose value is read, or an array's current index.
    struct Level {
        bool object = true;
        std::set<std::string> keys;
        std::string key;
        std::size_t index = 0, next = 0;
    };
    bool value() {
        if (!levels_.empty() && !levels_.back().object) levels_.back().index = levels_.back().next++;
        return true;
    }
    bool open(bool object) {
        value();
        levels_.push_back({.object = object, .keys = {}, .key = {}, .index = 0, .next = 0});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return true;
    }
    // The JSON path of the innermost object.
    [[nodiscard]] std::string pointer() const {
        std::string at;
        for (std::size_t l = 0; l + 1 < levels_.size(); ++l)
            at += "/" + (levels_[l].object ? excerpt(levels_[l].key) : std::to_string(levels_[l].index));
        return at.empty() ? "/" : at;
    }
    std::vector<Level> levels_;
};

Result<Json> parseJson(const std::string& path, std::string_view text) {
    if (auto bad = checkRawText(path, text)) return *bad;
    JsonChecker checker;
    if (!Json::sax_parse(text, &checker) || !checker.message.empty()) {
        if (!checker.duplicate.empty()) return Error{Error::Kind::BadInput, checker.duplicate, {path, 0, 0}};
        return Error{Error::Kind::BadInput, "invalid JSON: " + checker.message, locate(path, text, checker.offset)};
    }
    return Json::parse(text);
}

}  // namespace

Result<Json> scene_detail::parseJsonText(const std::string& path, std::string_view text) { return parseJson(path, text); }

CameraSpec scene_detail::readCamera(const Json& camera, const std::string& at) {
    if (!camera.is_object()) fail(at, std::string("expected an object, found ") + typeName(camera));
    CameraSpec spec;
    spec.eye = position3(member(camera, at, "eye"), at + "/eye", "an eye position");
    spec.target = position3(member(camera, at, "target"), at + "/target", "a target");
    if (camera.contains("fov")) {
        const double fov = number(camera["fov"], at + "/fov", "degrees");
        if (!(fov > range::kMinFieldOfView && fov < range::kMaxFieldOfView)) fail(at + "/fov", "expected 1 to 170 degrees");
        spec.verticalFovDegrees = static_cast<float>(fov);
    }
    if (glm::length(spec.eye - spec.target) < 1e-3F) fail(at, "eye and target must differ");
    return spec;
}

Result<SceneDescription> parseScene(std::string_view text, const std::string& path) {
    // Every failure names the file: a library's exception included, or running out of memory.
    try {
        auto root = parseJson(path, text);
        if (!root) return root.error();
        SceneDescription scene = read(root.value(), std::filesystem::path(path).parent_path());
        scene.source = path;
        // What the crowd's own checks call each group: its file and JSON path, as errors here do.
        for (std::size_t g = 0; g < scene.setup.groups.size(); ++g) scene.setup.groups[g].name = path + " at /groups/" + std::to_string(g);
        return scene;
    } catch (const SceneError& e) {
        return Error{Error::Kind::BadInput, e.message, {path, 0, 0}};
    } catch (const nlohmann::json::exception& e) {
        return Error{Error::Kind::BadInput, std::string("invalid scene: ") + e.what(), {path, 0, 0}};
    } catch (const std::filesystem::filesystem_error& e) {
        return Error{Error::Kind::BadInput, e.code().message() + " for '" + e.path1().string() + "'", {path, 0, 0}};
    } catch (const std::bad_alloc&) {
        return Error{Error::Kind::Runtime, "not enough memory to read the scene", {path, 0, 0}};
    } catch (const std::length_error&) {
        return Error{Error::Kind::BadInput, "the scene is too large to read", {path, 0, 0}};
    }
}

Result<SceneDescription> loadScene(const std::string& path) {
    constexpr std::uint64_t kMaxSceneBytes = 16ULL << 20;  // a scene is a page of JSON; this is generous
    auto file = readInputFile(path, kMaxSceneBytes, "scene file");
    if (!file) return file.error();
    return parseScene(file.value(), path);
}

}  // namespace throng::app
