// Scene files' "events" and a group's "pause" (#12): a group crossfades at a time to a clip
// ("play") or a set ("locomotion") and/or takes new ground speeds; bad fields are refused at
// their JSON path, naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene_file.h"

namespace {

using throng::app::SceneDescription;

const std::filesystem::path kAssets = std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path();
const std::string kScenePath = (kAssets / "test-events-scene.json").string();

throng::Result<SceneDescription> sceneWith(const std::string& groupFields, const std::string& events) {
    return throng::app::parseScene(
        R"({"clips": [{"name": "idle", "path": "idle.bvh"}, {"name": "walk", "path": "walk.bvh"}, {"name": "run", "path": "run.bvh"}],
            "groups": [{"count": 2, "clips": ["walk"], "region": {"centre": [0, 0], "size": [5, 5]})" +
            groupFields + R"(}], "events": )" + events + "}",
        kScenePath);
}

void expectRefused(const std::string& events, const std::string& message, const std::string& groupFields = "") {
    SCOPED_TRACE(events);
    auto scene = sceneWith(groupFields, events);
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().kind, throng::Error::Kind::BadInput);
    EXPECT_NE(scene.error().message.find(message), std::string::npos) << scene.error().message;
    EXPECT_EQ(scene.error().location.file, kScenePath);
}

TEST(SceneEvents, EventsAndPausesAreRead) {
    auto scene = sceneWith(R"(, "pause": [0.5, 2])",
                           R"([{"time": 2, "group": 0, "play": "run", "fade": 0.4},
                               {"time": 3.5, "group": 0, "locomotion": {"idle": "idle", "walk": "walk", "run": "run"}, "ground_speed": [2, 2.5]},
                               {"time": 5, "group": 0, "ground_speed": 0.5}])");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const auto& setup = scene.value().setup;
    EXPECT_EQ(setup.groups[0].pause, glm::vec2(0.5F, 2.0F));
    ASSERT_EQ(setup.events.size(), 3U);
    EXPECT_EQ(setup.events[0].time, 2.0);
    EXPECT_EQ(setup.events[0].clip, std::optional<std::uint32_t>(2U));
    EXPECT_FLOAT_EQ(setup.events[0].fade, 0.4F);
    ASSERT_TRUE(setup.events[1].locomotion.has_value());
    EXPECT_EQ(scene.value().locomotionMembers.at(*setup.events[1].locomotion).size(), 3U);
    EXPECT_EQ(setup.events[1].groundSpeed, std::optional<glm::vec2>(glm::vec2(2.0F, 2.5F)));
    EXPECT_FLOAT_EQ(setup.events[1].fade, 0.3F) << "the default fade";
    EXPECT_EQ(setup.events[2].groundSpeed, std::optional<glm::vec2>(glm::vec2(0.5F)));
    EXPECT_FALSE(setup.events[2].clip || setup.events[2].locomotion);
}

TEST(SceneEvents, BadEventsAreRefusedAtTheirPath) {
    expectRefused(R"({})", "/events: expected an array");
    expectRefused(R"([{"time": 1, "group": 0}])", "/events/0: expected \"play\", \"locomotion\" or \"ground_speed\"");
    expectRefused(R"([{"time": 1, "group": 1, "play": "run"}])", "/events/0/group: expected the index of a group");
    expectRefused(R"([{"time": 1, "group": -1, "play": "run"}])", "/events/0/group");
    expectRefused(R"([{"time": -1, "group": 0, "play": "run"}])", "/events/0/time");
    expectRefused(R"([{"time": 601, "group": 0, "play": "run"}])", "/events/0/time");
    expectRefused(R"([{"group": 0, "play": "run"}])", "time");
    expectRefused(R"([{"time": 1, "group": 0, "play": "jog"}])", "/events/0/play: expected the name of a clip");
    expectRefused(R"([{"time": 1, "group": 0, "play": "run", "fade": 11}])", "/events/0/fade");
    expectRefused(R"([{"time": 1, "group": 0, "play": "run", "fade": [1, 2]}])", "/events/0/fade");
    expectRefused(R"([{"time": 1, "group": 0, "play": "run", "locomotion": {"walk": "walk"}}])", "/events/0/play: an event plays a clip or blends");
    expectRefused(R"([{"time": 1, "group": 0, "ground_speed": 21}])", "/events/0/ground_speed");
    expectRefused(R"([{"time": 1, "group": 0, "play": "run", "ground_speed": 2}])", "/events/0/ground_speed: a clip played alone");
    expectRefused(R"([{"time": 1, "group": 0, "play": "run", "speed": 2}])", "/events/0/speed: unknown field");
    expectRefused(R"([])", "/groups/0/pause", R"(, "pause": [3, 1])");
    expectRefused(R"([])", "/groups/0/pause", R"(, "pause": -1)");
}

}  // namespace
