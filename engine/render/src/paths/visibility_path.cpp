// The visibility path: the fast path's culling and compaction, then one compute invocation per
// visible joint (and, with bone bodies, per visible bone) splats its exact shape into a
// per-pixel buffer of (distance along the ray, joint or bone), keeping the nearest with a
// 64-bit atomicMin (Schütz, Kerbl & Wimmer 2021 do this for point clouds), and one shading
// pass shades each pixel's body or the ground (with bone bodies, under their splatted contact
// shadows), 64-pixel square by square: the squares a body may touch with the whole shader, the
// others with the ground's part alone, the sky's not at all (shading_tiles.glsl). A CPU rasteriser pays a set-up per primitive that outweighs the
// few pixels a distant joint covers; the splat pays only for the pixels.
#include "render_path_impl.h"

#include <cstring>

#include "throng/core/environment.h"
#include "throng/gpu/readback.h"
#include "throng/shaders/classify_tiles_comp.h"
#include "throng/shaders/splat_bones_comp.h"
#include "throng/shaders/splat_large_shadows_comp.h"
#include "throng/shaders/splat_shadows_comp.h"
#include "throng/shaders/splat_spheres_comp.h"
#include "throng/shaders/visibility_resolve_bodies_frag.h"
#include "throng/shaders/visibility_resolve_bodies_ground_frag.h"
#include "throng/shaders/visibility_resolve_bodies_ground_unshadowed_frag.h"
#include "throng/shaders/visibility_resolve_bodies_joints_frag.h"
#include "throng/shaders/visibility_resolve_bodies_joints_opaque_frag.h"
#include "throng/shaders/visibility_resolve_bodies_opaque_frag.h"
#include "throng/shaders/visibility_resolve_frag.h"
#include "throng/shaders/visibility_resolve_ground_frag.h"
#include "throng/shaders/visibility_resolve_ground_opaque_frag.h"
#include "throng/shaders/visibility_resolve_opaque_frag.h"
#include "throng/shaders/skin_depth_reset_vert.h"
#include "throng/shaders/visibility_sky_frag.h"
#include "throng/shaders/visibility_tiles_vert.h"

namespace throng::render::detail {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;
constexpr std::uint32_t kSplatGroupSize = 64;  // local_size_x of the splats (kSplatGroupSize in bindings.glsl)
constexpr std::uint32_t kClassifyGroupSize = 64;  // local_size_x of classify_tiles.comp
constexpr std::uint32_t kTileVertices = 6;  // two triangles per square (visibility_tiles.vert)
// shading_tiles.glsl's lists, in its order: their draws' firstVertex is the list times kTileVertices.
constexpr std::uint32_t kBodyTileList = 0, kGroundTileList = 1, kJointTileList = 2, kShadowedGroundTileList = 3, kOpaqueGroundTileList = 4,
                        kOpaqueBodyTileList = 5, kOpaqueJointTileList = 6, kSkyTileList = 7, kShadingTileLists = THRONG_SHADING_TILE_LISTS;
// The buffer's head (ShadingTiles in shading_tiles.glsl, up to tileData); after it, per square a
// mark, an entry in each list and its state after the frame.
struct ShadingTilesHead {
    std::array<DrawArguments, kShadingTileLists> draws;
    std::uint32_t keepsLastFrame, skinBoxCount, unboundedSkin, keptSquares;
    std::array<glm::ivec4, THRONG_SKIN_BOXES> skinBoxes;
};
constexpr vk::DeviceSize kShadingTileHead = sizeof(ShadingTilesHead);
// What each frame resets: the draws, whether it keeps the last frame, and no skinned body listed.
constexpr vk::DeviceSize kShadingTileReset = offsetof(ShadingTilesHead, skinBoxes);

// The squares across and down a frame of `extent`.
vk::Extent2D tileGrid(vk::Extent2D extent) {
    return {(extent.width + kShadingTile - 1) / kShadingTile, (extent.height + kShadingTile - 1) / kShadingTile};
}

class VisibilityPath final : public RenderPathImpl {
public:
    VisibilityPath(const PathSetup& setup, float lodPixels) : lodPixels_(lodPixels), splat_(setup, false) {
        cull_ = createCullPipelines(setup);
    }
    [[nodiscard]] RenderPath path() const override { return RenderPath::Visibility; }
    [[nodiscard]] InstanceStorage storage() const override {
        return {.owners = true, .compacted = true, .visibility = true, .shadesGround = true};
    }
    void prepare(SlotBuffers& slot, std::span<const crowd::CharacterState> /*characters*/) override { slot.push.lodPixels = lodPixels_; }

