// Scene files' locomotion sets (#12): a group's "locomotion" names clips by part and its
// "ground_speed" the speeds its characters want; groups of the same clips share one set; bad
// fields are refused at their JSON path, and once the clips are baked a set the bake refuses,
// or a part that is not what it is called, is refused naming the file and the group.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scene_file.h"
#include "throng/motion/bvh_parser.h"

namespace {

using throng::app::SceneDescription;
using throng::app::SceneLocomotion;

const std::filesystem::path kAssets = std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path();
const std::string kScenePath = (kAssets / "test-locomotion-scene.json").string();
// The project's own set, each clip named as its part, and a second name for the walk.
const std::string kClips = R"("clips": [{"name": "idle", "path": "idle.bvh"}, {"name": "slow", "path": "slow_walk.bvh"},
                                        {"name": "walk", "path": "walk.bvh"}, {"name": "run", "path": "run.bvh"},
                                        {"name": "walk-again", "path": "walk.bvh"}])";

// A group in a 10 x 10 m region with `fields` added.
std::string group(const std::string& fields) {
    return R"({"count": 3, "region": {"centre": [0, 0], "size": [10, 10]})" + (fields.empty() ? "" : ", " + fields) + "}";
}

throng::Result<SceneDescription> sceneOf(const std::vector<std::string>& groups, const std::string& clips = kClips) {
    std::string list;
    for (const std::string& g : groups) list += (list.empty() ? "" : ", ") + g;
    return throng::app::parseScene("{" + clips + R"(, "groups": [)" + list + "]}", kScenePath);
}

void expectRefused(const std::vector<std::string>& groups, const std::string& message) {
    SCOPED_TRACE(groups.front());
    auto scene = sceneOf(groups);
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().kind, throng::Error::Kind::BadInput);
    EXPECT_NE(scene.error().message.find(message), std::string::npos) << scene.error().message;
    EXPECT_EQ(scene.error().location.file, kScenePath) << "the error names the file";
}

// The scene's sets over its baked clips, as prepareCrowdScene makes them.
throng::Result<std::vector<throng::motion::LocomotionSet>> setsOf(const SceneDescription& scene) {
    std::vector<throng::motion::BakedClip> clips;
    for (const throng::app::ClipSpec& spec : scene.clips) {
        auto raw = throng::motion::loadBvhFile(spec.path);
        if (!raw) return raw.error();
        auto baked = throng::motion::bake(raw.value(), spec.bake);
        if (!baked) return baked.error();
        clips.push_back(std::move(baked.value()));
    }
    return throng::app::makeSceneLocomotionSets(scene, clips);
}

void expectSetRefused(const std::vector<std::string>& groups, const std::string& message) {
    SCOPED_TRACE(groups.front());
    auto scene = sceneOf(groups);
    ASSERT_TRUE(scene.ok()) << scene.error().describe();
    auto sets = setsOf(scene.value());
    ASSERT_FALSE(sets.ok());
    EXPECT_EQ(sets.error().kind, throng::Error::Kind::BadInput);
    EXPECT_NE(sets.error().message.find(message), std::string::npos) << sets.error().message;
    EXPECT_EQ(sets.error().location.file, kScenePath) << "the error names the file";
}

