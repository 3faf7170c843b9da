// The visibility path: the fast path's culling and compaction, then one compute invocation per
// visible joint (and, with bone bodies, per visible bone) splats its exact shape into a
// per-pixel buffer of (depth, joint or bone), keeping the nearest with a 64-bit atomicMin
// (Schütz, Kerbl & Wimmer 2021 do this for point clouds), and one full-screen pass shades each
// pixel's body or the ground. A CPU rasteriser pays a set-up per primitive that outweighs the
// few pixels a distant joint covers; the splat pays only for the pixels.
#include "render_path_impl.h"
#include "throng/shaders/resolve_cull_comp.h"
#include "throng/shaders/splat_bones_comp.h"
#include "throng/shaders/splat_spheres_comp.h"
#include "throng/shaders/visibility_resolve_bodies_frag.h"
#include "throng/shaders/visibility_resolve_frag.h"
#include "throng/shaders/visibility_resolve_vert.h"

namespace throng::render::detail {
namespace {

constexpr std::uint32_t kSplatWorkgroupSize = 64;  // local_size_x of splat_spheres.comp and splat_bones.comp
using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

// One invocation per item the crowd could show; those past the culled count return at once.
// Rows of workgroups when one row would pass the device's largest dispatch.
void dispatchOver(const vk::raii::CommandBuffer& commands, std::uint64_t items, std::uint32_t largestGroups) {
    const std::uint64_t groups = std::max<std::uint64_t>((items + kSplatWorkgroupSize - 1) / kSplatWorkgroupSize, 1);
    const std::uint64_t columns = std::min<std::uint64_t>(groups, largestGroups);
    commands.dispatch(static_cast<std::uint32_t>(columns), static_cast<std::uint32_t>((groups + columns - 1) / columns), 1);
}

class VisibilityPath final : public RenderPathImpl {
public:
    VisibilityPath(const PathSetup& setup, float lodPixels) : lodPixels_(lodPixels), splat_(setup, false) {
        const gpu::Context& context = *setup.context;
        cull_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kResolveCullCompSpirv), *setup.layout);
    }
    [[nodiscard]] RenderPath path() const override { return RenderPath::Visibility; }
    [[nodiscard]] InstanceStorage storage() const override {
        return {.owners = true, .compacted = true, .visibility = true, .shadesGround = true};
    }
    void prepare(SlotBuffers& slot, std::span<const crowd::CharacterState> /*characters*/) override { slot.push.lodPixels = lodPixels_; }

    void recordCompute(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        recordCulling(commands, slot, cull_, {.argumentsStage = Stage::eComputeShader, .argumentsAccess = Access::eShaderStorageRead,
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

Splat::Splat(const PathSetup& setup, bool bodies)
    : jointsPerCharacter_(setup.jointsPerCharacter), bonesPerCharacter_(setup.palette->bonesPerCharacter()) {
    const gpu::Context& context = *setup.context;
    if (!context.hasInt64Atomics())
        throw ThrongException(Error{Error::Kind::Runtime, "the visibility path needs 64-bit buffer atomics (shaderBufferInt64Atomics), which device '" +
                                                              context.description().name + "' lacks; use --path fast", {}});
    largestGroups_ = context.limits().maxComputeWorkGroupCount[0];
    spheres_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatSpheresCompSpirv), *setup.layout);
    bones_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatBonesCompSpirv), *setup.layout);
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
    // Empty the buffer once the previous frame's shading has read it, then splat.
    const auto cleared = bufferBarrier(slot.visibility, Stage::eFragmentShader, Access::eShaderStorageRead, Stage::eCopy, Access::eTransferWrite);
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &cleared});
    commands.fillBuffer(slot.visibility.handle(), 0, VK_WHOLE_SIZE, 0xffffffffU);  // kNothingVisible
    const auto toSplat = bufferBarrier(slot.visibility, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader,
                                       Access::eShaderStorageRead | Access::eShaderStorageWrite);
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &toSplat});
    if (joints) {
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *spheres_);
        dispatchOver(commands, std::uint64_t{slot.characterCount} * jointsPerCharacter_, largestGroups_);
    }
    if (bones) {
        // Both splats only take minima: they need no barrier between them.
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *bones_);
        dispatchOver(commands, std::uint64_t{slot.characterCount} * bonesPerCharacter_, largestGroups_);
    }
    const auto splatted = bufferBarrier(slot.visibility, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eFragmentShader,
                                        Access::eShaderStorageRead);
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &splatted});
}

void Splat::recordShading(const vk::raii::CommandBuffer& commands) const {
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *shading_);
    commands.draw(3, 1, 0, 0);  // one triangle over the frame
}

std::unique_ptr<RenderPathImpl> makeVisibilityPath(const PathSetup& setup, float lodPixels) {
    return std::make_unique<VisibilityPath>(setup, lodPixels);
}

}  // namespace throng::render::detail
