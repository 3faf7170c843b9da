// The visibility path: the fast path's culling and compaction, then one compute invocation per
// visible joint splats its exact sphere into a per-pixel buffer of (depth, joint), keeping the
// nearest with a 64-bit atomicMin (Schütz, Kerbl & Wimmer 2021 do this for point clouds), and
// a full-screen pass shades each pixel's joint. A CPU rasteriser pays a set-up per primitive
// that outweighs the few pixels a distant joint covers; the splat pays only for the pixels.
#include "render_path_impl.h"
#include "throng/shaders/resolve_cull_comp.h"
#include "throng/shaders/splat_spheres_comp.h"
#include "throng/shaders/visibility_resolve_frag.h"
#include "throng/shaders/visibility_resolve_vert.h"

namespace throng::render::detail {
namespace {

constexpr std::uint32_t kSplatWorkgroupSize = 64;  // local_size_x of splat_spheres.comp
using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

class VisibilityPath final : public RenderPathImpl {
public:
    VisibilityPath(const PathSetup& setup, float lodPixels) : lodPixels_(lodPixels), jointsPerCharacter_(setup.jointsPerCharacter) {
        const gpu::Context& context = *setup.context;
        if (!context.hasInt64Atomics())
            throw ThrongException(Error{Error::Kind::Runtime, "the visibility path needs 64-bit buffer atomics (shaderBufferInt64Atomics), which device '" +
                                                                  context.description().name + "' lacks; use --path fast", {}});
        largestGroups_ = context.limits().maxComputeWorkGroupCount[0];
        cull_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kResolveCullCompSpirv), *setup.layout);
        splat_ = gpu::createComputePipeline(context, gpu::createShaderModule(context, kSplatSpheresCompSpirv), *setup.layout);
        const auto vertex = gpu::createShaderModule(context, kVisibilityResolveVertSpirv);
        const auto fragment = gpu::createShaderModule(context, kVisibilityResolveFragSpirv);
        resolve_ = gpu::createGraphicsPipeline(context, {.vertexShader = &vertex,
                                                         .fragmentShader = &fragment,
                                                         .layout = setup.layout,
                                                         .vertexBindings = {},
                                                         .vertexAttributes = {},
                                                         .topology = vk::PrimitiveTopology::eTriangleList,
                                                         .cullMode = vk::CullModeFlagBits::eNone,
                                                         .depthWrite = false,  // the frame's last draw
                                                         .colorFormat = setup.colorFormat,
                                                         .depthFormat = setup.depthFormat,
                                                         .samples = setup.samples});
    }
    [[nodiscard]] RenderPath path() const override { return RenderPath::Visibility; }
    [[nodiscard]] InstanceStorage storage() const override { return {.owners = true, .compacted = true, .visibility = true, .shadesGround = true}; }
    void prepare(SlotBuffers& slot, std::span<const crowd::CharacterState> /*characters*/) override { slot.push.lodPixels = lodPixels_; }

    void recordCompute(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        recordCulling(commands, slot, cull_, {.argumentsStage = Stage::eComputeShader, .argumentsAccess = Access::eShaderStorageRead,
                                              .instancesStage = Stage::eComputeShader | Stage::eFragmentShader});
        // Empty the buffer once the previous frame's shading has read it, then splat.
        const auto cleared = bufferBarrier(slot.visibility, Stage::eFragmentShader, Access::eShaderStorageRead, Stage::eCopy,
                                           Access::eTransferWrite);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &cleared});
        commands.fillBuffer(slot.visibility.handle(), 0, VK_WHOLE_SIZE, 0xffffffffU);  // kNothingVisible
        const auto toSplat = bufferBarrier(slot.visibility, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader,
                                           Access::eShaderStorageRead | Access::eShaderStorageWrite);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &toSplat});
        // One invocation per joint the crowd could show; those past the culled count return at once.
        const std::uint64_t joints = std::uint64_t{slot.characterCount} * jointsPerCharacter_;
        const std::uint64_t groups = std::max<std::uint64_t>((joints + kSplatWorkgroupSize - 1) / kSplatWorkgroupSize, 1);
        const std::uint64_t columns = std::min<std::uint64_t>(groups, largestGroups_);
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *splat_);
        commands.dispatch(static_cast<std::uint32_t>(columns), static_cast<std::uint32_t>((groups + columns - 1) / columns), 1);
        const auto splatted = bufferBarrier(slot.visibility, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eFragmentShader,
                                            Access::eShaderStorageRead);
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &splatted});
    }
    [[nodiscard]] std::optional<DetailCounts> detailCounts(const SlotBuffers& slot) const override { return culledCounts(slot); }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& /*slot*/) const override {
        commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *resolve_);
        commands.draw(3, 1, 0, 0);  // one triangle over the frame
    }

private:
    float lodPixels_;
    std::uint32_t jointsPerCharacter_;
    std::uint32_t largestGroups_ = 65535;
    vk::raii::Pipeline cull_{nullptr}, splat_{nullptr}, resolve_{nullptr};
};

}  // namespace

std::unique_ptr<RenderPathImpl> makeVisibilityPath(const PathSetup& setup, float lodPixels) {
    return std::make_unique<VisibilityPath>(setup, lodPixels);
}

}  // namespace throng::render::detail
