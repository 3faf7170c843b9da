#pragma once
// The render paths behind CrowdRenderer: one interface, one implementation per path, chosen
// once when the renderer is made. Private to the render module.

#include <cstddef>
#include <memory>
#include <optional>
#include <span>

#include "binding_numbers.h"
#include "throng/gpu/pipeline.h"
#include "throng/gpu/resources.h"
#include "throng/render/crowd_renderer.h"
#include "throng/render/gpu_types.h"
#include "throng/render/palette.h"
#include "throng/render/render_path.h"

namespace throng::render::detail {

/// What every path is built from: the device, the baked clips (CPU and GPU copies), the one
/// pipeline layout all paths share, and the attachment formats it draws into.
struct PathSetup {
    const gpu::Context* context = nullptr;
    const Palette* palette = nullptr;
    std::span<const motion::BakedClip> clips;
    const vk::raii::PipelineLayout* layout = nullptr;
    vk::Format colorFormat = vk::Format::eUndefined;
    vk::Format depthFormat = vk::Format::eUndefined;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
    std::uint32_t jointsPerCharacter = 0;
};

/// A draw into the target `setup` describes, with the paths' one layout: its shaders and
/// primitives, no vertex input (the shaders pull from the storage buffers), depth tested and
/// written. Each draw changes from here only what differs (vertex input, culling, depth,
/// coverage, blending).
[[nodiscard]] inline gpu::GraphicsPipelineInfo targetPipeline(const PathSetup& setup, const vk::raii::ShaderModule& vertex,
                                                              const vk::raii::ShaderModule* fragment, vk::PrimitiveTopology topology) {
    gpu::GraphicsPipelineInfo info;
    info.vertexShader = &vertex;
    info.fragmentShader = fragment;
    info.layout = setup.layout;
    info.topology = topology;
    info.colorFormat = setup.colorFormat;
    info.depthFormat = setup.depthFormat;
    info.samples = setup.samples;
    return info;
}

/// Bone bodies' writer passes (resolve_bones.comp's kWriter*): joint spheres, bones, skin.
constexpr std::uint32_t kBodyWriters = 3;
/// Per-character stretches of SlotBuffers::characterLists: each body writer's list, then the
/// visibility path's list of the contact shadows too large to splat one invocation a shadow,
/// after its dispatch and its count (LargeShadowList; bindings.glsl's kLargeShadowList).
constexpr std::uint32_t kCharacterLists = kBodyWriters + 1;
static_assert(THRONG_LARGE_SHADOW_LIST == kBodyWriters, "the shaders' kLargeShadowList follows the writers' lists");
/// The head of that last list (splat_shadows.comp writes it, splat_large_shadows.comp reads it).
struct LargeShadowList {
    DispatchArguments dispatch{0, 1, 1};  ///< A workgroup per shadow listed (up to splatGroupLimit()).
    std::uint32_t listed = 0;
};
static_assert(sizeof(LargeShadowList) == 16 && offsetof(LargeShadowList, listed) == 12, "bindings.glsl's kLargeShadowListed and kLargeShadowFirst");
/// After that list, the slots of the compacting passes' order-preserving allocation
/// (slot_allocation.glsl, for resolve_cull.comp and resolve_bones.comp; bindings.glsl's
/// characterSlotsStart): two per character (its joint spheres' and its bones' place in its
/// workgroup), then two per workgroup of kPlanWorkgroup characters.
constexpr std::uint32_t kSlotsPerCharacter = 2;
constexpr std::uint32_t kPlanWorkgroup = THRONG_ALLOCATION_GROUP;  // local_size_x of both passes
/// Bytes of SlotBuffers::characterLists for `capacity` characters.
constexpr std::uint64_t characterListsBytes(std::uint64_t capacity) {
    const std::uint64_t workgroups = (capacity + kPlanWorkgroup - 1) / kPlanWorkgroup;
    return (capacity * (kCharacterLists + kSlotsPerCharacter) + workgroups * kSlotsPerCharacter) * sizeof(std::uint32_t) + sizeof(LargeShadowList);
}

/// One batch of a frame-in-flight slot: the buffers and descriptors of up to what one storage
/// buffer holds on the device (a larger crowd has several, each drawn as a crowd of its own).
/// Sized for `capacity` characters and grown by CrowdRenderer when a larger crowd arrives.
struct SlotBuffers {
    std::uint32_t batch = 0;        ///< Its place among its slot's batches (which LevelFades buffer it shares).
    std::uint32_t capacity = 0;     ///< Characters the buffers below hold.
    std::uint32_t characterCount = 0;  ///< Characters this frame.
    gpu::Buffer characters;         ///< HostUpload: CharacterState per character, written every frame.
    gpu::Buffer scene;              ///< HostUpload uniform buffer.
    gpu::Buffer instances;          ///< Resolved joints (InstanceGpu), written by compute or the CPU.
    gpu::Buffer drawArguments;      ///< Fast path: the indirect draw, filled by the compute pass.
    gpu::Buffer instanceOwners;     ///< Fast path: (character, joint) of each compacted instance.
    gpu::Buffer counts;             ///< Readback: a copy of the FastPathCounts, for the HUD.
    gpu::Buffer boneInstances;      ///< Bone bodies: BoneInstanceGpu per visible bone, written by the compute pass.
    gpu::Buffer skinJoints;         ///< Skinned bodies: a skinning transform per joint of every character (compute writes).
    gpu::Buffer skinCharacters;     ///< Skinned bodies: per skeleton, room for every character (compute lists them).
    gpu::Buffer skinDraws;          ///< Skinned bodies: SkinDrawGpu per skeleton (reset each frame, compute counts).
    gpu::Buffer bodyLevels;         ///< Bone bodies: BodyLevelGpu per character, written by the compute pass.
    gpu::Buffer shadows;            ///< Visibility path, bone bodies: the contact shadows per pixel (splat_shadows.comp).
    gpu::Buffer characterLists;     ///< Bone bodies: a list of characters per body writer, written by the planning pass, then the large contact shadows' (kCharacterLists).
    gpu::Buffer visibility;         ///< Visibility path: a 64-bit (depth, joint) per pixel of the frame.
    gpu::Buffer shadingTiles;       ///< Visibility path: its shading's squares and their draws (shading_tiles.glsl).
    vk::raii::BufferView visibilityTexels{nullptr};  ///< Visibility path: `visibility` as texels, for the shading's reads.
    vk::raii::BufferView shadowTexels{nullptr};      ///< Visibility path: `shadows` as texels, for the shading's reads.
    vk::raii::BufferView skinJointTexels{nullptr};   ///< Skinned bodies: `skinJoints` as texels (RGBA32F), for skin.vert's reads.
    vk::raii::BufferView instanceTexels{nullptr};     ///< `instances` as texels (RGBA32F), for the visibility path's shading.
    vk::raii::BufferView boneInstanceTexels{nullptr}; ///< `boneInstances` as texels (RGBA32F), for the visibility path's shading.
    vk::Extent2D visibilityExtent;  ///< The frame `visibility` is sized for.
    /// Visibility path: this frame's epoch in its keys (shaders/visibility.glsl), counting down
    /// from THRONG_VISIBILITY_EPOCHS - 1 (the count's first frame, which fills `visibility` with
    /// nothing first) to 0; 0 too when `visibility` is new, so that the next frame starts the count.
    std::uint32_t visibilityEpoch = 0;
    /// Whether the frame given the epoch above recorded its splats (Splat::record sets it). One
    /// that did not (a window's frame given up after its upload) leaves its epoch, and its fill,
    /// to the next: a count whose fill was skipped would let the last count's keys through.
    mutable bool visibilityRecorded = true;
    /// Visibility path: this frame is drawn over the slot's last one, of the same scene, so the
    /// shading leaves out the squares that hold their pixels already (shading_tiles.glsl).
    bool drawsOverLastFrame = false;
    std::optional<SceneUniforms> lastScene;  ///< The scene the slot's last frame drew (the fades' flag left out).
    PushConstants push;
    vk::raii::DescriptorPool descriptorPool{nullptr};  // before the set: destroyed after it
    vk::raii::DescriptorSet descriptors{nullptr};
};

/// Which per-instance buffers a path needs, and where they live.
struct InstanceStorage {
    bool instances = true;                                ///< An InstanceGpu per joint of every character.
    gpu::MemoryIntent intent = gpu::MemoryIntent::DeviceLocal;  ///< HostUpload when the CPU writes them.
    bool owners = false;                                  ///< A (character, joint) pair per instance.
    bool compacted = false;                               ///< Only visible instances, counted in drawArguments.
    bool bones = false;                                   ///< A BoneInstanceGpu per bone of every character.
    std::uint32_t skeletons = 0;                          ///< Skinned bodies: how many meshes (0: none drawn).
    bool visibility = false;                              ///< A per-pixel visibility buffer, sized for the frame.
    bool shadesGround = false;                            ///< The path's draw shades the ground: no ground pass.
};

/// A barrier on the whole of `buffer`, for the paths' compute-to-draw hand-overs.
inline vk::BufferMemoryBarrier2 bufferBarrier(const gpu::Buffer& buffer, vk::PipelineStageFlags2 srcStage, vk::AccessFlags2 srcAccess,
                                              vk::PipelineStageFlags2 dstStage, vk::AccessFlags2 dstAccess) {
    return {.srcStageMask = srcStage, .srcAccessMask = srcAccess, .dstStageMask = dstStage, .dstAccessMask = dstAccess,
            .buffer = buffer.handle(), .offset = 0, .size = VK_WHOLE_SIZE};
}

class RenderPathImpl {
public:
    RenderPathImpl() = default;
    RenderPathImpl(const RenderPathImpl&) = delete;
    RenderPathImpl& operator=(const RenderPathImpl&) = delete;
    virtual ~RenderPathImpl() = default;