    void recordCompute(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        recordCulling(commands, slot, cull_, {.argumentsStage = Stage::eComputeShader | Stage::eDrawIndirect,
                                              .argumentsAccess = Access::eShaderStorageRead | Access::eIndirectCommandRead,
                                              .instancesStage = Stage::eComputeShader | Stage::eFragmentShader});
    }
    void recordVisibility(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override { splat_.record(commands, slot, true, false); }
    [[nodiscard]] std::optional<DetailCounts> detailCounts(const SlotBuffers& slot) const override { return culledCounts(slot); }
    void recordShading(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override { splat_.recordShading(commands, slot); }
    void recordDraw(const vk::raii::CommandBuffer& /*commands*/, const SlotBuffers& /*slot*/) const override {}  // the shading drew it all

private:
    float lodPixels_;
    Splat splat_;
    CullPipelines cull_{nullptr, nullptr, nullptr};
};

}  // namespace

vk::DeviceSize shadingTileBytes(vk::Extent2D extent) {
    const vk::Extent2D grid = tileGrid(extent);
    return kShadingTileHead + (1 + kShadingTileLists + 1) * vk::DeviceSize{grid.width} * grid.height * sizeof(std::uint32_t);
}

void visibilityBuffersMade(SlotBuffers& slot, vk::Extent2D extent) {
    slot.visibilityExtent = extent;
    slot.visibilityEpoch = 0;  // the next frame starts the count, filling the new buffer
    slot.visibilityRecorded = true;
}

std::uint32_t beginVisibilityFrame(SlotBuffers& slot, const SceneUniforms& scene, bool eligible) {
    SceneUniforms drawn = scene;
    drawn.levelFadesContinue = 0.0F;  // the bodies' cross-fades; the ground and sky are the same either way
    drawn.visibilityEpoch = 0;        // the renderer's own
    slot.drawsOverLastFrame = eligible && slot.lastScene && std::memcmp(&*slot.lastScene, &drawn, sizeof drawn) == 0;
    slot.lastScene = drawn;
    if (slot.visibilityRecorded) {
        slot.visibilityRecorded = false;
        slot.visibilityEpoch = slot.visibilityEpoch == 0 ? THRONG_VISIBILITY_EPOCHS - 1 : slot.visibilityEpoch - 1;
    }
    return slot.visibilityEpoch;
}

std::uint32_t keptGroundSquares(const gpu::Context& context, const SlotBuffers& slot) {
    const std::vector<std::byte> head = gpu::downloadBuffer(context, slot.shadingTiles, kShadingTileReset);
    std::uint32_t kept = 0;
    std::memcpy(&kept, head.data() + offsetof(ShadingTilesHead, keptSquares), sizeof kept);
    return kept;
}

std::uint32_t splatGroupLimit() {
    constexpr std::uint32_t kDefault = 4096, kMost = 65535;  // kMost: every device's maxComputeWorkGroupCount[0] at least
    return static_cast<std::uint32_t>(wholeNumberFromEnvironment("THRONG_SPLAT_GROUP_LIMIT", 1, kMost, "a workgroup count").value_or(kDefault));
}

Splat::Splat(const PathSetup& setup, bool bodies) {
    const gpu::Context& context = *setup.context;
    if (const std::optional<std::string> why = CrowdRenderer::visibilityPathUnsupported(context))
        throw ThrongException(Error{Error::Kind::Runtime, *why, {}});
    spheres_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatSpheresCompSpirv), *setup.layout);
    bones_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatBonesCompSpirv), *setup.layout);
    if (bodies) {
        // Both specialised with the most workgroups the large shadows' dispatch may ask for.
        const std::array<std::uint32_t, 1> groupLimit{splatGroupLimit()};
        shadows_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatShadowsCompSpirv), *setup.layout, groupLimit);
        largeShadows_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatLargeShadowsCompSpirv), *setup.layout, groupLimit);
    }
    classify_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kClassifyTilesCompSpirv), *setup.layout);
    const auto vertex = gpu::createShaderModule(context, kVisibilityTilesVertSpirv);
    // No depth test and no depth written: skinned bodies, drawn after, test against the
    // visibility buffer and the ground plane (skin_shading.glsl), and nothing else draws after.
    const auto shadingPipeline = [&](std::span<const std::uint32_t> fragmentSpirv) {
        const auto fragment = gpu::createShaderModule(context, fragmentSpirv);
        gpu::GraphicsPipelineInfo info = targetPipeline(setup, vertex, &fragment, vk::PrimitiveTopology::eTriangleList);
        info.cullMode = vk::CullModeFlagBits::eNone;
        info.depthTest = false;
        info.depthWrite = false;
        return gpu::createGraphicsPipeline(context, info);
    };
    shading_ = shadingPipeline(bodies ? std::span<const std::uint32_t>(kVisibilityResolveBodiesFragSpirv) : std::span<const std::uint32_t>(kVisibilityResolveFragSpirv));
    groundShading_ = shadingPipeline(bodies ? std::span<const std::uint32_t>(kVisibilityResolveBodiesGroundFragSpirv)
                                            : std::span<const std::uint32_t>(kVisibilityResolveGroundFragSpirv));
    // Joint spheres alone shade the same with or without bones' code: the spheres' form marks
    // its squares for this list only.
    jointShading_ = shadingPipeline(bodies ? std::span<const std::uint32_t>(kVisibilityResolveBodiesJointsFragSpirv)
                                           : std::span<const std::uint32_t>(kVisibilityResolveFragSpirv));
    // The ground where no contact shadow falls: no shadow to read (the joint-sphere form casts none).
    if (bodies) unshadowedGroundShading_ = shadingPipeline(kVisibilityResolveBodiesGroundUnshadowedFragSpirv);
    // The ground squares no body or shadow touches, every pixel on the ground: none discarded,
    // so lavapipe writes them straight out.
    opaqueGroundShading_ = shadingPipeline(kVisibilityResolveGroundOpaqueFragSpirv);
    // The body and joint squares that stand wholly on the ground: the same, opaque.
    opaqueShading_ = shadingPipeline(bodies ? std::span<const std::uint32_t>(kVisibilityResolveBodiesOpaqueFragSpirv)
                                            : std::span<const std::uint32_t>(kVisibilityResolveOpaqueFragSpirv));
    opaqueJointShading_ = shadingPipeline(bodies ? std::span<const std::uint32_t>(kVisibilityResolveBodiesJointsOpaqueFragSpirv)
                                                 : std::span<const std::uint32_t>(kVisibilityResolveOpaqueFragSpirv));
    skyShading_ = shadingPipeline(kVisibilitySkyFragSpirv);
    if (bodies) {
        const auto resetVertex = gpu::createShaderModule(context, kSkinDepthResetVertSpirv);
        gpu::GraphicsPipelineInfo reset = targetPipeline(setup, resetVertex, nullptr, vk::PrimitiveTopology::eTriangleList);
        reset.cullMode = vk::CullModeFlagBits::eNone;
        reset.depthCompare = vk::CompareOp::eAlways;
        reset.colorWrite = false;
        skinDepthReset_ = gpu::createGraphicsPipeline(context, reset);
    }
}

