#pragma once
// The per-frame GPU work that draws a crowd: the character buffer upload, the render path's
// compute pass (if it has one) with its barriers, and the ground and characters' draw. The
// path is chosen once; the crowd's size arrives with every frame and may change freely.

#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "throng/gpu/pipeline.h"
#include "throng/gpu/resources.h"
#include "throng/render/gpu_types.h"
#include "throng/render/palette.h"
#include "throng/render/render_path.h"

namespace throng::render {

namespace detail {
class LevelFades;
class RenderPathImpl;
struct SlotBuffers;
}  // namespace detail

struct CrowdRendererCreateInfo {
    RenderPath path = RenderPath::Compute;
    vk::Format colorFormat = vk::Format::eR8G8B8A8Srgb;  ///< Of the target it draws into.
    vk::Format depthFormat = vk::Format::eD32Sfloat;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
    std::uint32_t slots = 1;   ///< Frames in flight: one set of per-frame buffers each.
    float lodPixels = 0.0F;    ///< Fast path: characters shorter than this on screen draw only
                               ///< their major joints (BakedClip::jointDetail); 0 never.
    Body body = Body::Spheres; ///< Bones need the fast path (it culls and ray-casts them).
};

/// The per-character instances a frame stores: a joint sphere each (48 bytes), or a bone each
/// (64 bytes) for bone bodies.
struct CharacterFootprint {
    std::uint32_t count = 0;  ///< Instances per character: its joints, or its bones.
    bool bones = false;
    [[nodiscard]] std::uint64_t bytes() const;
    [[nodiscard]] std::string describe() const { return std::to_string(count) + (bones ? " bones" : " joints"); }
};

/// Where a path keeps a frame's resolved joints, for dumps and figures.
struct InstanceLayout {
    bool exists = true;      ///< False for the paper path: joints are resolved per vertex and never stored.
    bool compacted = false;  ///< Only visible joints, counted by the draw arguments, with an owner each.
    std::uint64_t gpuBytesPerCharacter = 0;  ///< Per-frame GPU memory one character costs on this path and body: every per-character buffer.
};

/// A frame's characters as the renderer takes them: how many, and a way to write any run of
/// them. The renderer hands `write` its batches' GPU-visible memory, so a crowd packs straight
/// into it (on its own threads) with no copy between: a million characters' 64 MB copy was
/// most of a frame's upload. `write` must fill all of `out`, which it must not read.
struct CharacterSource {
    std::size_t count = 0;
    std::function<void(std::size_t first, std::span<crowd::CharacterState> out)> write;
    /// Characters already packed in host memory, copied as they are.
    [[nodiscard]] static CharacterSource of(std::span<const crowd::CharacterState> characters) {
        return {characters.size(), [characters](std::size_t first, std::span<crowd::CharacterState> out) {
                    std::copy_n(characters.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
                }};
    }
};

/// How many characters a frame drew at each level of detail.
struct DetailCounts {
    std::uint32_t full = 0;    ///< With every joint (with bodies: as skin or bones).
    std::uint32_t coarse = 0;  ///< With their major joints only (with bodies: as joint spheres).
    std::uint32_t culled = 0;  ///< Outside the view.
    /// With bodies (--body bones, skin, auto): `full` split into skinned meshes and bone
    /// bodies. A character cross-fading between two levels is counted at both.
    std::optional<std::uint32_t> skin, bones;
    /// With bodies: how many characters are cross-fading between two levels (lod_fade.glsl).
    std::optional<std::uint32_t> fading;
};

/// Where a frame's GPU work splits into the passes the benchmark times apart: the splat into
/// the visibility buffer (after the compute pass's culling, poses and bodies), and the raster
/// after the shading pass.
enum class FramePass : std::uint8_t { Visibility, Raster };
/// Called as the recording reaches a FramePass, for a timestamp there.
using PassBoundary = std::function<void(const vk::raii::CommandBuffer&, FramePass)>;

class CrowdRenderer {
public:
    /// `clips` are the CPU copies of what `palette` holds (the cpu path resolves from them);
    /// both must outlive the renderer.
    CrowdRenderer(const gpu::Context& context, const Palette& palette, std::span<const motion::BakedClip> clips,
                  const CrowdRendererCreateInfo& info);
    CrowdRenderer(const CrowdRenderer&) = delete;
    CrowdRenderer& operator=(const CrowdRenderer&) = delete;
    ~CrowdRenderer();