    [[nodiscard]] virtual RenderPath path() const = 0;
    [[nodiscard]] virtual InstanceStorage storage() const = 0;
    /// Host work once the slot's characters are written (the cpu path resolves joints here).
    virtual void prepare(SlotBuffers& /*slot*/, std::span<const crowd::CharacterState> /*characters*/) {}
    /// Compute work before the scene pass (culling, poses, bodies), ending with the barriers
    /// its outputs need.
    virtual void recordCompute(const vk::raii::CommandBuffer& /*commands*/, const SlotBuffers& /*slot*/) const {}
    /// The visibility path's splat, after recordCompute: recorded apart so the benchmark can
    /// time it (CrowdRenderer::splats).
    virtual void recordVisibility(const vk::raii::CommandBuffer& /*commands*/, const SlotBuffers& /*slot*/) const {}
    /// The visibility path's shading pass, first in the scene pass, before recordDraw.
    virtual void recordShading(const vk::raii::CommandBuffer& /*commands*/, const SlotBuffers& /*slot*/) const {}
    /// The characters' draw, inside dynamic rendering, descriptors and push constants bound.
    virtual void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const = 0;
    /// Level-of-detail counts of the slot's last completed frame, for paths that cull or simplify.
    [[nodiscard]] virtual std::optional<DetailCounts> detailCounts(const SlotBuffers& /*slot*/) const { return std::nullopt; }
    /// Skinned bodies: every clip's bind pose per joint (Binding::BindPoses); nullptr when none.
    [[nodiscard]] virtual const gpu::Buffer* bindPoses() const { return nullptr; }
};

/// Who reads the fast path's culling output: its draw arguments (an indirect draw, or a
/// dispatch that reads the count) and its compacted joints.
struct CullConsumers {
    vk::PipelineStageFlags2 argumentsStage;
    vk::AccessFlags2 argumentsAccess;
    vk::PipelineStageFlags2 instancesStage;
};
/// Between the compacting passes (slot_allocation.glsl): the counts, then the slots, written to
/// the draw arguments and characterLists by one pass are read by the next.
void recordSlotsBarrier(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot);
/// resolve_cull.comp's passes (its kPass): count each character's joints, allot them in
/// character order (slot_allocation.glsl), write them.
using CullPipelines = std::array<vk::raii::Pipeline, 3>;
[[nodiscard]] CullPipelines createCullPipelines(const PathSetup& setup);
/// The fast path's culling passes over the slot's characters into its compacted joints and
/// draw arguments, with the barriers to `consumers` and a copy of the counts for the host.
void recordCulling(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, const CullPipelines& cull, const CullConsumers& consumers);
/// The host copy of the slot's last completed culling pass's counts.
[[nodiscard]] FastPathCounts readCounts(const SlotBuffers& slot);
/// Those counts as level-of-detail counts of joint spheres (full, coarse, culled).
[[nodiscard]] DetailCounts culledCounts(const SlotBuffers& slot);

/// The most workgroups a visibility-path splat asks for (the writers' specialisation constant 0,
/// kLargestSplatGroups): 4096, or THRONG_SPLAT_GROUP_LIMIT (1 to 65535), which lets a test make
/// a small crowd loop as a million-character one does. Throws ThrongException (BadInput) on a
/// bad value.
[[nodiscard]] std::uint32_t splatGroupLimit();

/// Whether a character may mix another of these clips into its own: two of them share a
/// skeleton (pose.glsl's mixes()). The pose-sampling passes' specialisation constant 2,
/// kClipsMayMix: false leaves the mixing out of their shaders.
[[nodiscard]] bool clipsMayMix(std::span<const motion::BakedClip> clips);

/// Pixels a side of the visibility path's shading squares (shading_tiles.glsl's, from binding_numbers.h).
constexpr std::uint32_t kShadingTile = THRONG_SHADING_TILE_PIXELS;
/// Bytes of the visibility path's shading squares for a frame of `extent` (shading_tiles.glsl):
/// its head (eight indirect draws, the skinned bodies' bounds), then per square a mark, an entry
/// in each of the eight lists and its state.
[[nodiscard]] vk::DeviceSize shadingTileBytes(vk::Extent2D extent);

/// The visibility path's splat and shading, shared by its joint-sphere and bone-body forms:
/// joints (splat_spheres.comp) and bones (splat_bones.comp) are splatted into the slot's
/// visibility buffer, marking the squares they touch, then the shading (visibility_resolve.frag)
/// shades each pixel's body or the ground, square by square (shading_tiles.glsl: the marked
/// squares with the whole shader, the others that see the ground with its part alone); with
/// `bodies`, bones too, with the contact shadows splatted onto the ground (splat_shadows.comp;
/// the ground squares no shadow touches are shaded without reading them). It writes no depth:
/// the skinned bodies drawn after it test against the visibility buffer and the ground plane.
/// Throws ThrongException (Runtime) without 64-bit buffer atomics.
class Splat {
public:
    Splat(const PathSetup& setup, bool bodies);
    /// Clears the buffer and splats the culled joints and/or bones, with the barriers to the shading.
    void record(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, bool joints, bool bones) const;
    /// The shading, inside dynamic rendering.
    void recordShading(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const;
    /// With bodies, inside dynamic rendering and before the skinned bodies: depth reset to the
    /// far plane over their screen bounds (the path does not clear it: CrowdRenderer::needsClearedDepth).
    void recordSkinDepthReset(const vk::raii::CommandBuffer& commands) const;

private:
    void clear(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const;

    vk::raii::Pipeline spheres_{nullptr}, bones_{nullptr}, shadows_{nullptr}, classify_{nullptr};
    vk::raii::Pipeline largeShadows_{nullptr};  ///< With bodies: a workgroup per contact shadow too large for one invocation.
    vk::raii::Pipeline shading_{nullptr}, groundShading_{nullptr};  ///< The marked squares' whole shading, the others' ground alone.
    vk::raii::Pipeline jointShading_{nullptr};                     ///< The squares only joint spheres touch.
    vk::raii::Pipeline unshadowedGroundShading_{nullptr};          ///< With bodies: the ground squares no contact shadow touches.
    vk::raii::Pipeline opaqueGroundShading_{nullptr};              ///< Of those, the ones all ground: nothing discarded.
    vk::raii::Pipeline opaqueShading_{nullptr}, opaqueJointShading_{nullptr};  ///< The body and joint squares wholly on the ground.
    vk::raii::Pipeline skyShading_{nullptr};  ///< Over the last frame: the squares to paint with the sky first.
    vk::raii::Pipeline skinDepthReset_{nullptr};  ///< With bodies: depth back to 1 where skinned bodies may draw.
};

/// Notes that the slot's visibility buffers were made anew, for frames of `extent`: the next
/// frame fills them, starting the epochs' count again.
void visibilityBuffersMade(SlotBuffers& slot, vk::Extent2D extent);
/// Starts a frame of the slot. Sets slot.drawsOverLastFrame: `eligible` (the target holds the
/// slot's last frame, drawn by the visibility path) and that frame drew the same scene; keeps
/// `scene` for the next. Moves the visibility epoch on: one down, or the first again (and the
/// buffer filled) after the last; the same again where the last frame recorded no splat. Returns
/// this frame's epoch (SceneUniforms::visibilityEpoch). Called once per frame the slot uploads,
/// after anything there that may throw.
[[nodiscard]] std::uint32_t beginVisibilityFrame(SlotBuffers& slot, const SceneUniforms& scene, bool eligible);
/// How many shading squares the slot's last frame kept from the one before (waits for the device).
[[nodiscard]] std::uint32_t keptGroundSquares(const gpu::Context& context, const SlotBuffers& slot);

[[nodiscard]] std::unique_ptr<RenderPathImpl> makePaperPath(const PathSetup& setup);
[[nodiscard]] std::unique_ptr<RenderPathImpl> makeCpuPath(const PathSetup& setup);
[[nodiscard]] std::unique_ptr<RenderPathImpl> makeComputePath(const PathSetup& setup);
[[nodiscard]] std::unique_ptr<RenderPathImpl> makeFastPath(const PathSetup& setup, float lodPixels);
/// The fast path's culling, then joint spheres splatted into a visibility buffer and shaded in
/// one shading pass. Throws ThrongException (Unsupported) without 64-bit buffer atomics.
[[nodiscard]] std::unique_ptr<RenderPathImpl> makeVisibilityPath(const PathSetup& setup, float lodPixels);
/// The fast path drawing bone bodies: culled characters' bones as ray-cast tapered capsules;
/// with Body::Auto, characters under kAutoBonePixels tall as the fast path's joint spheres.
/// With `splat`, the visibility path's form: bones and joint spheres splatted (Splat), skinned
/// bodies and contact shadows rasterised over the shading.
[[nodiscard]] std::unique_ptr<RenderPathImpl> makeBonePath(const PathSetup& setup, Body body, float lodPixels, bool splat);
/// The fast path's joint-sphere pipeline: a point sprite per instance, ray-cast.
[[nodiscard]] vk::raii::Pipeline createJointSpritePipeline(const PathSetup& setup);

}  // namespace throng::render::detail
