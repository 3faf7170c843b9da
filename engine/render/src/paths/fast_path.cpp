// The fast path: one compute invocation per character culls it against the view frustum,
// keeps only major joints when it is small on screen, and compacts the visible joints into an
// indirect draw of point sprites that the fragment shader ray-casts as exact spheres.
#include <algorithm>
#include <cstring>

#include "render_path_impl.h"
#include "throng/shaders/impostor_frag.h"
#include "throng/shaders/impostor_vert.h"
#include "throng/shaders/resolve_cull_comp.h"

namespace throng::render::detail {
namespace {

constexpr std::uint32_t kWorkgroupSize = kPlanWorkgroup;  // local_size_x of resolve_cull.comp
using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

class FastPath final : public RenderPathImpl {
public:
    FastPath(const PathSetup& setup, float lodPixels) : lodPixels_(lodPixels) {
        cull_ = createCullPipelines(setup);
        impostors_ = createJointSpritePipeline(setup);
    }
    [[nodiscard]] RenderPath path() const override { return RenderPath::Fast; }
    [[nodiscard]] InstanceStorage storage() const override { return {.owners = true, .compacted = true}; }
    void prepare(SlotBuffers& slot, std::span<const crowd::CharacterState> /*characters*/) override { slot.push.lodPixels = lodPixels_; }

    void recordCompute(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        recordCulling(commands, slot, cull_, {.argumentsStage = Stage::eDrawIndirect, .argumentsAccess = Access::eIndirectCommandRead,
                                              .instancesStage = Stage::eVertexShader});
    }
    [[nodiscard]] std::optional<DetailCounts> detailCounts(const SlotBuffers& slot) const override { return culledCounts(slot); }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *impostors_);
        commands.drawIndirect(slot.drawArguments.handle(), 0, 1, sizeof(DrawArguments));
    }

private:
    float lodPixels_;
    CullPipelines cull_{nullptr, nullptr, nullptr};
    vk::raii::Pipeline impostors_{nullptr};
};

}  // namespace

CullPipelines createCullPipelines(const PathSetup& setup) {
    const gpu::Context& context = *setup.context;
    const auto cull = gpu::createShaderModule(context, kResolveCullCompSpirv);
    CullPipelines pipelines{nullptr, nullptr, nullptr};
    const std::uint32_t groupLimit = splatGroupLimit(), mixes = clipsMayMix(setup.clips) ? 1U : 0U;  // the same for every pass
    for (std::uint32_t pass = 0; pass < pipelines.size(); ++pass) {
        const std::array<std::uint32_t, 3> constants{groupLimit, pass, mixes};
        pipelines[pass] = gpu::createComputePipeline(context, cull, *setup.layout, constants);
    }
    return pipelines;
}

bool clipsMayMix(std::span<const motion::BakedClip> clips) {
    for (std::size_t a = 0; a < clips.size(); ++a)
        for (std::size_t b = a + 1; b < clips.size(); ++b)
            if (clips[a].jointCount() == clips[b].jointCount()) return true;
    return false;
}

void recordSlotsBarrier(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) {
    const std::array<vk::BufferMemoryBarrier2, 2> counted{
        bufferBarrier(slot.drawArguments, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader,
                      Access::eShaderStorageRead | Access::eShaderStorageWrite),
        bufferBarrier(slot.characterLists, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eComputeShader,
                      Access::eShaderStorageRead | Access::eShaderStorageWrite)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 2, .pBufferMemoryBarriers = counted.data()});
}

void recordCulling(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, const CullPipelines& cull, const CullConsumers& consumers) {
    // Reset the draw's counter (the previous frame's read of it must finish first), cull and
    // compact, then hand the arguments and the joints to their consumers (and both, with the
    // owners, to copies for --dump-instances).
    const auto previous = bufferBarrier(slot.drawArguments, consumers.argumentsStage | Stage::eCopy,
                                        consumers.argumentsAccess | Access::eTransferRead, Stage::eCopy, Access::eTransferWrite);
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &previous});
    commands.updateBuffer<FastPathCounts>(slot.drawArguments.handle(), 0, FastPathCounts{});
    const auto reset = bufferBarrier(slot.drawArguments, Stage::eCopy, Access::eTransferWrite, Stage::eComputeShader,
                                     Access::eShaderStorageRead | Access::eShaderStorageWrite);
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &reset});
    // Count, allot (one workgroup), write: each pass reads what the one before wrote.
    const std::uint32_t workgroups = (slot.characterCount + kWorkgroupSize - 1) / kWorkgroupSize;
    for (std::uint32_t pass = 0; pass < cull.size(); ++pass) {
        if (pass > 0) recordSlotsBarrier(commands, slot);
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *cull[pass]);
        commands.dispatch(pass == 1 ? 1 : workgroups, 1, 1);
    }
    const std::array<vk::BufferMemoryBarrier2, 3> culled{
        bufferBarrier(slot.drawArguments, Stage::eComputeShader, Access::eShaderStorageWrite, consumers.argumentsStage | Stage::eCopy,
                      consumers.argumentsAccess | Access::eTransferRead),
        // The visibility path's shading reads them through their texel view.
        bufferBarrier(slot.instances, Stage::eComputeShader, Access::eShaderStorageWrite, consumers.instancesStage | Stage::eCopy,
                      Access::eShaderStorageRead | Access::eShaderSampledRead | Access::eTransferRead),
        bufferBarrier(slot.instanceOwners, Stage::eComputeShader, Access::eShaderStorageWrite, Stage::eCopy, Access::eTransferRead)};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 3, .pBufferMemoryBarriers = culled.data()});
    // The counts travel to a host-visible copy, read once the frame's fence has signalled.
    commands.copyBuffer(slot.drawArguments.handle(), slot.counts.handle(), vk::BufferCopy{.size = sizeof(FastPathCounts)});
    const vk::MemoryBarrier2 toHost{.srcStageMask = Stage::eCopy, .srcAccessMask = Access::eTransferWrite,
                                    .dstStageMask = Stage::eHost, .dstAccessMask = Access::eHostRead};
    commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
}

FastPathCounts readCounts(const SlotBuffers& slot) {
    slot.counts.invalidate();
    FastPathCounts counts;
    std::memcpy(&counts, slot.counts.mapped(), sizeof counts);
    return counts;
}

DetailCounts culledCounts(const SlotBuffers& slot) {
    const FastPathCounts counts = readCounts(slot);
    const std::uint32_t visible = counts.fullCharacters + counts.coarseCharacters;
    return DetailCounts{.full = counts.fullCharacters, .coarse = counts.coarseCharacters,
                        .culled = slot.characterCount - std::min(visible, slot.characterCount), .skin = {}, .bones = {}, .fading = {}};
}

vk::raii::Pipeline createJointSpritePipeline(const PathSetup& setup) {
    const gpu::Context& context = *setup.context;
    const auto vertex = gpu::createShaderModule(context, kImpostorVertSpirv);
    const auto fragment = gpu::createShaderModule(context, kImpostorFragSpirv);
    gpu::GraphicsPipelineInfo info = targetPipeline(setup, vertex, &fragment, vk::PrimitiveTopology::ePointList);
    info.cullMode = vk::CullModeFlagBits::eNone;
    info.alphaToCoverage = setup.samples != vk::SampleCountFlagBits::e1;
    return gpu::createGraphicsPipeline(context, info);
}

std::unique_ptr<RenderPathImpl> makeFastPath(const PathSetup& setup, float lodPixels) {
    return std::make_unique<FastPath>(setup, lodPixels);
}

}  // namespace throng::render::detail
