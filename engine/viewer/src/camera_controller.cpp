#include "throng/viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace throng::viewer {
namespace {
constexpr float kRadiansPerPixel = 0.005F;
constexpr float kMaxElevation = 1.5F;  // just short of straight down, where the up vector degenerates
}  // namespace

CameraController::CameraController(const Camera& camera) { reset(camera); }

void CameraController::reset(const Camera& camera) {
    target_ = camera.target;
    const glm::vec3 back = camera.eye - camera.target;
    distance_ = std::max(glm::length(back), 0.1F);
    // The eye sits behind the target: the view direction is -back.
    azimuth_ = std::atan2(-back.x, -back.z);
    elevation_ = std::asin(std::clamp(back.y / distance_, -1.0F, 1.0F));
    fov_ = camera.verticalFovDegrees;
    far_ = camera.farPlane;
}

void CameraController::orbit(glm::vec2 pixels) {
    azimuth_ -= pixels.x * kRadiansPerPixel;
    elevation_ = std::clamp(elevation_ + pixels.y * kRadiansPerPixel, -kMaxElevation, kMaxElevation);
}

void CameraController::pan(glm::vec2 pixels) {
    const Camera c = camera();
    const glm::vec3 forward = glm::normalize(c.target - c.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    const float metresPerPixel = distance_ * 0.0015F;
    target_ += (-pixels.x * right + pixels.y * up) * metresPerPixel;
}

void CameraController::zoom(float steps) { distance_ = std::clamp(distance_ * std::pow(0.88F, steps), 0.3F, 5000.0F); }

void CameraController::fly(float forward, float right, float up, float seconds) {
    const Camera c = camera();
    glm::vec3 ahead = c.target - c.eye;
    ahead.y = 0.0F;  // WASD moves over the ground, QE up and down
    ahead = glm::length(ahead) > 1e-4F ? glm::normalize(ahead) : glm::vec3(0, 0, 1);
    const glm::vec3 side = glm::normalize(glm::cross(ahead, glm::vec3(0, 1, 0)));
    const float speed = std::max(2.0F, distance_ * 0.6F);  // metres per second
    target_ += (forward * ahead + right * side + up * glm::vec3(0, 1, 0)) * speed * seconds;
}

void CameraController::lookAt(glm::vec3 point) { target_ = point; }

void CameraController::setDistance(float metres) { distance_ = std::clamp(metres, 0.3F, 5000.0F); }

Camera CameraController::camera() const {
    Camera c;
    const glm::vec3 direction(std::sin(azimuth_) * std::cos(elevation_), -std::sin(elevation_), std::cos(azimuth_) * std::cos(elevation_));
    c.target = target_;
    c.eye = target_ - direction * distance_;
    c.verticalFovDegrees = fov_;
    c.nearPlane = std::max(0.05F, distance_ * 0.01F);
    c.farPlane = std::max(far_, distance_ * 20.0F);
    return c;
}

}  // namespace throng::viewer
