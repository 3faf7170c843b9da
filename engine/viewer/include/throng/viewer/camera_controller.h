#pragma once
// Interactive camera for the demo: orbit, pan and zoom around a target, fly with WASD/QE,
// frame the crowd, or follow one character. Pure state and arithmetic; input comes in as values.

#include <span>

#include "throng/render/camera.h"

namespace throng::viewer {

using render::Camera;

class CameraController {
public:
    /// Starts at `camera` (e.g. from frameCrowd).
    explicit CameraController(const Camera& camera);

    void orbit(glm::vec2 pixels);              ///< Mouse drag: yaw and pitch around the target.
    void pan(glm::vec2 pixels);                ///< Mouse drag: move target and eye in the view plane.
    void zoom(float steps);                    ///< Wheel: each step moves 12% closer (negative: farther).
    /// Fly: forward/right/up in -1..1 for `seconds`, at a speed that scales with the distance.
    void fly(float forward, float right, float up, float seconds);
    /// Follow: keeps the current view direction and distance but moves the target to `point`.
    void lookAt(glm::vec3 point);
    /// Moves the eye to `metres` from the target along the current view direction.
    void setDistance(float metres);
    /// Replaces the view with `camera` (the F key: frame the crowd).
    void reset(const Camera& camera);

    [[nodiscard]] Camera camera() const;

private:
    glm::vec3 target_{0.0F};
    float distance_ = 10.0F;
    float azimuth_ = 0.0F;    ///< Radians about +Y; 0 looks toward +Z.
    float elevation_ = 0.3F;  ///< Radians above the horizon, looking down.
    float fov_ = 35.0F;
    float far_ = 2000.0F;
};

}  // namespace throng::viewer
