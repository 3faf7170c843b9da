// A scene's "events": at a time, a group plays another clip or blends another locomotion set,
// crossfading over "fade" seconds, and/or takes new ground speeds; and a group's "pause" at
// its goals. Checked here as far as the file can say; Crowd::spawn checks the rest (skeletons).
#include "scene_reading.h"
#include "throng/core/supported_range.h"

namespace throng::app::scene_detail {
namespace {

// [min, max] or one number of seconds within [0, most].
glm::vec2 readSecondsRange(const Json& value, const std::string& at, double most) {
    const bool pair = value.is_array() && value.size() == 2;
    if (!value.is_number() && !pair) fail(at, "expected seconds as a number or [min, max]");
    const double lo = number(pair ? value[0] : value, pair ? at + "/0" : at, "seconds");
    const double hi = pair ? number(value[1], at + "/1", "seconds") : lo;
    if (!(lo >= 0.0 && hi >= lo && hi <= most)) fail(at, "expected 0 <= min <= max <= " + shown(most) + " s, found " + value.dump());
    return {static_cast<float>(lo), static_cast<float>(hi)};
}

crowd::CrowdEvent readEvent(const Json& entry, const std::string& at, const std::map<std::string, std::uint32_t>& clipIndex,
                            SceneDescription& scene) {
    if (!entry.is_object()) fail(at, std::string("expected an object, found ") + entry.type_name());
    onlyFields(entry, at, {"time", "group", "play", "locomotion", "ground_speed", "fade"}, "an event");
    crowd::CrowdEvent event;
    event.time = number(member(entry, at, "time"), at + "/time", "seconds");
    if (!(event.time >= 0 && event.time <= range::kMaxTimeSeconds))
        fail(at + "/time", "expected 0 to " + shown(range::kMaxTimeSeconds) + " seconds, found " + shown(event.time));
    const Json& group = member(entry, at, "group");
    if (!group.is_number_unsigned() || group.get<std::uint64_t>() >= scene.setup.groups.size())
        fail(at + "/group", "expected the index of a group, 0 to " + std::to_string(scene.setup.groups.size() - 1) + ", found " + group.dump());
    event.group = static_cast<std::uint32_t>(group.get<std::uint64_t>());
    if (entry.contains("play")) {
        if (entry.contains("locomotion")) fail(at + "/play", "an event plays a clip or blends a \"locomotion\" set; give one or the other");
        const Json& name = entry["play"];
        const auto clip = name.is_string() ? clipIndex.find(name.get<std::string>()) : clipIndex.end();
        if (clip == clipIndex.end()) fail(at + "/play", "expected the name of a clip, found " + name.dump());
        event.clip = clip->second;
    }
    if (entry.contains("locomotion")) {
        // Read as a group's set would be (shared with any group of the same clips).
        crowd::GroupSpec spec;
        readGroupLocomotion(entry, at, clipIndex, scene, spec);
        event.locomotion = spec.locomotion;
    }
    if (entry.contains("ground_speed")) {
        // A clip played alone walks at its own pace: the speeds would change nothing.
        if (event.clip) fail(at + "/ground_speed", "a clip played alone (\"play\") walks at its own pace: ground_speed needs \"locomotion\"");
        event.groundSpeed = readGroundSpeed(entry["ground_speed"], at + "/ground_speed");
    }
    if (!event.clip && !event.locomotion && !event.groundSpeed) fail(at, "expected \"play\", \"locomotion\" or \"ground_speed\": what changes");
    if (entry.contains("fade")) {
        const double fade = number(entry["fade"], at + "/fade", "seconds");
        if (!(fade >= 0 && fade <= crowd::CrowdEvent::kLongestFade))
            fail(at + "/fade", "expected 0 to " + shown(crowd::CrowdEvent::kLongestFade) + " seconds, found " + shown(fade));
        event.fade = static_cast<float>(fade);
    }
    return event;
}

}  // namespace

void readGroupPause(const Json& group, const std::string& at, crowd::GroupSpec& spec) {
    if (group.contains("pause")) spec.pause = readSecondsRange(group["pause"], at + "/pause", range::kMaxTimeSeconds);
}

void readEvents(const Json& root, const std::map<std::string, std::uint32_t>& clipIndex, SceneDescription& scene) {
    if (!root.contains("events")) return;
    const Json& events = root["events"];
    if (!events.is_array()) fail("/events", std::string("expected an array of events, found ") + events.type_name());
    if (events.size() > 10'000) fail("/events", "expected at most 10000 events, found " + std::to_string(events.size()));
    for (std::size_t e = 0; e < events.size(); ++e)
        scene.setup.events.push_back(readEvent(events[e], "/events/" + std::to_string(e), clipIndex, scene));
}

}  // namespace throng::app::scene_detail
