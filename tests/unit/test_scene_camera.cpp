// Camera paths (scene_file.h): reading keyframes with their errors' JSON paths, and the camera
// between keyframes.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "scene_file.h"

namespace {

using namespace throng;
using namespace throng::app;

std::string writeFile(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("throng_camera_" + name + ".json");
    std::ofstream(path) << text;
    return path.string();
}

std::vector<CameraKey> twoKeys() {
    return {{0.0, {{0.0F, 10.0F, -20.0F}, {0.0F, 0.0F, 0.0F}, 40.0F}}, {2.0, {{20.0F, 2.0F, 0.0F}, {0.0F, 1.0F, 0.0F}, 30.0F}}};
}

TEST(CameraPath, TheCameraIsAtEachKeyframeHeldOutsideAndMovesSmoothlyBetween) {
    const std::vector<CameraKey> path = twoKeys();
    for (double t : {-1.0, 0.0}) EXPECT_EQ(cameraAt(path, t).eye, path[0].camera.eye) << t;
    for (double t : {2.0, 9.0}) EXPECT_EQ(cameraAt(path, t).eye, path[1].camera.eye) << t;
    const CameraSpec middle = cameraAt(path, 1.0);
    EXPECT_NEAR(middle.verticalFovDegrees, 35.0F, 1e-4F);
    // Between two keyframes the curve is their midpoint at half time (ends repeated).
    EXPECT_NEAR(glm::length(middle.eye - glm::vec3(10.0F, 6.0F, -10.0F)), 0.0F, 1e-4F);
    // Small steps in time, small steps of the eye: no jump anywhere.
    glm::vec3 previous = cameraAt(path, 0.0).eye;
    for (double t = 0.01; t <= 2.0; t += 0.01) {
        const glm::vec3 eye = cameraAt(path, t).eye;
        EXPECT_LT(glm::length(eye - previous), 0.5F) << t;
        previous = eye;
    }
}

TEST(CameraPath, KeyframesAreReadFromASceneOrTheirOwnFileAndAKeyWithoutFovKeepsTheOneBefore) {
    const std::string file = writeFile("ok", R"({"camera_path": [{"time": 0, "eye": [0, 10, -20], "target": [0, 0, 0], "fov": 50},
                                                                  {"time": 1.5, "eye": [5, 2, 0], "target": [0, 1, 0]}]})");
    auto path = loadCameraPath(file);
    ASSERT_TRUE(path.ok()) << path.error().describe();
    ASSERT_EQ(path.value().size(), 2U);
    EXPECT_DOUBLE_EQ(path.value()[1].time, 1.5);
    EXPECT_FLOAT_EQ(path.value()[1].camera.verticalFovDegrees, 50.0F);
    EXPECT_EQ(path.value()[1].camera.eye, glm::vec3(5.0F, 2.0F, 0.0F));
}

TEST(CameraPath, BadKeyframesAreRefusedNamingTheFileAndTheJsonPath) {
    const std::pair<const char*, const char*> cases[] = {
        {R"({"camera": {"eye": [0, 1, 2], "target": [0, 0, 0]}})", "at /: expected an object with a \"camera_path\""},
        {R"({"camera_path": []})", "at /camera_path: expected a non-empty array"},
        {R"({"camera_path": [{"time": 1, "eye": [0, 1, 2], "target": [0, 0, 0]}, {"time": 1, "eye": [0, 1, 3], "target": [0, 0, 0]}]})",
         "at /camera_path/1/time: expected a time after the keyframe before"},
        {R"({"camera_path": [{"time": 0, "target": [0, 0, 0]}]})", "at /camera_path/0: missing required field \"eye\""},
        {R"({"camera_path": [{"time": 0, "eye": [0, 1, 1e39], "target": [0, 0, 0]}]})", "at /camera_path/0/eye/2: expected a coordinate"},
        {R"({"camera_path": [{"time": 0, "eye": [0, 1, 2], "target": [0, 0, 0], "fov": 179}]})", "at /camera_path/0/fov: expected 1 to 170 degrees"},
        {R"({"camera_path": [{"time": 700, "eye": [0, 1, 2], "target": [0, 0, 0]}]})", "at /camera_path/0/time: expected seconds from 0 to 600"},
        {R"({"camera_path": [{"time": 0, "eye": [0, 1, 2], "target": [0, 1, 2]}]})", "at /camera_path/0: eye and target must differ"},
        {R"({"camera_path": [)", "invalid JSON"},
    };
    int n = 0;
    for (const auto& [text, says] : cases) {
        const std::string file = writeFile("bad" + std::to_string(n++), text);
        auto path = loadCameraPath(file);
        ASSERT_FALSE(path.ok()) << text;
        EXPECT_EQ(path.error().kind, Error::Kind::BadInput) << text;
        EXPECT_EQ(path.error().location.file, file) << text;
        EXPECT_NE(path.error().describe().find(says), std::string::npos) << path.error().describe();
    }
    EXPECT_FALSE(loadCameraPath("/nonexistent/camera.json").ok());
}

}  // namespace