// Where the large contact shadows' list (LargeShadowList, then the characters) starts in
// characterLists: after the body writers' lists (bindings.glsl's kLargeShadowList).
static vk::DeviceSize largeShadowListOffset(const SlotBuffers& slot) {
    return vk::DeviceSize{THRONG_LARGE_SHADOW_LIST} * slot.characterCount * sizeof(std::uint32_t);
}

void Splat::clear(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const {
    // Empty the buffers once the previous frame's shading has read them; the large shadows'
    // list, once this frame's planning and writers are done with the lists before it.
    const bool shadows = static_cast<bool>(*shadows_);
    const std::uint32_t buffers = shadows ? 4 : 2;  // the shadows' last, where there are some
    // The visibility buffer is filled one frame in THRONG_VISIBILITY_EPOCHS (visibility.glsl);
    // otherwise the splats write it straight after the last frame's reads.
    const auto splatReads = Access::eShaderStorageRead | Access::eShaderStorageWrite;
    const bool fillsVisibility = slot.visibilityEpoch == THRONG_VISIBILITY_EPOCHS - 1;  // the count's first frame
    const std::array<vk::BufferMemoryBarrier2, 4> cleared{
        bufferBarrier(slot.visibility, Stage::eFragmentShader, Access::eShaderSampledRead, fillsVisibility ? Stage::eCopy : Stage::eComputeShader,
                      fillsVisibility ? vk::AccessFlags2(Access::eTransferWrite) : splatReads),
        // The last frame's squares' states, which this frame's classify_tiles.comp reads, too.
        bufferBarrier(slot.shadingTiles, Stage::eVertexShader | Stage::eDrawIndirect | Stage::eComputeShader,
                      Access::eShaderStorageRead | Access::eIndirectCommandRead | Access::eShaderStorageWrite, Stage::eCopy | Stage::eComputeShader,
                      Access::eTransferWrite | Access::eShaderStorageRead),
        bufferBarrier(slot.shadows, Stage::eFragmentShader, Access::eShaderSampledRead, Stage::eCopy, Access::eTransferWrite),
        bufferBarrier(slot.characterLists, Stage::eComputeShader, Access::eShaderStorageRead | Access::eShaderStorageWrite, Stage::eCopy,
                      Access::eTransferWrite)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = buffers, .pBufferMemoryBarriers = cleared.data()});
    if (fillsVisibility) commands.fillBuffer(slot.visibility.handle(), 0, VK_WHOLE_SIZE, 0xffffffffU);  // kNothingVisible
    if (shadows) {
        commands.fillBuffer(slot.shadows.handle(), 0, VK_WHOLE_SIZE, 0U);  // no shadow
        commands.updateBuffer<LargeShadowList>(slot.characterLists.handle(), largeShadowListOffset(slot), LargeShadowList{});  // none listed
    }
    // No square marked, none listed (the draws in shading_tiles.glsl's order), no skinned body
    // listed; the squares' states stay for this frame to read.
    ShadingTilesHead head{};
    for (std::uint32_t list = 0; list < kShadingTileLists; ++list) head.draws[list] = DrawArguments{kTileVertices, 0, list * kTileVertices, 0};
    head.keepsLastFrame = slot.drawsOverLastFrame ? 1U : 0U;
    commands.updateBuffer<std::byte>(slot.shadingTiles.handle(), 0,
                                     vk::ArrayProxy<const std::byte>(static_cast<std::uint32_t>(kShadingTileReset), reinterpret_cast<const std::byte*>(&head)));
    const vk::Extent2D grid = tileGrid(slot.visibilityExtent);
    commands.fillBuffer(slot.shadingTiles.handle(), kShadingTileHead, vk::DeviceSize{grid.width} * grid.height * sizeof(std::uint32_t), 0U);
    const std::array<vk::BufferMemoryBarrier2, 4> toSplat{
        bufferBarrier(slot.visibility, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader, splatReads),
        bufferBarrier(slot.shadingTiles, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader, splatReads),
        bufferBarrier(slot.shadows, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader, splatReads),
        bufferBarrier(slot.characterLists, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader, splatReads)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = buffers, .pBufferMemoryBarriers = toSplat.data()});
}