    /// Largest crowd one storage buffer of resolved joints holds on this device.
    [[nodiscard]] static std::uint64_t maxCharactersFor(const gpu::Context& context, std::uint32_t jointsPerCharacter);
    /// What one character of `clips` stores per frame when drawn as `body`.
    [[nodiscard]] static CharacterFootprint footprintOf(std::span<const motion::BakedClip> clips, Body body);
    /// About how many bytes of GPU memory one character of `clips` drawn as `body` takes per
    /// frame slot, at most (every buffer a path may use, sized for every character).
    [[nodiscard]] static std::uint64_t bytesPerCharacter(std::span<const motion::BakedClip> clips, Body body);
    /// Largest crowd of that footprint one storage buffer holds on this device: a larger crowd
    /// is drawn in batches of at most this many characters, each with its own buffers.
    [[nodiscard]] static std::uint64_t maxCharactersFor(const gpu::Context& context, const CharacterFootprint& footprint);
    /// Why the visibility path can't run on this device (it needs 64-bit buffer atomics, and
    /// more components from vertex to fragment shader than the least a device may offer), one
    /// line ending in advice; nullopt when it can.
    [[nodiscard]] static std::optional<std::string> visibilityPathUnsupported(const gpu::Context& context);
    /// The most pixels a frame may have on the visibility path on this device: its per-pixel
    /// buffer (8 bytes a pixel) must fit one storage buffer, and one texel buffer view too.
    [[nodiscard]] static std::uint64_t visibilityPixelLimit(const gpu::Context& context);
    /// The pixels the visibility path's per-pixel buffers hold for a frame of `extent`: the frame
    /// padded to whole 4 x 4-pixel blocks (visibility.glsl's pixelSlot).
    [[nodiscard]] static std::uint64_t visibilityBufferPixels(vk::Extent2D extent);
    /// The texels the visibility path's contact-shadow buffer holds for a frame of `extent`: one
    /// to each 2 x 2 pixels, and a border of zeros all round (visibility.glsl's shadowSlot).
    [[nodiscard]] static std::uint64_t shadowBufferTexels(vk::Extent2D extent);
    /// " (N pixels in whole 4 x 4-pixel blocks)" where padding a frame of `extent` to whole
    /// blocks makes it larger, else "": for messages that compare it with visibilityPixelLimit.
    [[nodiscard]] static std::string visibilityPaddingNote(vk::Extent2D extent);
    /// Whether a frame of `extent` is within visibilityPixelLimit.
    [[nodiscard]] static bool visibilityFrameFits(const gpu::Context& context, vk::Extent2D extent) {
        return visibilityBufferPixels(extent) <= visibilityPixelLimit(context);
    }

    /// Writes this frame's characters and scene into slot `slot`, growing its buffers when the
    /// crowd outgrew them (in batches of what one storage buffer holds, as many as the crowd
    /// needs), and does the path's host work. The caller has waited for the slot's previous
    /// submission. Throws ThrongException (Runtime) when the device's memory runs out, and
    /// (BadInput) on the visibility path for a crowd past one batch or a frame past
    /// visibilityPixelLimit. `targetHoldsLastFrame`: the colour attachment the frame is drawn
    /// into holds the slot's last frame as this renderer left it (an offscreen image of its
    /// own; not a swapchain's); on the visibility path, a frame of the same scene then draws
    /// only what changed, over it (drawsOverLastFrame).
    void update(std::uint32_t slot, const CharacterSource& characters, const SceneUniforms& scene, bool targetHoldsLastFrame = false);
    void update(std::uint32_t slot, std::span<const crowd::CharacterState> characters, const SceneUniforms& scene,
                bool targetHoldsLastFrame = false) {
        update(slot, CharacterSource::of(characters), scene, targetHoldsLastFrame);
    }
    /// Whether slot `slot`'s frame draws over its last one: begin its rendering keeping the
    /// colour attachment's contents (RenderTarget::begin's keptFrom).
    [[nodiscard]] bool drawsOverLastFrame(std::uint32_t slot) const;
    /// On the visibility path: of the 64-pixel squares of slot `slot`'s last frame, how many
    /// kept the ground the frame before drew there (not shaded again). Waits for the device.
    [[nodiscard]] std::optional<std::uint32_t> keptGroundSquares(std::uint32_t slot) const;
    /// Records the path's compute pass and the barriers that hand its output to the draw; on a
    /// path that splats (splats()), `boundary` (if given) is called with FramePass::Visibility
    /// between its resolve and its splat.
    void recordCompute(const vk::raii::CommandBuffer& commands, std::uint32_t slot, const PassBoundary& boundary = {}) const;
    /// Records the ground and the characters; call inside dynamic rendering. On a path that
    /// splats, `boundary` (if given) is called with FramePass::Raster between its shading pass
    /// and what it rasterises over it (skinned bodies).
    void recordDraw(const vk::raii::CommandBuffer& commands, std::uint32_t slot, vk::Extent2D extent, const PassBoundary& boundary = {}) const;
    /// Whether the path splats into a visibility buffer and shades it in a shading pass
    /// (the visibility path): the passes `boundary` splits off.
    [[nodiscard]] bool splats() const;
    /// Whether recordDraw needs the depth attachment cleared. The splatting path tests depth
    /// only for skinned bodies, and resets it where they may draw (their screen bounds) first.
    [[nodiscard]] bool needsClearedDepth() const { return !splats(); }

