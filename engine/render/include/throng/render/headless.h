#pragma once
// Offscreen rendering: one frame of the crowd into an MSAA image, resolved, copied to a host
// buffer (honouring its row pitch) and handed back as tightly packed RGBA8 (sRGB) pixels.

#include <span>
#include <vector>

#include "throng/render/camera.h"
#include "throng/render/crowd_renderer.h"

namespace throng::render {

struct HeadlessOptions {
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    std::uint32_t msaa = 4;          ///< Wanted sample count; lowered to what the device supports.
    bool readInstances = false;      ///< Also copy the resolved instance buffer back.
};

struct HeadlessFrame {
    std::uint32_t width = 0, height = 0;
    std::uint32_t samples = 1;             ///< MSAA sample count actually used.
    std::vector<std::uint8_t> rgba;        ///< width × height × 4, rows top to bottom, sRGB.
    std::vector<InstanceGpu> instances;    ///< characters × joints, when requested.
    double setupMilliseconds = 0.0;        ///< Pipelines, images and buffers (once per run).
    double frameMilliseconds = 0.0;        ///< Character upload, compute, draw, resolve and readback copy, wall clock.
};

/// The default look: key light, sky and bounce ambient, fog, a ground big enough for the crowd.
[[nodiscard]] SceneUniforms makeScene(const Camera& camera, float aspect, float groundHalfExtent);

/// The clear colour, matching the fog so the horizon fades into the sky (linear RGB).
[[nodiscard]] glm::vec3 skyColor();

/// Renders one frame. Throws VulkanError on device failure.
[[nodiscard]] HeadlessFrame renderHeadless(const gpu::Context& context, const Palette& palette,
                                           std::span<const crowd::CharacterState> characters, const SceneUniforms& scene,
                                           const HeadlessOptions& options);

}  // namespace throng::render
