#pragma once
// The scene's look, shared by every frame driver: key light, sky and bounce ambient, fog and a
// ground big enough for the crowd.

#include <array>

#include "throng/gpu/vulkan.h"
#include "throng/render/camera.h"
#include "throng/render/gpu_types.h"

namespace throng::render {

/// The uniforms for `camera` over a `viewport`-sized image, with a ground reaching
/// `groundHalfExtent` metres from the origin.
[[nodiscard]] SceneUniforms makeScene(const Camera& camera, vk::Extent2D viewport, float groundHalfExtent);

/// The sky: the clear colour, matching the fog so the horizon fades into it (linear RGB).
[[nodiscard]] glm::vec3 skyColor();
/// skyColor() as an opaque clear value.
[[nodiscard]] std::array<float, 4> skyClearColor();

}  // namespace throng::render
