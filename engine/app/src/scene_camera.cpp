// Camera paths (scene_file.h): keyframes read from a scene's "camera_path" or a file of its own,
// and the camera between them.
#include <algorithm>
#include <cmath>

#include "scene_reading.h"
#include "throng/core/input_file.h"

namespace throng::app {

using scene_detail::fail;
using scene_detail::Json;
using scene_detail::SceneError;

std::vector<CameraKey> scene_detail::readCameraPath(const Json& keys, const std::string& at) {
    if (!keys.is_array() || keys.empty()) fail(at, "expected a non-empty array of keyframes {\"time\", \"eye\", \"target\", \"fov\"}");
    if (keys.size() > range::kMaxWaypoints)
        fail(at, "expected at most " + std::to_string(range::kMaxWaypoints) + " keyframes, found " + std::to_string(keys.size()));
    std::vector<CameraKey> path;
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::string key = at + "/" + std::to_string(k);
        if (!keys[k].is_object()) fail(key, "expected a keyframe object");
        scene_detail::onlyFields(keys[k], key, {"time", "eye", "target", "fov"}, "a keyframe");
        const double time = number(member(keys[k], key, "time"), key + "/time", "seconds");
        if (!range::within(time, 0.0, range::kMaxTimeSeconds))
            fail(key + "/time", "expected seconds from 0 to " + std::to_string(static_cast<int>(range::kMaxTimeSeconds)) + ", found " + shown(time));
        if (!path.empty() && !(time > path.back().time))
            fail(key + "/time", "expected a time after the keyframe before (" + shown(path.back().time) + " s), found " + shown(time));
        CameraSpec camera = readCamera(keys[k], key);
        // A keyframe without "fov" keeps the one before (the default view's for the first).
        if (!keys[k].contains("fov") && !path.empty()) camera.verticalFovDegrees = path.back().camera.verticalFovDegrees;
        path.push_back({time, camera});
    }
    return path;
}

Result<std::vector<CameraKey>> loadCameraPath(const std::string& path) {
    constexpr std::uint64_t kMaxBytes = 16ULL << 20;
    auto text = readInputFile(path, kMaxBytes, "camera path file");
    if (!text) return text.error();
    try {
        auto root = scene_detail::parseJsonText(path, text.value());
        if (!root) return root.error();
        if (!root.value().is_object() || !root.value().contains("camera_path"))
            fail("", "expected an object with a \"camera_path\" array of keyframes");
        return scene_detail::readCameraPath(root.value()["camera_path"], "/camera_path");
    } catch (const SceneError& e) {
        return Error{Error::Kind::BadInput, e.message, {path, 0, 0}};
    } catch (const nlohmann::json::exception& e) {
        return Error{Error::Kind::BadInput, std::string("invalid camera path: ") + e.what(), {path, 0, 0}};
    }
}

CameraSpec cameraAt(std::span<const CameraKey> path, double time) {
    if (path.size() == 1 || !(time > path.front().time)) return path.front().camera;
    if (!(time < path.back().time)) return path.back().camera;
    const auto after = std::upper_bound(path.begin(), path.end(), time, [](double t, const CameraKey& key) { return t < key.time; });
    const auto k = static_cast<std::size_t>(after - path.begin()) - 1;
    const std::size_t before = k == 0 ? 0 : k - 1, next = std::min(k + 2, path.size() - 1);
    const auto u = static_cast<float>((time - path[k].time) / (path[k + 1].time - path[k].time));
    // Catmull-Rom through the keyframes (uniform in keyframe order), ends repeated.
    const auto curve = [&](glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
        return 0.5F * (2.0F * p1 + (p2 - p0) * u + (2.0F * p0 - 5.0F * p1 + 4.0F * p2 - p3) * u * u + (3.0F * p1 - p0 - 3.0F * p2 + p3) * u * u * u);
    };
    CameraSpec camera;
    camera.eye = curve(path[before].camera.eye, path[k].camera.eye, path[k + 1].camera.eye, path[next].camera.eye);
    camera.target = curve(path[before].camera.target, path[k].camera.target, path[k + 1].camera.target, path[next].camera.target);
    camera.verticalFovDegrees = path[k].camera.verticalFovDegrees + (path[k + 1].camera.verticalFovDegrees - path[k].camera.verticalFovDegrees) * u;
    // A curve that brings eye and target together would have no direction: keep them apart.
    if (glm::length(camera.eye - camera.target) < 1e-3F) camera.target = camera.eye + (path[k + 1].camera.target - path[k + 1].camera.eye);
    return camera;
}

}  // namespace throng::app
