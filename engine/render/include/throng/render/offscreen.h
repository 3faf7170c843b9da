#pragma once
// Offscreen rendering: frames of the crowd into the shared render target, resolved into an
// image of our own, copied to a host buffer and handed back as tightly packed RGBA8 (sRGB).

#include <memory>
#include <span>
#include <vector>

#include "throng/render/crowd_renderer.h"

namespace throng::render {

struct OffscreenOptions {
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    std::uint32_t msaa = 4;          ///< Wanted sample count; lowered to what the device supports.
    RenderPath path = RenderPath::Compute;
    float lodPixels = 0.0F;          ///< Fast path level of detail (see CrowdRendererCreateInfo).
    Body body = Body::Spheres;       ///< What characters are drawn as (bones: fast path only).
    bool readBack = true;            ///< Copy each frame's image to the host (pixels()); false: a frame ends at the draw.
    /// The visibility path draws a frame of the same scene as the last over it, shading again
    /// only where something moved (a still camera); false: every frame from scratch.
    bool keepLastFrame = true;
};

/// Where one offscreen frame's time went, milliseconds.
struct FrameTimings {
    double uploadMs = 0.0;    ///< CPU: writing characters (and, for the cpu path, resolving and writing instances).
    double computeMs = -1.0;  ///< GPU timestamps; negative without timestamp support.
    double drawMs = -1.0;     ///< GPU timestamps: ground, characters, resolve.
    /// The parts of those on the visibility path (GPU timestamps; 0 on paths that don't splat,
    /// negative without timestamps): the splat into the visibility buffer, its clear
    /// included, within computeMs; the shading pass within drawMs (the rest of it is
    /// the raster of what is drawn over it).
    double visibilityMs = -1.0, shadingMs = -1.0;
    double readbackMs = 0.0;  ///< The image's copy into host memory (GPU timestamps) plus the host's read of it.
    double frameMs = 0.0;     ///< The whole frame: upload, submit, wait, readback.
};

/// A reusable offscreen target: renders frame after frame into the same images (for the
/// benchmark), or once (for `throng render`). Any crowd size, frame to frame.
class OffscreenRenderer {
public:
    OffscreenRenderer(const gpu::Context& context, const Palette& palette, std::span<const motion::BakedClip> clips,
                      const OffscreenOptions& options);
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;
    ~OffscreenRenderer();

    /// Renders one frame and reads its pixels back. With `timePasses`, the GPU writes a timestamp
    /// between its passes (FrameTimings' GPU figures; negative without): lavapipe flushes its
    /// work at each, which costs a 2000-character frame about 0.5-0.7 ms, so frames that are
    /// only drawn leave them out.
    /// FrameTimings::uploadMs covers writing the characters (with a crowd as the source: its
    /// packing, straight into the GPU's memory).
    /// `whileDrawing`, if given, runs on this thread between the frame's submission and the
    /// wait for it (the next frame's simulation, overlapped with the GPU's work, as two frames in
    /// flight do); FrameTimings::frameMs includes it.
    FrameTimings render(const CharacterSource& characters, const SceneUniforms& scene, bool timePasses = false,
                        const std::function<void()>& whileDrawing = {});
    FrameTimings render(std::span<const crowd::CharacterState> characters, const SceneUniforms& scene, bool timePasses = false) {
        return render(CharacterSource::of(characters), scene, timePasses);
    }
    /// The last frame: width × height × 4 bytes, sRGB, rows top to bottom.
    [[nodiscard]] const std::vector<std::uint8_t>& pixels() const;
    /// The last frame's resolved joints: characters × joints, or the compacted visible ones.
    [[nodiscard]] std::vector<InstanceGpu> instances() const;
    /// For compacted paths, (character, joint) of each instance; empty for the others.
    [[nodiscard]] std::vector<glm::uvec2> instanceOwners() const;
    /// Bone bodies (bones, skin, auto): per character, the level it was drawn at; empty on
    /// the sphere paths.
    [[nodiscard]] std::vector<BodyLevelGpu> bodyLevels() const;
    /// Bone bodies: every bone drawn in the last frame (BodyLevelGpu::firstBone indexes it).
    [[nodiscard]] std::vector<BoneInstanceGpu> boneInstances() const;
    [[nodiscard]] std::uint32_t samples() const;
    [[nodiscard]] const CrowdRenderer& renderer() const { return renderer_; }

private:
    struct Frame;
    /// Instances the last frame wrote: all of them, or the compacted count.
    [[nodiscard]] std::size_t instanceCount() const;
    const gpu::Context* context_;
    OffscreenOptions options_;
    std::unique_ptr<Frame> frame_;
    CrowdRenderer renderer_;
    std::vector<std::uint8_t> pixels_;
    bool holdsLastFrame_ = false;  ///< The output holds the last frame rendered (the visibility path draws over it).
};

}  // namespace throng::render
