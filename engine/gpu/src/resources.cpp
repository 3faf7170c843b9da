#include "throng/gpu/resources.h"

#include <string>

#include "throng/core/error.h"

namespace throng::gpu {
namespace {

// A crowd too large for the device's memory ends in one clear line, not a driver's code.
vk::raii::DeviceMemory allocate(const Context& context, const vk::MemoryAllocateInfo& info) {
    try {
        return vk::raii::DeviceMemory(context.device(), info);
    } catch (const vk::OutOfDeviceMemoryError&) {
    } catch (const vk::OutOfHostMemoryError&) {
    }
    throw ThrongException(Error{Error::Kind::Runtime,
                                "out of GPU memory: the device could not allocate " + std::to_string(info.allocationSize >> 20) +
                                    " MiB more (fewer characters, or a smaller frame, would fit)",
                                {}});
}

}  // namespace

Buffer::Buffer(const Context& context, const BufferCreateInfo& info) : size_(info.size), device_(&context.device()) {
    if (info.size == 0) throw VulkanError("cannot create an empty buffer");
    vk::BufferUsageFlags usage = info.usage;
    if (info.intent == MemoryIntent::DeviceLocal) usage |= vk::BufferUsageFlagBits::eTransferDst;
    buffer_ = vk::raii::Buffer(context.device(), vk::BufferCreateInfo{.size = info.size, .usage = usage});
    const vk::MemoryRequirements requirements = buffer_.getMemoryRequirements();
    using F = vk::MemoryPropertyFlagBits;
    std::uint32_t type = 0;
    switch (info.intent) {
        case MemoryIntent::DeviceLocal: type = context.memoryType(requirements.memoryTypeBits, F::eDeviceLocal, {}); break;
        case MemoryIntent::HostUpload:
            type = context.memoryType(requirements.memoryTypeBits, F::eHostVisible | F::eHostCoherent);
            break;
        case MemoryIntent::Readback:
            // Cached memory makes CPU reads fast; coherent is optional (invalidate() covers it).
            type = context.memoryType(requirements.memoryTypeBits, F::eHostVisible | F::eHostCached, F::eHostVisible);
            break;
    }
    memory_ = allocate(context, {.allocationSize = requirements.size, .memoryTypeIndex = type});
    buffer_.bindMemory(*memory_, 0);
    if (info.intent != MemoryIntent::DeviceLocal) {
        mapped_ = static_cast<std::byte*>(memory_.mapMemory(0, VK_WHOLE_SIZE));
        coherent_ = static_cast<bool>(context.memoryFlags(type) & F::eHostCoherent);
    }
}

void Buffer::write(std::span<const std::byte> bytes, vk::DeviceSize offset) {
    if (mapped_ == nullptr) throw VulkanError("write() on a buffer that is not host-visible");
    if (offset + bytes.size() > size_) throw VulkanError("write() past the end of a buffer");
    std::memcpy(mapped_ + offset, bytes.data(), bytes.size());
}

void Buffer::invalidate() const {
    if (mapped_ != nullptr && !coherent_)
        device_->invalidateMappedMemoryRanges(vk::MappedMemoryRange{.memory = *memory_, .offset = 0, .size = VK_WHOLE_SIZE});
}

Image::Image(const Context& context, const ImageCreateInfo& info) : extent_(info.extent), format_(info.format) {
    image_ = vk::raii::Image(context.device(),
                             vk::ImageCreateInfo{.imageType = vk::ImageType::e2D,
                                                 .format = info.format,
                                                 .extent = {info.extent.width, info.extent.height, 1},
                                                 .mipLevels = 1,
                                                 .arrayLayers = 1,
                                                 .samples = info.samples,
                                                 .tiling = vk::ImageTiling::eOptimal,
                                                 .usage = info.usage,
                                                 .initialLayout = vk::ImageLayout::eUndefined});
    const vk::MemoryRequirements requirements = image_.getMemoryRequirements();
    memory_ = allocate(context, {.allocationSize = requirements.size,
                                 .memoryTypeIndex = context.memoryType(requirements.memoryTypeBits, vk::MemoryPropertyFlagBits::eDeviceLocal, {})});
    image_.bindMemory(*memory_, 0);
    view_ = vk::raii::ImageView(context.device(),
                                vk::ImageViewCreateInfo{.image = *image_,
                                                        .viewType = vk::ImageViewType::e2D,
                                                        .format = info.format,
                                                        .subresourceRange = {info.aspect, 0, 1, 0, 1}});
}

void immediateSubmit(const Context& context, const std::function<void(const vk::raii::CommandBuffer&)>& record) {
    const vk::raii::CommandPool pool(context.device(), vk::CommandPoolCreateInfo{
                                                           .flags = vk::CommandPoolCreateFlagBits::eTransient,
                                                           .queueFamilyIndex = context.queueFamily()});
    vk::raii::CommandBuffers buffers(context.device(), vk::CommandBufferAllocateInfo{
                                                           .commandPool = *pool,
                                                           .level = vk::CommandBufferLevel::ePrimary,
                                                           .commandBufferCount = 1});
    const vk::raii::CommandBuffer& commands = buffers.front();
    commands.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    record(commands);
    commands.end();
    const vk::raii::Fence fence(context.device(), vk::FenceCreateInfo{});
    const vk::CommandBufferSubmitInfo commandInfo{.commandBuffer = *commands};
    context.queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &commandInfo}, *fence);
    THRONG_VK_CHECK(context.device().waitForFences(*fence, VK_TRUE, UINT64_MAX));
}

void uploadToDeviceLocal(const Context& context, const Buffer& destination, std::span<const std::byte> bytes) {
    if (bytes.empty()) return;
    Buffer staging(context, {.size = bytes.size(), .usage = vk::BufferUsageFlagBits::eTransferSrc,
                             .intent = MemoryIntent::HostUpload});
    staging.write(bytes);
    immediateSubmit(context, [&](const vk::raii::CommandBuffer& commands) {
        commands.copyBuffer(staging.handle(), destination.handle(), vk::BufferCopy{.size = bytes.size()});
        // Later submissions read what this copy wrote; the fence alone orders it only for the host.
        const vk::MemoryBarrier2 written{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                         .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                         .dstStageMask = vk::PipelineStageFlagBits2::eAllCommands,
                                         .dstAccessMask = vk::AccessFlagBits2::eMemoryRead};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &written});
    });
}

}  // namespace throng::gpu