void Splat::record(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, bool joints, bool bones) const {
    clear(commands, slot);
    slot.visibilityRecorded = true;
    const bool shadows = static_cast<bool>(*shadows_);
    if (shadows) {
        // Every character's contact shadow on the ground, or its place in the list of those too
        // large for one invocation (only sums and a list: no barrier with the other splats).
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *shadows_);
        commands.dispatch((slot.characterCount + kSplatGroupSize - 1) / kSplatGroupSize, 1, 1);
    }
    // Each splat has as many workgroups as the joints or bones written need (the pass that
    // wrote them counted them into its dispatch), so none starts only to find nothing.
    if (joints) {
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *spheres_);
        commands.dispatchIndirect(slot.drawArguments.handle(), offsetof(FastPathCounts, jointSplat));
    }
    if (bones) {
        // Both splats only take minima and mark squares: they need no barrier between them.
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *bones_);
        commands.dispatchIndirect(slot.drawArguments.handle(), offsetof(FastPathCounts, boneSplat));
    }
    // List the squares once every splat has marked them, for the shading's two draws; cast the
    // large shadows once they are listed.
    const auto splatReads = Access::eShaderStorageRead | Access::eShaderStorageWrite;
    const std::array<vk::BufferMemoryBarrier2, 3> marked{
        bufferBarrier(slot.shadingTiles, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader, splatReads),
        bufferBarrier(slot.characterLists, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader | Stage::eDrawIndirect,
                      Access::eShaderStorageRead | Access::eIndirectCommandRead),
        bufferBarrier(slot.shadows, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader, splatReads)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = shadows ? 3U : 1U, .pBufferMemoryBarriers = marked.data()});
    if (shadows) {
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *largeShadows_);
        commands.dispatchIndirect(slot.characterLists.handle(), largeShadowListOffset(slot));
    }
    const vk::Extent2D grid = tileGrid(slot.visibilityExtent);
    commands.bindPipeline(vk::PipelineBindPoint::eCompute, *classify_);
    commands.dispatch((grid.width * grid.height + kClassifyGroupSize - 1) / kClassifyGroupSize, 1, 1);
    // The shadows last again, where there are some.
    const std::array<vk::BufferMemoryBarrier2, 3> splatted{
        // The shading reads both through their texel views (visibility.glsl).
        bufferBarrier(slot.visibility, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eFragmentShader, Access::eShaderSampledRead),
        bufferBarrier(slot.shadingTiles, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eVertexShader | Stage::eDrawIndirect,
                      Access::eShaderStorageRead | Access::eIndirectCommandRead),
        bufferBarrier(slot.shadows, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eFragmentShader, Access::eShaderSampledRead)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = shadows ? 3U : 2U, .pBufferMemoryBarriers = splatted.data()});
}

