#pragma once
// A look-at camera with a perspective projection for Vulkan's clip space (y down, z in [0, 1]).

#include <array>
#include <span>

#include "throng/core/math.h"

namespace throng::render {

struct Camera {
    glm::vec3 eye{0.0F, 10.0F, -20.0F};    ///< World position, metres.
    glm::vec3 target{0.0F, 1.0F, 0.0F};    ///< Point looked at.
    float verticalFovDegrees = 35.0F;
    float nearPlane = 0.1F;                ///< Metres.
    float farPlane = 2000.0F;              ///< Metres.
    /// Moves the image right by this fraction of half the viewport width (normalised device
    /// x), keeping perspective: the demo centres the crowd in the part of the window its HUD
    /// panel leaves free. 0 for a centred view.
    float lensShiftX = 0.0F;

    [[nodiscard]] glm::mat4 viewProjection(float aspect) const;
    /// The same view with the eye moved to the origin: it takes a point's offset from the eye.
    /// Its inverse gives the rays through pixels as directions from the eye without subtracting
    /// the eye from a world position, which in float at 30 km from the origin bent them by
    /// percents (a body's bones missed their own pixels).
    [[nodiscard]] glm::mat4 viewProjectionAtEye(float aspect) const;
    [[nodiscard]] glm::mat4 projection(float aspect) const;
    /// The world direction that is up in the image for a view along `forward`: +Y, or +Z for
    /// a view straight down or up.
    [[nodiscard]] static glm::vec3 upFor(glm::vec3 forward);
};

/// A camera that frames every point in `points` (e.g. the characters' ground positions,
/// raised by `height`), looking down at `elevationDegrees` from azimuth `azimuthDegrees`
/// (0 looks toward +Z from behind the crowd).
[[nodiscard]] Camera frameCrowd(std::span<const glm::vec3> points, float height, float aspect,
                                float azimuthDegrees = 45.0F, float elevationDegrees = 26.0F);

/// A camera looking across the crowd whose ground positions are `points` from a raised
/// pedestrian's or a balcony's height (2.5 to 8 m, growing with the crowd's size), standing
/// just outside the crowd on the side azimuth `azimuthDegrees` looks from and pitched about
/// 10 degrees down, so near characters are large and far ones small and the crowd fills the
/// frame below the horizon.
[[nodiscard]] Camera streetCamera(std::span<const glm::vec3> points, float aspect, float azimuthDegrees = 38.0F);

/// World-space frustum planes of a view-projection matrix (Vulkan depth 0..1), normalised,
/// inside where dot(xyz, p) + w >= 0.
[[nodiscard]] std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProjection);

}  // namespace throng::render
