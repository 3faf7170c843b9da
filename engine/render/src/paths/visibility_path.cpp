// The visibility path: the fast path's culling and compaction, then one compute invocation per
// visible joint (and, with bone bodies, per visible bone) splats its exact shape into a
// per-pixel buffer of (distance along the ray, joint or bone), keeping the nearest with a
// 64-bit atomicMin (Schütz, Kerbl & Wimmer 2021 do this for point clouds), and one full-screen
// pass shades each pixel's body or the ground (with bone bodies, under their splatted contact
// shadows). A CPU rasteriser pays a set-up per primitive that outweighs the
// few pixels a distant joint covers; the splat pays only for the pixels.
#include "render_path_impl.h"
#include "throng/core/environment.h"
#include "throng/shaders/resolve_cull_comp.h"
#include "throng/shaders/splat_bones_comp.h"
#include "throng/shaders/splat_shadows_comp.h"
#include "throng/shaders/splat_spheres_comp.h"
#include "throng/shaders/visibility_resolve_bodies_frag.h"
#include "throng/shaders/visibility_resolve_frag.h"
#include "throng/shaders/visibility_resolve_vert.h"

namespace throng::render::detail {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;
constexpr std::uint32_t kSplatGroupSize = 64;  // local_size_x of the splats (kSplatGroupSize in bindings.glsl)

class VisibilityPath final : public RenderPathImpl {
public:
    VisibilityPath(const PathSetup& setup, float lodPixels) : lodPixels_(lodPixels), splat_(setup, false) {
        const gpu::Context& context = *setup.context;
        const std::array<std::uint32_t, 1> constants{splatGroupLimit()};
        cull_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kResolveCullCompSpirv), *setup.layout, constants);
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
        splat_.record(commands, slot, true, false);
    }
    [[nodiscard]] std::optional<DetailCounts> detailCounts(const SlotBuffers& slot) const override { return culledCounts(slot); }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& /*slot*/) const override { splat_.recordShading(commands); }

private:
    float lodPixels_;
    Splat splat_;
    vk::raii::Pipeline cull_{nullptr};
};

}  // namespace

std::uint32_t splatGroupLimit() {
    constexpr std::uint32_t kDefault = 4096, kMost = 65535;  // kMost: every device's maxComputeWorkGroupCount[0] at least
    return static_cast<std::uint32_t>(wholeNumberFromEnvironment("THRONG_SPLAT_GROUP_LIMIT", 1, kMost, "a workgroup count").value_or(kDefault));
}

Splat::Splat(const PathSetup& setup, bool bodies) {
    const gpu::Context& context = *setup.context;
    if (!context.hasInt64Atomics())
        throw ThrongException(Error{Error::Kind::Runtime, "the visibility path needs 64-bit buffer atomics (shaderBufferInt64Atomics), which device '" +
                                                              context.description().name + "' lacks; use --path fast", {}});
    spheres_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatSpheresCompSpirv), *setup.layout);
    bones_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatBonesCompSpirv), *setup.layout);
    if (bodies) shadows_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatShadowsCompSpirv), *setup.layout);
    const auto vertex = gpu::createShaderModule(context, kVisibilityResolveVertSpirv);
    const auto fragment = gpu::createShaderModule(context, bodies ? std::span<const std::uint32_t>(kVisibilityResolveBodiesFragSpirv)
                                                                       : std::span<const std::uint32_t>(kVisibilityResolveFragSpirv));
    shading_ = gpu::createGraphicsPipeline(context, {.vertexShader = &vertex,
                                                     .fragmentShader = &fragment,
                                                     .layout = setup.layout,
                                                     .vertexBindings = {},
                                                     .vertexAttributes = {},
                                                     .topology = vk::PrimitiveTopology::eTriangleList,
                                                     .cullMode = vk::CullModeFlagBits::eNone,
                                                     .depthWrite = bodies,
                                                     .colorFormat = setup.colorFormat,
                                                     .depthFormat = setup.depthFormat,
                                                     .samples = setup.samples});
}

void Splat::record(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, bool joints, bool bones) const {
    // Empty the buffers once the previous frame's shading has read them, then splat.
    const bool shadows = static_cast<bool>(*shadows_);
    const std::uint32_t buffers = shadows ? 2 : 1;
    const std::array<vk::BufferMemoryBarrier2, 2> cleared{
        bufferBarrier(slot.visibility, Stage::eFragmentShader, Access::eShaderStorageRead, Stage::eCopy, Access::eTransferWrite),
        bufferBarrier(slot.shadows, Stage::eFragmentShader, Access::eShaderStorageRead, Stage::eCopy, Access::eTransferWrite)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = buffers, .pBufferMemoryBarriers = cleared.data()});
    commands.fillBuffer(slot.visibility.handle(), 0, VK_WHOLE_SIZE, 0xffffffffU);  // kNothingVisible
    if (shadows) commands.fillBuffer(slot.shadows.handle(), 0, VK_WHOLE_SIZE, 0U);   // no shadow
    const std::array<vk::BufferMemoryBarrier2, 2> toSplat{
        bufferBarrier(slot.visibility, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader, Access::eShaderStorageRead | Access::eShaderStorageWrite),
        bufferBarrier(slot.shadows, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader, Access::eShaderStorageRead | Access::eShaderStorageWrite)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = buffers, .pBufferMemoryBarriers = toSplat.data()});
    if (shadows) {
        // Every character's contact shadow on the ground (only sums: no barrier with the others).
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
        // Both splats only take minima: they need no barrier between them.
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *bones_);
        commands.dispatchIndirect(slot.drawArguments.handle(), offsetof(FastPathCounts, boneSplat));
    }
    const std::array<vk::BufferMemoryBarrier2, 2> splatted{
        bufferBarrier(slot.visibility, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eFragmentShader, Access::eShaderStorageRead),
        bufferBarrier(slot.shadows, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eFragmentShader, Access::eShaderStorageRead)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = buffers, .pBufferMemoryBarriers = splatted.data()});
}

void Splat::recordShading(const vk::raii::CommandBuffer& commands) const {
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *shading_);
    commands.draw(3, 1, 0, 0);  // one triangle over the frame
}

std::unique_ptr<RenderPathImpl> makeVisibilityPath(const PathSetup& setup, float lodPixels) {
    return std::make_unique<VisibilityPath>(setup, lodPixels);
}

}  // namespace throng::render::detail