    [[nodiscard]] RenderPath path() const;
    [[nodiscard]] InstanceLayout instanceLayout() const;
    [[nodiscard]] std::uint32_t jointsPerCharacter() const { return jointsPerCharacter_; }
    /// Most characters one batch holds on this device (what one storage buffer holds, and for
    /// skinned bodies one texel view too).
    [[nodiscard]] std::uint32_t batchCharacters() const { return batchCharacters_; }
    /// Batches the slot's crowd was split into (1 unless it outgrew one storage buffer).
    [[nodiscard]] std::uint32_t batchCount(std::uint32_t slot) const;
    /// The slot's first batch (all of it when batchCount() is 1): its resolved joints
    /// (InstanceGpu), its draw arguments (DrawArguments) and, when compacted, the (character,
    /// joint) owner of each instance (two uints).
    [[nodiscard]] const gpu::Buffer& instances(std::uint32_t slot) const;
    [[nodiscard]] const gpu::Buffer& drawArguments(std::uint32_t slot) const;
    [[nodiscard]] const gpu::Buffer& instanceOwners(std::uint32_t slot) const;
    /// Bone bodies: the level each character was drawn at, and the bones drawn.
    [[nodiscard]] const gpu::Buffer& bodyLevels(std::uint32_t slot) const;
    [[nodiscard]] const gpu::Buffer& boneInstances(std::uint32_t slot) const;
    [[nodiscard]] std::uint32_t characterCount(std::uint32_t slot) const;  ///< In the slot's first batch.
    /// The slot's last completed frame's level-of-detail counts, summed over its batches (once
    /// its submission has finished); nullopt for paths that draw every character in full.
    [[nodiscard]] std::optional<DetailCounts> detailCounts(std::uint32_t slot) const;

private:
    /// The slot's batch number `batch` (its place among the slot's batches).
    [[nodiscard]] std::unique_ptr<detail::SlotBuffers> makeBatch(std::uint32_t batch);
    void grow(detail::SlotBuffers& batch, std::uint32_t characters) const;
    /// Visibility path: (re)allocates the batch's per-pixel buffer when the frame's size changed.
    void sizeVisibility(detail::SlotBuffers& batch, vk::Extent2D extent) const;
    void bindDescriptors(detail::SlotBuffers& batch) const;
    [[nodiscard]] const detail::SlotBuffers& firstBatch(std::uint32_t slot) const;
    /// Binds each of the slot's active batches (descriptors, push constants) at `bindPoint`
    /// and records `record(batch index, batch)` for it.
    void forEachBatch(const vk::raii::CommandBuffer& commands, std::uint32_t slot, vk::PipelineBindPoint bindPoint,
                      const std::function<void(std::uint32_t, const detail::SlotBuffers&)>& record) const;

    const gpu::Context* context_;
    const Palette* palette_;
    float cullRadius_ = 1.0F, cullHeight_ = 1.0F;
    std::uint32_t jointsPerCharacter_;
    vk::raii::DescriptorSetLayout setLayout_{nullptr};
    vk::raii::PipelineLayout pipelineLayout_{nullptr};
    vk::raii::Pipeline groundPipeline_{nullptr};
    std::unique_ptr<detail::RenderPathImpl> path_;
    std::uint32_t batchCharacters_ = 1;  ///< Most characters one batch's buffers may hold on this device.
    /// Per frame-in-flight slot, its batches; only the first `activeBatches_[slot]` hold this frame's crowd.
    std::vector<std::vector<std::unique_ptr<detail::SlotBuffers>>> slots_;
    std::vector<std::uint32_t> activeBatches_;
    /// Bone bodies' cross-fades between levels, per batch, kept from frame to frame.
    std::unique_ptr<detail::LevelFades> levelFades_;
};

/// Resolves every joint of every character on the CPU, as the compute pass does (the cpu
/// path). `out` holds characters × jointsPerCharacter entries.
void resolveInstancesOnCpu(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> characters,
                           std::uint32_t jointsPerCharacter, std::span<InstanceGpu> out);

}  // namespace throng::render