TEST(SceneLocomotion, AGroupBlendsTheClipsItNamesAtItsGroundSpeeds) {
    auto scene = sceneOf({group(R"("mode": "goals", "locomotion": {"run": "run", "idle": "idle", "walk": "walk"},
                                    "ground_speed": [0.5, 2.5])")});
    ASSERT_TRUE(scene.ok()) << scene.error().describe();
    const SceneDescription& s = scene.value();
    EXPECT_EQ(s.source, kScenePath);
    ASSERT_EQ(s.setup.groups.size(), 1U);
    const throng::crowd::GroupSpec& g = s.setup.groups[0];
    EXPECT_EQ(g.locomotion, std::optional<std::uint32_t>(0));
    EXPECT_TRUE(g.clips.empty());
    EXPECT_EQ(g.groundSpeed, glm::vec2(0.5F, 2.5F));
    EXPECT_EQ(g.mode, throng::crowd::Mode::Goals);
    ASSERT_EQ(s.locomotionMembers.size(), 1U);
    EXPECT_EQ(s.locomotionMembers[0], (std::vector<std::uint32_t>{0, 2, 3}));
    // The parts in the order idle, slow_walk, walk, jog, run, whatever the file's order.
    ASSERT_EQ(s.locomotionGroups.size(), 1U);
    const SceneLocomotion& named = s.locomotionGroups[0];
    EXPECT_EQ(named.at, "/groups/0/locomotion");
    ASSERT_EQ(named.parts.size(), 3U);
    EXPECT_EQ(named.parts[0].role, "idle");
    EXPECT_EQ(named.parts[1].role, "walk");
    EXPECT_EQ(named.parts[2].role, "run");
    EXPECT_EQ(named.parts[2].clipName, "run");
    EXPECT_EQ(named.parts[2].clip, 3U);

    // Baked: one set of an idle and two gaits, the walk slower than the run.
    auto sets = setsOf(s);
    ASSERT_TRUE(sets.ok()) << sets.error().describe();
    ASSERT_EQ(sets.value().size(), 1U);
    const throng::motion::LocomotionSet& set = sets.value()[0];
    ASSERT_TRUE(set.idle.has_value());
    EXPECT_EQ(set.idle->clip, 0U);
    ASSERT_EQ(set.gaits.size(), 2U);
    EXPECT_EQ(set.gaits[0].clip, 2U);
    EXPECT_EQ(set.gaits[1].clip, 3U);
}

TEST(SceneLocomotion, GroundSpeedDefaultsAndTakesOneNumber) {
    auto plain = sceneOf({group(R"("locomotion": {"walk": "walk"})"), group(R"("locomotion": {"walk": "walk"}, "ground_speed": 1.25)"),
                          group(R"("locomotion": {"walk": "walk"}, "ground_speed": [0, 20])")});
    ASSERT_TRUE(plain.ok()) << plain.error().describe();
    EXPECT_EQ(plain.value().setup.groups[0].groundSpeed, throng::crowd::GroupSpec{}.groundSpeed) << "the command line's default too";
    EXPECT_EQ(plain.value().setup.groups[1].groundSpeed, glm::vec2(1.25F, 1.25F));
    EXPECT_EQ(plain.value().setup.groups[2].groundSpeed, glm::vec2(0.0F, 20.0F));
}

TEST(SceneLocomotion, GroupsOfTheSameClipsShareOneSet) {
    auto scene = sceneOf({group(R"("locomotion": {"walk": "walk", "run": "run"})"),
                          group(R"("clips": ["walk"])"),
                          group(R"("locomotion": {"idle": "idle", "walk": "walk", "run": "run"})"),
                          group(R"("locomotion": {"run": "run", "walk": "walk"}, "ground_speed": 2)"),
                          group(R"("locomotion": {"slow_walk": "walk", "jog": "run"})"),
                          group(R"("locomotion": {"idle": "idle", "run": "run", "walk": "walk"})")});
    ASSERT_TRUE(scene.ok()) << scene.error().describe();
    const SceneDescription& s = scene.value();
    ASSERT_EQ(s.locomotionMembers.size(), 2U) << "walk+run and idle+walk+run";
    EXPECT_EQ(s.locomotionMembers[0], (std::vector<std::uint32_t>{2, 3}));
    EXPECT_EQ(s.locomotionMembers[1], (std::vector<std::uint32_t>{0, 2, 3}));
    const std::vector<std::optional<std::uint32_t>> expected{0U, std::nullopt, 1U, 0U, 0U, 1U};
    for (std::size_t g = 0; g < expected.size(); ++g) EXPECT_EQ(s.setup.groups[g].locomotion, expected[g]) << "group " << g;
    EXPECT_EQ(s.locomotionGroups.size(), 5U) << "one per group that names a set";
    EXPECT_EQ(s.locomotionGroups[3].at, "/groups/4/locomotion");
    auto sets = setsOf(s);
    ASSERT_TRUE(sets.ok()) << sets.error().describe();
    EXPECT_EQ(sets.value().size(), 2U);
}

TEST(SceneLocomotion, RefusesBadFieldsAtTheirPath) {
    expectRefused({group(R"("locomotion": {"walk": "wlak"})")}, "at /groups/0/locomotion/walk: no clip is named 'wlak'");
    expectRefused({group(R"("locomotion": {"trot": "walk"})")},
                  "at /groups/0/locomotion/trot: unknown part \"trot\" (a locomotion set takes idle, slow_walk, walk, jog and run)");
    expectRefused({group(R"("locomotion": {"walk": 3})")}, "at /groups/0/locomotion/walk: expected a clip name, found number");
    expectRefused({group(R"("locomotion": ["walk", "run"])")}, "at /groups/0/locomotion: expected an object naming a clip per part");
    expectRefused({group(R"("locomotion": {})")}, "at /groups/0/locomotion: expected an object naming a clip per part");
    expectRefused({group(R"("locomotion": {"idle": "idle"})")}, "at /groups/0/locomotion: expected a gait too");
    expectRefused({group(R"("locomotion": {"walk": "walk", "run": "walk"})")},
                  "at /groups/0/locomotion/run: clip 'walk' is already the set's walk");
    // A set is blended, not played: no "clips" and no playback "speed" beside it.
    expectRefused({group(R"("locomotion": {"walk": "walk"}, "clips": ["walk"])")},
                  "at /groups/0/clips: a group blends its \"locomotion\" set or plays \"clips\"; give one or the other");
    expectRefused({group(R"("locomotion": {"walk": "walk"}, "speed": [1, 1.2])")},
                  "at /groups/0/speed: \"speed\" is a playback multiplier for \"clips\"; a locomotion group's speed is \"ground_speed\"");
    expectRefused({group(R"("clips": ["walk"])"), group(R"("ground_speed": [1, 2])")},
                  "at /groups/1/ground_speed: a ground speed needs \"locomotion\"");
}

TEST(SceneLocomotion, RefusesGroundSpeedsOutOfRange) {
    const std::string walk = R"("locomotion": {"walk": "walk"}, "ground_speed": )";
    expectRefused({group(walk + "[2, 1]")}, "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s, found [2,1]");
    expectRefused({group(walk + "[-0.5, 1]")}, "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s, found [-0.5,1]");
    expectRefused({group(walk + "21")}, "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s, found 21");
    expectRefused({group(walk + "[1, 1e39]")}, "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s");
    expectRefused({group(walk + R"("fast")")}, "at /groups/0/ground_speed: expected a ground speed in m/s as a number or [min, max]");
    expectRefused({group(walk + "[1, 2, 3]")}, "at /groups/0/ground_speed: expected a ground speed in m/s as a number or [min, max]");
    expectRefused({group(walk + R"([1, "2"])")}, "at /groups/0/ground_speed/1: expected a speed in m/s, found string");
    // JSON has no NaN and a double no 1e999: both are refused as the file's text, with a line.
    for (const char* notANumber : {"NaN", "[1, 1e999]"}) {
        auto scene = sceneOf({group(walk + notANumber)});
        ASSERT_FALSE(scene.ok()) << notANumber;
        EXPECT_NE(scene.error().message.find("invalid JSON"), std::string::npos) << scene.error().message;
        EXPECT_EQ(scene.error().location.file, kScenePath);
        EXPECT_GT(scene.error().location.line, 0);
    }
}

TEST(SceneLocomotion, EachPartMustBeWhatItIsCalled) {
    expectSetRefused({group(R"("locomotion": {"idle": "walk", "run": "run"})")},
                     "at /groups/0/locomotion/idle: clip 'walk' walks (a gait at 1.");
    expectSetRefused({group(R"("locomotion": {"walk": "idle", "run": "run"})")},
                     "at /groups/0/locomotion/walk: clip 'idle' stands (no gait): walk names a clip that walks or runs");
    expectSetRefused({group(R"("locomotion": {"walk": "run", "run": "walk"})")},
                     "at /groups/0/locomotion/run: clip 'walk' goes 1.");
    expectSetRefused({group(R"("locomotion": {"slow_walk": "walk", "walk": "slow"})")}, "slower than the slow_walk 'walk'");
    // A misnamed part of a shared set is found in the group that misnames it.
    expectSetRefused({group(R"("locomotion": {"walk": "walk", "run": "run"})"), group(R"("locomotion": {"run": "walk", "jog": "run"})")},
                     "at /groups/1/locomotion/run: clip 'walk' goes");
}

TEST(SceneLocomotion, ASetTheBakeRefusesNamesTheFileAndGroup) {
    // Two names for one walk: two gaits at one speed.
    expectSetRefused({group(R"("clips": ["walk"])"), group(R"("locomotion": {"walk": "walk", "run": "walk-again"})")},
                     "at /groups/1/locomotion: locomotion set: ");
    expectSetRefused({group(R"("locomotion": {"walk": "walk", "run": "walk-again"})")}, "walk at nearly the same speed");
    const std::filesystem::path other = std::filesystem::path(THRONG_SHARED_MOCAP_DIR) / "bvhtoolbox_walk01_19j_zxy_24fps.bvh";
    if (!std::filesystem::exists(other)) GTEST_SKIP() << "needs the shared captures in " << THRONG_SHARED_MOCAP_DIR;
    auto scene = sceneOf({group(R"("locomotion": {"walk": "walk", "run": "other"})")},
                         R"("clips": [{"name": "walk", "path": "walk.bvh"}, {"name": "other", "path": ")" + other.string() + R"("}])");
    ASSERT_TRUE(scene.ok()) << scene.error().describe();
    auto sets = setsOf(scene.value());
    ASSERT_FALSE(sets.ok());
    EXPECT_NE(sets.error().message.find("at /groups/0/locomotion: locomotion set: "), std::string::npos) << sets.error().message;
    EXPECT_NE(sets.error().message.find("has a different skeleton"), std::string::npos) << sets.error().message;
    EXPECT_EQ(sets.error().location.file, kScenePath);
}

TEST(SceneLocomotion, TheCommandLinesSetKeepsItsOwnLine) {
    // A set with no scene group behind it (--locomotion) fails with makeLocomotionSet's words alone.
    SceneDescription described;
    described.clips = {{(kAssets / "idle.bvh").string(), {}}};
    described.locomotionMembers = {{0}};
    auto sets = setsOf(described);
    ASSERT_FALSE(sets.ok());
    EXPECT_EQ(sets.error().message.rfind("locomotion set: no clip shows a gait", 0), 0U) << sets.error().message;
    EXPECT_TRUE(sets.error().location.file.empty());
}

}  // namespace
