#pragma once
// Offscreen rendering: frames of the crowd into an MSAA image, resolved, copied to a host
// buffer (honouring its row pitch) and handed back as tightly packed RGBA8 (sRGB) pixels.

#include <memory>
#include <span>
#include <vector>

#include "throng/render/camera.h"
#include "throng/render/crowd_renderer.h"

namespace throng::render {

struct HeadlessOptions {
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    std::uint32_t msaa = 4;          ///< Wanted sample count; lowered to what the device supports.
    RenderPath path = RenderPath::Compute;
    float lodPixels = 0.0F;          ///< Fast path level of detail (see CrowdRendererCreateInfo).
};

/// Where one offscreen frame's time went, milliseconds.
struct FrameTimings {
    double uploadMs = 0.0;    ///< CPU: writing characters (and, for the cpu path, resolving and writing instances).
    double computeMs = -1.0;  ///< GPU timestamps; negative without timestamp support.
    double drawMs = -1.0;     ///< GPU timestamps: ground, spheres, resolve.
    double readbackMs = 0.0;  ///< Copy to the host buffer and out of it, wall clock.
    double frameMs = 0.0;     ///< The whole frame: upload, submit, wait, readback.
};

/// A reusable offscreen target: renders frame after frame into the same images (for the
/// benchmark), or once (for `throng render`).
class OffscreenRenderer {
public:
    OffscreenRenderer(const gpu::Context& context, const Palette& palette, std::span<const motion::BakedClip> clips,
                      std::uint32_t maxCharacters, const HeadlessOptions& options);
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;
    ~OffscreenRenderer();

    /// Renders one frame and reads its pixels back.
    FrameTimings render(std::span<const crowd::CharacterState> characters, const SceneUniforms& scene);
    /// The last frame: width × height × 4 bytes, sRGB, rows top to bottom.
    [[nodiscard]] std::vector<std::uint8_t> pixels() const;
    /// The last frame's instances (characters × joints, or the fast path's visible ones), and
    /// for the fast path the character of each.
    [[nodiscard]] std::vector<InstanceGpu> instances() const;
    /// Fast path: (character, joint) of each compacted instance; empty for other paths.
    [[nodiscard]] std::vector<glm::uvec2> instanceOwners() const;
    [[nodiscard]] std::uint32_t samples() const { return static_cast<std::uint32_t>(samples_); }
    [[nodiscard]] const CrowdRenderer& renderer() const { return renderer_; }

private:
    struct Targets;
    /// Instances the last frame wrote: all of them, or the fast path's visible count.
    [[nodiscard]] std::size_t instanceCount() const;
    const gpu::Context* context_;
    std::span<const motion::BakedClip> clips_;
    HeadlessOptions options_;
    vk::SampleCountFlagBits samples_;
    CrowdRenderer renderer_;
    std::unique_ptr<Targets> targets_;
    std::vector<InstanceGpu> cpuInstances_;
    std::uint32_t lastCharacters_ = 0;
};


/// The default look: key light, sky and bounce ambient, fog, a ground big enough for the crowd.
[[nodiscard]] SceneUniforms makeScene(const Camera& camera, vk::Extent2D viewport, float groundHalfExtent);

/// The clear colour, matching the fog so the horizon fades into the sky (linear RGB).
[[nodiscard]] glm::vec3 skyColor();

}  // namespace throng::render