void Splat::recordShading(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const {
    // The squares no body touches first, with the ground's shading alone; the sky's squares
    // are not drawn at all (their clear colour and depth stay).
    const auto drawList = [&](const vk::raii::Pipeline& pipeline, std::uint32_t list) {
        commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline);
        commands.drawIndirect(slot.shadingTiles.handle(), list * sizeof(DrawArguments), 1, sizeof(DrawArguments));
    };
    // Over the last frame, the sky first where a square may show it and held more (none else).
    if (slot.drawsOverLastFrame) drawList(skyShading_, kSkyTileList);
    drawList(opaqueGroundShading_, kOpaqueGroundTileList);
    if (*unshadowedGroundShading_) {
        drawList(unshadowedGroundShading_, kGroundTileList);
        drawList(groundShading_, kShadowedGroundTileList);
    } else {
        drawList(groundShading_, kGroundTileList);  // no contact shadows: nothing is listed as shadowed
    }
    drawList(jointShading_, kJointTileList);
    drawList(opaqueJointShading_, kOpaqueJointTileList);
    drawList(shading_, kBodyTileList);  // squares a bone may show in (none without bones)
    drawList(opaqueShading_, kOpaqueBodyTileList);
}

void Splat::recordSkinDepthReset(const vk::raii::CommandBuffer& commands) const {
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *skinDepthReset_);
    commands.draw(kTileVertices, THRONG_SKIN_BOXES, 0, 0);  // a quad per listed bound (skin_depth_reset.vert)
}

