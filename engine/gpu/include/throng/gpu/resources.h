#pragma once
// Move-only owners of buffers and images, made from a create-info struct that states the
// memory intent (Granite's buffer.hpp pattern): the factory picks the memory type.

#include <cstddef>
#include <cstring>
#include <functional>
#include <span>

#include "throng/gpu/context.h"

namespace throng::gpu {

/// Where the memory lives and who touches it.
enum class MemoryIntent {
    DeviceLocal,  ///< GPU only; filled through a staging upload. Fastest for the GPU.
    HostUpload,   ///< CPU writes every frame, GPU reads; persistently mapped, coherent.
    Readback,     ///< GPU writes, CPU reads; persistently mapped, cached where possible.
};

struct BufferCreateInfo {
    vk::DeviceSize size = 0;             ///< Bytes, > 0.
    vk::BufferUsageFlags usage;          ///< TransferDst is added for DeviceLocal, TransferSrc never implied.
    MemoryIntent intent = MemoryIntent::DeviceLocal;
};

class Buffer {
public:
    Buffer() = default;
    Buffer(const Context& context, const BufferCreateInfo& info);

    [[nodiscard]] vk::Buffer handle() const { return *buffer_; }
    [[nodiscard]] vk::DeviceSize size() const { return size_; }
    /// Mapped pointer for host intents, nullptr for DeviceLocal.
    [[nodiscard]] std::byte* mapped() const { return mapped_; }
    /// Copies bytes into a host-visible buffer at `offset`.
    void write(std::span<const std::byte> bytes, vk::DeviceSize offset = 0);
    /// Makes GPU writes visible to the CPU for non-coherent readback memory.
    void invalidate() const;

private:
    vk::raii::Buffer buffer_{nullptr};
    vk::raii::DeviceMemory memory_{nullptr};
    vk::DeviceSize size_ = 0;
    std::byte* mapped_ = nullptr;
    bool coherent_ = true;
    const vk::raii::Device* device_ = nullptr;
};

struct ImageCreateInfo {
    vk::Extent2D extent;
    vk::Format format = vk::Format::eR8G8B8A8Unorm;
    vk::ImageUsageFlags usage;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
    vk::ImageAspectFlags aspect = vk::ImageAspectFlagBits::eColor;
};

/// A device-local 2D image with one view.
class Image {
public:
    Image() = default;
    Image(const Context& context, const ImageCreateInfo& info);

    [[nodiscard]] vk::Image handle() const { return *image_; }
    [[nodiscard]] vk::ImageView view() const { return *view_; }
    [[nodiscard]] vk::Extent2D extent() const { return extent_; }
    [[nodiscard]] vk::Format format() const { return format_; }

private:
    vk::raii::Image image_{nullptr};
    vk::raii::DeviceMemory memory_{nullptr};
    vk::raii::ImageView view_{nullptr};
    vk::Extent2D extent_;
    vk::Format format_ = vk::Format::eUndefined;
};

/// Records into a one-time command buffer, submits it and waits (vulkan-guide's immediate
/// submit). For uploads and readbacks, not for per-frame work.
void immediateSubmit(const Context& context, const std::function<void(const vk::raii::CommandBuffer&)>& record);

/// Fills a DeviceLocal buffer through a temporary staging buffer.
void uploadToDeviceLocal(const Context& context, const Buffer& destination, std::span<const std::byte> bytes);

/// Byte view of a contiguous range, for uploads.
template <typename T>
std::span<const std::byte> asBytes(std::span<const T> values) {
    return std::as_bytes(values);
}

}  // namespace throng::gpu
