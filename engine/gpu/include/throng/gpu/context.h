#pragma once
// Vulkan instance, physical-device choice and logical device. A real GPU is preferred;
// lavapipe (llvmpipe, the CPU) is the fallback, and `deviceFilter` picks by name.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "throng/gpu/vulkan.h"

namespace throng::gpu {

struct ContextCreateInfo {
    /// Substring of the device name to pick (case-insensitive), e.g. "llvmpipe"; empty picks
    /// the best device: discrete GPU, then integrated, then virtual, then CPU.
    std::string deviceFilter;
    /// Enable the Khronos validation layer and report its messages. Also turned on by the
    /// environment variable THRONG_VALIDATION=1.
    bool validation = false;
    /// With validation, also enable synchronization validation.
    bool synchronizationValidation = true;
    /// Instance extensions a window system needs (the viewer asks its window library); empty for headless.
    std::vector<std::string> instanceExtensions;
    /// For a window: makes the surface from the new instance. The chosen device must then be
    /// able to present to it from its graphics+compute queue, and the swapchain extension is enabled.
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

/// What `throng devices` prints for each device.
struct DeviceDescription {
    std::string name;
    std::string type;        ///< "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other".
    std::string apiVersion;  ///< "1.3.230"
    std::string driver;      ///< Driver name and info, e.g. "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)".
};

/// Counts what the validation layer reported; shared with its callback.
struct ValidationReport {
    std::atomic<std::uint32_t> messages{0};  ///< Warnings and errors (any message fails a test).
};

class Context {
public:
    explicit Context(const ContextCreateInfo& info);
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    ~Context();

    [[nodiscard]] const vk::raii::Instance& instance() const { return instance_; }
    [[nodiscard]] const vk::raii::PhysicalDevice& physicalDevice() const { return physicalDevice_; }
    [[nodiscard]] const vk::raii::Device& device() const { return device_; }
    [[nodiscard]] const vk::raii::Queue& queue() const { return queue_; }
    /// The window surface, or a null handle for headless contexts.
    [[nodiscard]] vk::SurfaceKHR surface() const { return *surface_; }
    [[nodiscard]] std::uint32_t queueFamily() const { return queueFamily_; }
    [[nodiscard]] const DeviceDescription& description() const { return description_; }
    [[nodiscard]] const vk::PhysicalDeviceLimits& limits() const { return limits_; }
    [[nodiscard]] bool validationEnabled() const { return validation_ != nullptr; }
    /// Validation warnings and errors so far (0 when validation is off).
    [[nodiscard]] std::uint32_t validationMessages() const { return validation_ ? validation_->messages.load() : 0; }

    /// A memory type with all `required` flags among `typeBits`; throws VulkanError if none.
    [[nodiscard]] std::uint32_t memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags required) const;
    /// Like memoryType, but tries `preferred` first and falls back to `required`.
    [[nodiscard]] std::uint32_t memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags preferred,
                                           vk::MemoryPropertyFlags required) const;
    [[nodiscard]] vk::MemoryPropertyFlags memoryFlags(std::uint32_t type) const;
    /// Bytes of the largest device-local memory heap (for lavapipe, a share of the host's).
    [[nodiscard]] std::uint64_t largestDeviceHeap() const;
    /// 64-bit integers and 64-bit atomics on storage buffers are enabled (the visibility path needs them).
    [[nodiscard]] bool hasInt64Atomics() const { return int64Atomics_; }
    /// Largest MSAA sample count usable for both colour and depth, capped at `wanted`.
    [[nodiscard]] vk::SampleCountFlagBits sampleCount(std::uint32_t wanted) const;

private:
    void createInstance(const ContextCreateInfo& info);
    void chooseDevice(const std::string& deviceFilter);
    void createDevice();

    vk::raii::Context loader_;
    std::unique_ptr<ValidationReport> validation_;
    vk::raii::Instance instance_{nullptr};
    vk::raii::DebugUtilsMessengerEXT messenger_{nullptr};
    vk::raii::SurfaceKHR surface_{nullptr};
    vk::raii::PhysicalDevice physicalDevice_{nullptr};
    vk::raii::Device device_{nullptr};
    vk::raii::Queue queue_{nullptr};
    std::uint32_t queueFamily_ = 0;
    DeviceDescription description_;
    vk::PhysicalDeviceLimits limits_;
    vk::PhysicalDeviceMemoryProperties memory_;
    bool int64Atomics_ = false;
    std::uint64_t memoryCap_ = UINT64_MAX;  ///< THRONG_DEVICE_MEMORY_LIMIT, for tests.
};

/// Every device the Vulkan loader sees, in its order. Throws VulkanError without a loader.
[[nodiscard]] std::vector<DeviceDescription> listDevices();

}  // namespace throng::gpu
