#pragma once
// Image layout transitions as one synchronization2 barrier each (vulkan-guide's
// transition_image idea): the caller states both sides of the dependency, so every use says why.

#include "throng/gpu/vulkan.h"

namespace throng::gpu {

/// Moves `image` (all of it, one mip and layer) from layout `from` to `to`, after the
/// `srcStage`/`srcAccess` work and before the `dstStage`/`dstAccess` work.
void transitionImage(const vk::raii::CommandBuffer& commands, vk::Image image, vk::ImageAspectFlags aspect, vk::ImageLayout from,
                     vk::ImageLayout to, vk::PipelineStageFlags2 srcStage, vk::AccessFlags2 srcAccess,
                     vk::PipelineStageFlags2 dstStage, vk::AccessFlags2 dstAccess);

}  // namespace throng::gpu
