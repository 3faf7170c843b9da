// The compute path (the paper's design with a compute pass): one invocation per joint instance
// resolves m = id / k, j = id % k into the instance buffer; instanced sphere meshes read it.
#include "sphere_draw.h"
#include "throng/gpu/pipeline.h"
#include "throng/shaders/resolve_comp.h"
#include "throng/shaders/sphere_vert.h"

namespace throng::render::detail {
namespace {

constexpr std::uint32_t kWorkgroupSize = 64;  // local_size_x of resolve.comp

class ComputePath final : public RenderPathImpl {
public:
    explicit ComputePath(const PathSetup& setup) : spheres_(setup, kSphereVertSpirv), joints_(setup.jointsPerCharacter) {
        const auto shader = gpu::createShaderModule(*setup.context, kResolveCompSpirv);
        resolve_ = gpu::createComputePipeline(*setup.context, shader, *setup.layout);
    }
    [[nodiscard]] RenderPath path() const override { return RenderPath::Compute; }
    [[nodiscard]] InstanceStorage storage() const override { return {}; }

    void recordCompute(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        using Stage = vk::PipelineStageFlagBits2;
        using Access = vk::AccessFlagBits2;
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *resolve_);
        const std::uint32_t instances = slot.characterCount * joints_;
        commands.dispatch((instances + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
        // The vertex shader reads what the compute pass just wrote: make the shader writes
        // available and visible to vertex-stage storage reads before any draw starts. (Transfer
        // reads cover --dump-instances, which copies the same buffer out.)
        const vk::BufferMemoryBarrier2 resolved{.srcStageMask = Stage::eComputeShader, .srcAccessMask = Access::eShaderStorageWrite,
                                                .dstStageMask = Stage::eVertexShader | Stage::eCopy,
                                                .dstAccessMask = Access::eShaderStorageRead | Access::eTransferRead,
                                                .buffer = slot.instances.handle(), .offset = 0, .size = VK_WHOLE_SIZE};
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &resolved});
    }
    void recordDraw(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot) const override {
        spheres_.record(commands, slot, joints_);
    }

private:
    SphereDraw spheres_;
    std::uint32_t joints_;
    vk::raii::Pipeline resolve_{nullptr};
};

}  // namespace

std::unique_ptr<RenderPathImpl> makeComputePath(const PathSetup& setup) { return std::make_unique<ComputePath>(setup); }

}  // namespace throng::render::detail
