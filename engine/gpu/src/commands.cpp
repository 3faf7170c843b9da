#include "throng/gpu/commands.h"

namespace throng::gpu {

FrameCommands::FrameCommands(const Context& context)
    : pool_(context.device(), vk::CommandPoolCreateInfo{.flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                        .queueFamilyIndex = context.queueFamily()}) {
    vk::raii::CommandBuffers buffers(context.device(), vk::CommandBufferAllocateInfo{.commandPool = *pool_,
                                                                                   .level = vk::CommandBufferLevel::ePrimary,
                                                                                   .commandBufferCount = 1});
    buffer_ = std::move(buffers.front());
}

const vk::raii::CommandBuffer& FrameCommands::begin() {
    buffer_.reset();
    buffer_.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    return buffer_;
}

void submit(const Context& context, const vk::raii::CommandBuffer& commands, vk::Fence fence, vk::Semaphore wait,
            vk::PipelineStageFlags2 waitStage, vk::Semaphore signal) {
    const vk::SemaphoreSubmitInfo waitInfo{.semaphore = wait, .stageMask = waitStage};
    // The signal fires when everything before it is done: presentation reads the finished image.
    const vk::SemaphoreSubmitInfo signalInfo{.semaphore = signal, .stageMask = vk::PipelineStageFlagBits2::eAllCommands};
    const vk::CommandBufferSubmitInfo commandInfo{.commandBuffer = *commands};
    context.queue().submit2(vk::SubmitInfo2{.waitSemaphoreInfoCount = wait ? 1U : 0U,
                                            .pWaitSemaphoreInfos = &waitInfo,
                                            .commandBufferInfoCount = 1,
                                            .pCommandBufferInfos = &commandInfo,
                                            .signalSemaphoreInfoCount = signal ? 1U : 0U,
                                            .pSignalSemaphoreInfos = &signalInfo},
                            fence);
}

}  // namespace throng::gpu
