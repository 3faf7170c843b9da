#include "throng/gpu/barriers.h"

namespace throng::gpu {

void transitionImage(const vk::raii::CommandBuffer& commands, vk::Image image, vk::ImageAspectFlags aspect, vk::ImageLayout from,
                     vk::ImageLayout to, vk::PipelineStageFlags2 srcStage, vk::AccessFlags2 srcAccess,
                     vk::PipelineStageFlags2 dstStage, vk::AccessFlags2 dstAccess) {
    const vk::ImageMemoryBarrier2 barrier{.srcStageMask = srcStage, .srcAccessMask = srcAccess, .dstStageMask = dstStage,
                                          .dstAccessMask = dstAccess, .oldLayout = from, .newLayout = to, .image = image,
                                          .subresourceRange = {aspect, 0, 1, 0, 1}};
    commands.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &barrier});
}

}  // namespace throng::gpu