std::unique_ptr<RenderPathImpl> makeVisibilityPath(const PathSetup& setup, float lodPixels) {
    return std::make_unique<VisibilityPath>(setup, lodPixels);
}

}  // namespace throng::render::detail

namespace throng::render {

std::optional<std::string> CrowdRenderer::visibilityPathUnsupported(const gpu::Context& context) {
    const std::string device = "device '" + context.description().name + "'";
    if (!context.hasInt64Atomics()) return "the visibility path needs 64-bit buffer atomics (shaderBufferInt64Atomics), which " + device + " lacks; use --path fast";
    // The shading's squares hand on the ray, then the scene as flat inputs (visibility_tiles.vert):
    // GLSL starts each of the scene's members at a location of its own, so its vec3 and its uint
    // take two where their bytes would fill one: 18 locations, 72 components, past the 64
    // every device passes.
    constexpr auto kSceneLocations = static_cast<std::uint32_t>(sizeof(SceneUniforms) / sizeof(glm::vec4) + 1);
    constexpr std::uint32_t kShadingInputs = 4 * (1 + kSceneLocations);
    const vk::PhysicalDeviceLimits& limits = context.limits();
    if (std::min(limits.maxVertexOutputComponents, limits.maxFragmentInputComponents) < kShadingInputs)
        return "the visibility path's shading takes " + std::to_string(kShadingInputs) + " components from vertex to fragment shader, more than " +
               device + " passes; use --path fast";
    return std::nullopt;
}

std::uint64_t CrowdRenderer::visibilityBufferPixels(vk::Extent2D extent) {
    const auto whole = [](std::uint64_t pixels) { return (pixels + THRONG_PIXEL_BLOCK - 1) / THRONG_PIXEL_BLOCK * THRONG_PIXEL_BLOCK; };
    return whole(extent.width) * whole(extent.height);
}

std::uint64_t CrowdRenderer::shadowBufferTexels(vk::Extent2D extent) {
    const auto texels = [](std::uint64_t pixels) { return (pixels + THRONG_SHADOW_TEXEL - 1) / THRONG_SHADOW_TEXEL + 2; };  // a zero each side
    return texels(extent.width) * texels(extent.height);
}

std::string CrowdRenderer::visibilityPaddingNote(vk::Extent2D extent) {
    const std::uint64_t padded = visibilityBufferPixels(extent);
    if (padded == std::uint64_t{extent.width} * extent.height) return {};
    const std::string side = std::to_string(THRONG_PIXEL_BLOCK);
    return " (" + std::to_string(padded) + " pixels in whole " + side + " x " + side + "-pixel blocks)";
}

std::uint64_t CrowdRenderer::visibilityPixelLimit(const gpu::Context& context) {
    const vk::PhysicalDeviceLimits& limits = context.limits();
    return std::min<std::uint64_t>(limits.maxStorageBufferRange / sizeof(std::uint64_t), limits.maxTexelBufferElements);
}

}  // namespace throng::render
