#pragma once
// The scene's look, shared by every frame driver: key light, sky and bounce ambient, fog and a
// ground big enough for the crowd.

#include <array>

#include "throng/gpu/vulkan.h"
#include "throng/render/camera.h"
#include "throng/render/gpu_types.h"

namespace throng::render {

/// The uniforms for `camera` over a `viewport`-sized image, with a ground reaching
/// `groundHalfExtent` metres from the origin; `followsPrevious`: the frame comes after one of
/// the same crowd, whose cross-fades between levels of detail it continues (else a still).
[[nodiscard]] SceneUniforms makeScene(const Camera& camera, vk::Extent2D viewport, float groundHalfExtent, bool followsPrevious = false);

/// The frames a character takes to dissolve from one level of detail into the next once its
/// size on screen crosses a threshold (lod_fade.glsl's kLevelFadeFrames): a frame's levels
/// depend on that many frames before it, which a video drawn in parts draws first.
inline constexpr int kLevelFadeFrames = 8;

/// The sky: the clear colour, matching the fog so the horizon fades into it (linear RGB).
[[nodiscard]] glm::vec3 skyColor();
/// skyColor() as an opaque clear value.
[[nodiscard]] std::array<float, 4> skyClearColor();

}  // namespace throng::render
