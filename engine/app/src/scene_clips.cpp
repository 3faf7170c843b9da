// A scene file's "clips": each a path, or an object with a path, an optional name and the
// bake overrides that `--bvh FILE:key=value` takes (clip_spec.h), as JSON fields.
#include <algorithm>
#include <cstdint>
#include <system_error>

#include "clip_spec.h"
#include "scene_reading.h"

namespace throng::app::scene_detail {
namespace {

constexpr std::size_t kMaxClips = 256;

// A clip's file, resolved against the scene's directory. Filesystem errors (a symlink loop,
// an over-long name) are messages here, never exceptions.
std::string clipFile(const std::string& path, const std::filesystem::path& directory, const std::string& at) {
    const std::filesystem::path given(path);
    const std::filesystem::path resolved = given.is_absolute() ? given : directory / given;
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(resolved, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) fail(at, "clip file '" + resolved.string() + "': " + ec.message());
    if (!std::filesystem::exists(status)) fail(at, "clip file '" + resolved.string() + "' does not exist");
    if (!std::filesystem::is_regular_file(status)) fail(at, "clip file '" + resolved.string() + "' is not a regular file");
    return resolved.string();
}

std::string fieldList() {
    std::string list = "name, path";
    for (std::size_t i = 0; i < kClipOverrides.size(); ++i)
        list += (i + 1 == kClipOverrides.size() ? " and " : ", ") + std::string(kClipOverrides[i].field);
    return list;
}

// A whole number as a long long, a huge unsigned one clamped (it is refused by range anyway).
long long wholeNumber(const Json& value) {
    return value.is_number_unsigned() ? static_cast<long long>(std::min<std::uint64_t>(value.get<std::uint64_t>(), INT64_MAX))
                                      : value.get<long long>();
}

motion::LoopRange readLoop(const Json& value, const std::string& at) {
    const bool shaped = value.is_array() && value.size() == 2 && value[0].is_number_integer() && value[1].is_number_integer();
    if (!shaped) fail(at, "expected frame indices as [FIRST, LAST]");
    const long long first = wholeNumber(value[0]), last = wholeNumber(value[1]);
    if (!acceptedLoop(first, last))
        fail(at, "expected frame indices with 0 <= FIRST < LAST, found " + value.dump());
    return {static_cast<int>(first), static_cast<int>(last)};
}

bool readSwitch(const Json& value, const std::string& at) {
    if (!value.is_boolean()) fail(at, std::string("expected true or false, found ") + value.type_name());
    return value.get<bool>();
}

// One field of a clip object that is not "name" or "path": a bake override, each checked by
// the rule the command line's key=value uses, or an unknown field (a typo would otherwise
// leave the clip baked as if the field were absent).
void readOverride(const std::string& field, const Json& value, const std::string& clipAt, motion::BakeOptions& bake) {
    const std::string at = clipAt + "/" + field;
    if (field == "units") {
        const bool ok = value.is_number() && acceptedMetresPerUnit(value.get<double>());
        if (!ok)
            fail(at, "expected a positive number of metres per file unit, at most 1e6, found " +
                         (value.is_number() ? shown(value.get<double>()) : std::string(value.type_name())));
        bake.metresPerUnit = value.get<double>();
    } else if (field == "up") {
        const auto axis = value.is_string() ? motion::upAxisFromName(value.get<std::string>()) : std::nullopt;
        if (!axis) fail(at, "expected the file's up axis: " + upAxisList());
        bake.upAxis = *axis;
    } else if (field == "root") {
        if (!value.is_string() || value.get<std::string>().empty()) fail(at, "expected the name of a joint of the file");
        bake.travelJoint = value.get<std::string>();
    } else if (field == "loop") {
        bake.loop = readLoop(value, at);
    } else if (field == "position_channels") {
        const auto channels = value.is_string() ? positionChannelsFromName(value.get<std::string>()) : std::nullopt;
        if (!channels) fail(at, "expected \"replace\" or \"add\"");
        bake.positionChannels = *channels;
    } else if (field == "straighten") {
        bake.straighten = readSwitch(value, at);
    } else if (field == "foot_lock") {
        bake.footLock = readSwitch(value, at);
    } else if (field == "keep_first_frame") {
        bake.skipFirstFrame = readSwitch(value, at) ? std::optional<bool>(false) : std::nullopt;
    } else {
        fail(clipAt, "unknown field \"" + field + "\" (a clip takes " + fieldList() + ")");
    }
}

// One entry of "clips": its path, and its name (empty when not given) and overrides.
ClipSpec readClip(const Json& clip, const std::string& at, std::string& name) {
    ClipSpec spec;
    if (clip.is_string()) {
        spec.path = clip.get<std::string>();
    } else if (clip.is_object()) {
        const Json& p = member(clip, at, "path");
        if (!p.is_string()) fail(at + "/path", std::string("expected a file path, found ") + p.type_name());
        spec.path = p.get<std::string>();
        if (clip.contains("name")) {
            if (!clip["name"].is_string()) fail(at + "/name", "expected a string");
            name = clip["name"].get<std::string>();
        }
        for (const auto& [field, value] : clip.items())
            if (field != "name" && field != "path") readOverride(field, value, at, spec.bake);
    } else {
        fail(at, std::string("expected a path or {\"name\", \"path\"}, found ") + clip.type_name());
    }
    if (spec.path.empty()) fail(at, "the clip's path is empty");
    return spec;
}

}  // namespace

void readClips(const Json& root, const std::filesystem::path& directory, SceneDescription& scene,
               std::map<std::string, std::uint32_t>& clipIndex) {
    const Json& clips = member(root, "", "clips");
    if (!clips.is_array() || clips.empty()) fail("/clips", "expected a non-empty array of clips");
    if (clips.size() > kMaxClips) fail("/clips", "expected at most 256 clips, found " + std::to_string(clips.size()));
    for (std::size_t i = 0; i < clips.size(); ++i) {
        const std::string at = "/clips/" + std::to_string(i);
        std::string name;
        ClipSpec spec = readClip(clips[i], at, name);
        if (name.empty()) name = std::filesystem::path(spec.path).stem().string();
        spec.path = clipFile(spec.path, directory, at);
        if (clipIndex.count(name)) fail(at, "clip name '" + name + "' is used twice");
        clipIndex[name] = static_cast<std::uint32_t>(i);
        scene.clips.push_back(std::move(spec));
        scene.clipNames.push_back(name);
    }
}

}  // namespace throng::app::scene_detail
