// Scaling a scene's crowd to a total (scaleScene: the demo's [ and ]).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "scene_file.h"

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

}  // namespace
