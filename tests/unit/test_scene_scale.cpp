// Scaling a scene's crowd (scaleScene: `throng bench --scene -n`, the demo's [ and ]), and the
// benchmark scene assets/scenes/bench_transitions.json (#12): loaded, baked and scaled the way
// the bench takes it, every character blends the project's set and is mid-transition at every
// step of the 10 s it promises.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "scene_file.h"
#include "throng/motion/bvh_parser.h"

namespace {

using throng::app::SceneDescription;
using throng::app::scaleScene;

const std::filesystem::path kAssets = std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path();

SceneDescription groupsOf(const std::vector<int>& counts) {
    SceneDescription scene;
    for (const int count : counts) {
        throng::crowd::GroupSpec group;
        group.count = count;
        group.region = {{0.0F, 0.0F}, {10.0F, 20.0F}};
        scene.setup.groups.push_back(group);
    }
    return scene;
}

std::vector<int> countsOf(const SceneDescription& scene) {
    std::vector<int> counts;
    for (const throng::crowd::GroupSpec& group : scene.setup.groups) counts.push_back(group.count);
    return counts;
}

int totalOf(const SceneDescription& scene) {
    const std::vector<int> counts = countsOf(scene);
    return std::accumulate(counts.begin(), counts.end(), 0);
}

TEST(SceneScale, TheScenesOwnTotalChangesNothing) {
    SceneDescription scene = groupsOf({60, 30, 12});
    ASSERT_FALSE(scaleScene(scene, 102));
    EXPECT_EQ(countsOf(scene), (std::vector<int>{60, 30, 12}));
    for (const throng::crowd::GroupSpec& group : scene.setup.groups) EXPECT_EQ(group.region.size, glm::vec2(10.0F, 20.0F));
}

TEST(SceneScale, GroupsKeepTheirProportionsAndTheTotalIsExact) {
    for (const int total : {1000, 10000, 7, 103, 999'999}) {
        SCOPED_TRACE(total);
        SceneDescription scene = groupsOf({60, 30, 12});
        ASSERT_FALSE(scaleScene(scene, total));
        EXPECT_EQ(totalOf(scene), total);
        const std::vector<int> counts = countsOf(scene);
        const std::vector<int> own{60, 30, 12};
        for (std::size_t g = 0; g < counts.size(); ++g) {
            EXPECT_LT(std::abs(counts[g] - own[g] * total / 102.0), 1.0) << "group " << g << " within one of its share";
            // The region keeps the group's density: its area grows with the count.
            const glm::vec2 size = scene.setup.groups[g].region.size;
            EXPECT_NEAR(size.x * size.y / static_cast<float>(counts[g]), 200.0 / own[g], 1e-3 * 200.0 / own[g]);
        }
    }
    SceneDescription twice = groupsOf({60, 30, 12});
    ASSERT_FALSE(scaleScene(twice, 204));
    EXPECT_EQ(countsOf(twice), (std::vector<int>{120, 60, 24})) << "an exact multiple scales every group exactly";
}

TEST(SceneScale, EveryGroupKeepsACharacter) {
    SceneDescription scene = groupsOf({1000, 1, 1});
    ASSERT_FALSE(scaleScene(scene, 3));
    EXPECT_EQ(countsOf(scene), (std::vector<int>{1, 1, 1}));
    SceneDescription five = groupsOf({1000, 1, 1});
    ASSERT_FALSE(scaleScene(five, 5));
    EXPECT_EQ(countsOf(five), (std::vector<int>{3, 1, 1}));
}

TEST(SceneScale, ImpossibleTotalsAreRefusedAndChangeNothing) {
    for (const std::int64_t total : {std::int64_t{2}, std::int64_t{0}, std::int64_t{-5}, std::int64_t{throng::app::kMaxCharacters} + 1}) {
        SCOPED_TRACE(total);
        SceneDescription scene = groupsOf({60, 30, 12});
        scene.source = "some.json";
        const std::optional<throng::Error> refused = scaleScene(scene, total);
        ASSERT_TRUE(refused);
        EXPECT_EQ(refused->kind, throng::Error::Kind::BadInput);
        EXPECT_EQ(refused->location.file, "some.json");
        EXPECT_EQ(countsOf(scene), (std::vector<int>{60, 30, 12}));
    }
    SceneDescription none;
    EXPECT_TRUE(scaleScene(none, 10)) << "a scene with no groups has nothing to scale";
}

// The bench's crowd from the scene: its clips baked, its sets made, scaled to `characters`.
struct BenchCrowd {
    std::vector<throng::motion::BakedClip> clips;
    throng::crowd::Crowd crowd;
};

BenchCrowd benchCrowd(int characters) {
    auto scene = throng::app::loadScene((kAssets / "scenes/bench_transitions.json").string());
    if (!scene) throw throng::ThrongException(scene.error());
    std::vector<throng::motion::BakedClip> clips;
    for (const throng::app::ClipSpec& spec : scene.value().clips)
        clips.push_back(throng::motion::bake(throng::motion::loadBvhFile(spec.path).orThrow(), spec.bake).orThrow());
    scene.value().setup.locomotion = throng::app::makeSceneLocomotionSets(scene.value(), clips).orThrow();
    if (auto refused = scaleScene(scene.value(), characters)) throw throng::ThrongException(*refused);
    auto crowd = throng::crowd::Crowd::spawn(clips, scene.value().setup).orThrow();
    return {std::move(clips), std::move(crowd)};
}

// Steps `steps` times by the bench's 1/30 s and checks every character after each step, as the
// bench's timed frames see them: the project's whole set, two of its clips blended, and a
// transition's outgoing clip still showing.
void expectBlendingAndCrossfading(BenchCrowd& bench, int steps) {
    int failures = 0;
    for (int s = 0; s < steps && failures < 5; ++s) {
        bench.crowd.step(bench.clips, 1.0 / 30.0);
        for (int i = 0; i < bench.crowd.size() && failures < 5; ++i) {
            const throng::motion::LocomotionSet* set = bench.crowd.locomotion(i);
            const bool wholeSet = set != nullptr && set->idle.has_value() && set->gaits.size() == 3;
            const float blend = bench.crowd.blendWeight(i), from = bench.crowd.fromWeight(i);
            const bool ok = wholeSet && blend > 0.0F && blend < 1.0F && from > 0.0F && from < 1.0F;
            if (!ok) ++failures;
            EXPECT_TRUE(ok) << "step " << s + 1 << ", character " << i << ": whole set " << wholeSet << ", blend " << blend
                            << ", from weight " << from;
        }
    }
}

TEST(BenchTransitionsScene, EveryCharacterBlendsAndCrossfadesAtTheBenchsFrames) {
    BenchCrowd bench = benchCrowd(10000);  // the scene's own size, the one #12 asks about
    ASSERT_EQ(bench.crowd.size(), 10000);
    EXPECT_EQ(bench.crowd.fromWeight(0), 1.0F) << "the event at time 0 applies at spawn; every bench frame steps first";
    expectBlendingAndCrossfading(bench, 3 + 20);  // the bench's default warm-up and timed frames
}

TEST(BenchTransitionsScene, ItKeepsBlendingAndCrossfadingForItsTenSeconds) {
    BenchCrowd bench = benchCrowd(300);  // scaled down, as -n does, for the long run
    ASSERT_EQ(bench.crowd.size(), 300);
    expectBlendingAndCrossfading(bench, 10 * 30 - 1);  // the 10 s fade's last step ends it
}

}  // namespace
