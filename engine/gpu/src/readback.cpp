#include "throng/gpu/readback.h"

#include <cstring>

namespace throng::gpu {
namespace {

// The copy's writes must be visible to the host once the fence signals: a fence alone makes
// the work complete, not its writes available to host reads.
void makeCopyVisibleToHost(const vk::raii::CommandBuffer& commands) {
    const vk::MemoryBarrier2 toHost{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                    .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                    .dstStageMask = vk::PipelineStageFlagBits2::eHost,
                                    .dstAccessMask = vk::AccessFlagBits2::eHostRead};
    commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
}

}  // namespace

ImageReadback::ImageReadback(const Context& context, vk::Extent2D extent)
    : extent_(extent),
      rowTexels_((extent.width + 63U) / 64U * 64U),
      buffer_(context, {.size = std::size_t{rowTexels_} * 4 * std::max(extent.height, 1U),
                        .usage = vk::BufferUsageFlagBits::eTransferDst,
                        .intent = MemoryIntent::Readback}) {}

void ImageReadback::recordCopy(const vk::raii::CommandBuffer& commands, vk::Image image) const {
    commands.copyImageToBuffer(image, vk::ImageLayout::eTransferSrcOptimal, buffer_.handle(),
                               vk::BufferImageCopy{.bufferRowLength = rowTexels_,
                                                   .imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                                   .imageExtent = {extent_.width, extent_.height, 1}});
    makeCopyVisibleToHost(commands);
}

std::vector<std::uint8_t> ImageReadback::read() const {
    buffer_.invalidate();
    const std::size_t rowBytes = std::size_t{extent_.width} * 4;
    std::vector<std::uint8_t> rgba(rowBytes * extent_.height);
    for (std::uint32_t y = 0; y < extent_.height; ++y)
        std::memcpy(rgba.data() + y * rowBytes, buffer_.mapped() + std::size_t{y} * rowTexels_ * 4, rowBytes);
    return rgba;
}

std::vector<std::byte> downloadBuffer(const Context& context, const Buffer& source, std::size_t bytes) {
    if (bytes == 0) return {};
    const Buffer staging(context, {.size = bytes, .usage = vk::BufferUsageFlagBits::eTransferDst, .intent = MemoryIntent::Readback});
    immediateSubmit(context, [&](const vk::raii::CommandBuffer& commands) {
        commands.copyBuffer(source.handle(), staging.handle(), vk::BufferCopy{.size = bytes});
        makeCopyVisibleToHost(commands);
    });
    staging.invalidate();
    return {staging.mapped(), staging.mapped() + bytes};
}

}  // namespace throng::gpu
