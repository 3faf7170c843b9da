// A scene group's locomotion set: "locomotion" names a clip per part (idle, slow_walk, walk,
// jog, run), "ground_speed" the speeds its characters want. Read with the file; checked
// against the baked clips once they exist, since only the bake knows whether a clip stands or
// walks and how fast.
#include <algorithm>
#include <cstdio>

#include "scene_reading.h"
#include "throng/core/supported_range.h"

namespace throng::app {
namespace scene_detail {
namespace {

bool isPart(const std::string& key) {
    return std::find(kLocomotionParts.begin(), kLocomotionParts.end(), key) != kLocomotionParts.end();
}

std::string partList() {
    std::string list;
    for (std::size_t i = 0; i < kLocomotionParts.size(); ++i)
        list += (i == 0 ? "" : i + 1 == kLocomotionParts.size() ? " and " : ", ") + std::string(kLocomotionParts[i]);
    return list;
}

// The parts of "locomotion" in kLocomotionParts order, each a clip of the scene.
std::vector<SceneLocomotion::Part> readParts(const Json& parts, const std::string& at,
                                             const std::map<std::string, std::uint32_t>& clipIndex) {
    if (!parts.is_object() || parts.empty())
        fail(at, "expected an object naming a clip per part, e.g. {\"idle\": \"stand\", \"walk\": \"walk\"}; the parts are " +
                     partList());
    for (const auto& [key, value] : parts.items())
        if (!isPart(key)) fail(at + "/" + key, "unknown part \"" + key + "\" (a locomotion set takes " + partList() + ")");
    std::vector<SceneLocomotion::Part> found;
    for (const std::string_view role : kLocomotionParts) {
        const std::string key(role), partAt = at + "/" + key;
        if (!parts.contains(key)) continue;
        const Json& name = parts[key];
        if (!name.is_string()) fail(partAt, std::string("expected a clip name, found ") + name.type_name());
        const auto clip = clipIndex.find(name.get<std::string>());
        if (clip == clipIndex.end()) fail(partAt, "no clip is named '" + name.get<std::string>() + "'");
        for (const SceneLocomotion::Part& earlier : found)
            if (earlier.clip == clip->second) fail(partAt, "clip '" + clip->first + "' is already the set's " + earlier.role);
        found.push_back({key, clip->first, clip->second});
    }
    if (found.size() == 1 && found.front().role == "idle")
        fail(at, "expected a gait too (slow_walk, walk, jog or run): an idle alone can't travel");
    return found;
}

}  // namespace

glm::vec2 readGroundSpeed(const Json& value, const std::string& at) {
    const bool pair = value.is_array() && value.size() == 2;
    if (!value.is_number() && !pair) fail(at, "expected a ground speed in m/s as a number or [min, max]");
    const double lo = number(pair ? value[0] : value, pair ? at + "/0" : at, "a speed in m/s");
    const double hi = pair ? number(value[1], at + "/1", "a speed in m/s") : lo;
    if (!(lo >= 0.0 && hi >= lo && hi <= range::kLargestSpeed))
        fail(at, "expected 0 <= min <= max <= " + shown(range::kLargestSpeed) + " m/s, found " + value.dump());
    return {static_cast<float>(lo), static_cast<float>(hi)};
}

void readGroupLocomotion(const Json& group, const std::string& at, const std::map<std::string, std::uint32_t>& clipIndex,
                         SceneDescription& scene, crowd::GroupSpec& spec) {
    if (!group.contains("locomotion")) {
        if (group.contains("ground_speed"))
            fail(at + "/ground_speed", "a ground speed needs \"locomotion\", a set to blend; \"clips\" play at their playback \"speed\"");
        return;
    }
    if (group.contains("clips"))
        fail(at + "/clips", "a group blends its \"locomotion\" set or plays \"clips\"; give one or the other");
    if (group.contains("speed"))
        fail(at + "/speed", "\"speed\" is a playback multiplier for \"clips\"; a locomotion group's speed is \"ground_speed\" in m/s");
    SceneLocomotion named{at + "/locomotion", 0, readParts(group["locomotion"], at + "/locomotion", clipIndex)};
    std::vector<std::uint32_t> members;
    for (const SceneLocomotion::Part& part : named.parts) members.push_back(part.clip);
    std::sort(members.begin(), members.end());
    // Groups of the same clips share a set: one entry however many groups blend it.
    const auto same = std::find(scene.locomotionMembers.begin(), scene.locomotionMembers.end(), members);
    named.set = static_cast<std::uint32_t>(same - scene.locomotionMembers.begin());
    if (same == scene.locomotionMembers.end()) scene.locomotionMembers.push_back(std::move(members));
    spec.locomotion = named.set;
    if (group.contains("ground_speed")) spec.groundSpeed = readGroundSpeed(group["ground_speed"], at + "/ground_speed");
    scene.locomotionGroups.push_back(std::move(named));
}

}  // namespace scene_detail

namespace {

std::string speedText(double metresPerSecond) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f m/s", metresPerSecond);
    return text;
}

// Whether each part of `named` is what it is called in the set the bake made of its clips: the
// idle stands, every gait walks, and the gaits' speeds rise in kLocomotionParts' order.
std::optional<std::string> misnamedPart(const SceneLocomotion& named, const motion::LocomotionSet& set) {
    // Every clip of a set is its idle or one of its gaits.
    const auto gaitOf = [&set](std::uint32_t clip) -> const motion::LocomotionClip* {
        const auto gait = std::find_if(set.gaits.begin(), set.gaits.end(), [clip](const auto& g) { return g.clip == clip; });
        return gait == set.gaits.end() ? nullptr : &*gait;
    };
    const SceneLocomotion::Part* slower = nullptr;
    double slowerSpeed = 0.0;
    for (const SceneLocomotion::Part& part : named.parts) {
        const std::string at = "at " + named.at + "/" + part.role + ": clip '" + part.clipName + "'";
        const motion::LocomotionClip* gait = gaitOf(part.clip);
        if (part.role == "idle") {
            if (gait == nullptr) continue;
            return at + " walks (a gait at " + speedText(gait->speed) + "): an idle stands still";
        }
        if (gait == nullptr) return at + " stands (no gait): " + part.role + " names a clip that walks or runs";
        if (slower != nullptr && !(gait->speed > slowerSpeed))
            return at + " goes " + speedText(gait->speed) + ", slower than the " + slower->role + " '" + slower->clipName + "' (" +
                   speedText(slowerSpeed) + "): the gaits' speeds rise from slow_walk to walk, jog and run";
        slower = &part;
        slowerSpeed = gait->speed;
    }
    return std::nullopt;
}

}  // namespace

Result<std::vector<motion::LocomotionSet>> makeSceneLocomotionSets(const SceneDescription& scene,
                                                                   std::span<const motion::BakedClip> clips) {
    // The first group that names a set speaks for it: the set's refusal is about its clips.
    const auto firstGroup = [&](std::size_t set) -> const SceneLocomotion* {
        for (const SceneLocomotion& named : scene.locomotionGroups)
            if (named.set == set) return &named;
        return nullptr;
    };
    std::vector<motion::LocomotionSet> sets;
    for (std::size_t s = 0; s < scene.locomotionMembers.size(); ++s) {
        auto set = motion::makeLocomotionSet(clips, scene.locomotionMembers[s]);
        if (!set) {
            const SceneLocomotion* named = firstGroup(s);
            if (named == nullptr) return set.error();
            return Error{Error::Kind::BadInput, "at " + named->at + ": " + set.error().message, {scene.source, 0, 0}};
        }
        sets.push_back(std::move(set.value()));
    }
    for (const SceneLocomotion& named : scene.locomotionGroups)
        if (std::optional<std::string> problem = misnamedPart(named, sets.at(named.set)))
            return Error{Error::Kind::BadInput, *problem, {scene.source, 0, 0}};
    return sets;
}

}  // namespace throng::app
