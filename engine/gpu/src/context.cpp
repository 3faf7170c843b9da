#include "throng/gpu/context.h"

#include "throng/core/environment.h"
#include "throng/core/log.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

namespace throng::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    const bool counts = (severity & (VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                     VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)) != 0;
    if (counts) {
        static_cast<ValidationReport*>(user)->messages.fetch_add(1);
        std::fprintf(stderr, "throng: validation: %s\n", data->pMessage != nullptr ? data->pMessage : "(no text)");
    }
    return VK_FALSE;  // never abort the call that triggered it
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::string versionString(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

const char* typeName(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete GPU";
        case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated GPU";
        case vk::PhysicalDeviceType::eVirtualGpu: return "virtual GPU";
        case vk::PhysicalDeviceType::eCpu: return "CPU";
        default: return "other";
    }
}

int preference(vk::PhysicalDeviceType type) {
    switch (type) {
        case vk::PhysicalDeviceType::eDiscreteGpu: return 4;
        case vk::PhysicalDeviceType::eIntegratedGpu: return 3;
        case vk::PhysicalDeviceType::eVirtualGpu: return 2;
        case vk::PhysicalDeviceType::eCpu: return 1;
        default: return 0;
    }
}

DeviceDescription describe(const vk::raii::PhysicalDevice& device) {
    const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>();
    const auto& properties = chain.get<vk::PhysicalDeviceProperties2>().properties;
    const auto& driver = chain.get<vk::PhysicalDeviceDriverProperties>();
    return {properties.deviceName.data(), typeName(properties.deviceType), versionString(properties.apiVersion),
            std::string(driver.driverName.data()) + " " + driver.driverInfo.data()};
}

// One queue does everything: graphics, compute and (for a window) present.
std::optional<std::uint32_t> graphicsComputeFamily(const vk::raii::PhysicalDevice& device, vk::SurfaceKHR surface) {
    const auto families = device.getQueueFamilyProperties();
    for (std::uint32_t i = 0; i < families.size(); ++i)
        if ((families[i].queueFlags & vk::QueueFlagBits::eGraphics) && (families[i].queueFlags & vk::QueueFlagBits::eCompute) &&
            (!surface || device.getSurfaceSupportKHR(i, surface)))
            return i;
    return std::nullopt;
}

bool wantsValidationFromEnvironment() {
    const char* value = std::getenv("THRONG_VALIDATION");
    return value != nullptr && std::strcmp(value, "0") != 0 && value[0] != '\0';
}

// THRONG_STORAGE_BUFFER_LIMIT=BYTES lowers the device's maxStorageBufferRange, and
// THRONG_DEVICE_MEMORY_LIMIT=BYTES its memory, so tests can meet a large crowd's limits with a
// small one: split over several buffers, or refused for want of memory.
std::optional<std::uint64_t> byteLimitFromEnvironment(const char* name, std::uint64_t most) {
    return wholeNumberFromEnvironment(name, 4096, most, "a byte count");
}

}  // namespace

void throwVulkanError(vk::Result result, const char* call, const char* file, int line) {
    throw VulkanError(std::string("Vulkan call failed with ") + vk::to_string(result) + ": " + call + " (" + file + ":" +
                      std::to_string(line) + ")");
}

Context::Context(const ContextCreateInfo& info) {
    createInstance(info);
    if (info.createSurface) {
        const VkSurfaceKHR surface = info.createSurface(*instance_);
        if (surface == VK_NULL_HANDLE) throw VulkanError("cannot create a Vulkan surface for the window");
        surface_ = vk::raii::SurfaceKHR(instance_, surface);
    }
    chooseDevice(info.deviceFilter);
    createDevice();
}

void Context::createInstance(const ContextCreateInfo& info) {
    const bool validation = info.validation || wantsValidationFromEnvironment();
    std::vector<const char*> layers, extensions;
    for (const std::string& extension : info.instanceExtensions) extensions.push_back(extension.c_str());
    if (validation) {
        const auto available = loader_.enumerateInstanceLayerProperties();
        const bool found = std::any_of(available.begin(), available.end(),
                                       [](const vk::LayerProperties& l) { return std::strcmp(l.layerName, kValidationLayer) == 0; });
        if (!found)
            throw VulkanError(std::string("validation was requested but ") + kValidationLayer +
                              " is not installed (Debian package vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        validation_ = std::make_unique<ValidationReport>();
    }

    const vk::ApplicationInfo application{.pApplicationName = "throng", .applicationVersion = 1, .pEngineName = "throng",
                                          .engineVersion = 1, .apiVersion = VK_API_VERSION_1_3};
    const vk::ValidationFeatureEnableEXT syncValidation = vk::ValidationFeatureEnableEXT::eSynchronizationValidation;
    const vk::DebugUtilsMessengerCreateInfoEXT messengerInfo{
        .messageSeverity = vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning | vk::DebugUtilsMessageSeverityFlagBitsEXT::eError,
        .messageType = vk::DebugUtilsMessageTypeFlagBitsEXT::eGeneral | vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation |
                       vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance,
        .pfnUserCallback = &onValidationMessage,
        .pUserData = validation_.get()};
    // The messenger info is chained so that instance creation and destruction are validated too.
    const vk::ValidationFeaturesEXT features{
        .pNext = &messengerInfo, .enabledValidationFeatureCount = 1, .pEnabledValidationFeatures = &syncValidation};
    const void* next = nullptr;
    if (validation) next = info.synchronizationValidation ? static_cast<const void*>(&features) : &messengerInfo;
    const vk::InstanceCreateInfo instanceInfo{.pNext = next,
                                              .pApplicationInfo = &application,
                                              .enabledLayerCount = static_cast<std::uint32_t>(layers.size()),
                                              .ppEnabledLayerNames = layers.data(),
                                              .enabledExtensionCount = static_cast<std::uint32_t>(extensions.size()),
                                              .ppEnabledExtensionNames = extensions.data()};
    try {
        instance_ = vk::raii::Instance(loader_, instanceInfo);
    } catch (const vk::SystemError& e) {
        throw VulkanError(std::string("cannot create a Vulkan instance (is a Vulkan driver installed? Debian: "
                                      "mesa-vulkan-drivers): ") + e.what());
    }
    if (validation) messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, messengerInfo);
}

// Among devices with Vulkan 1.3 and a graphics+compute queue (that can present, with a
// surface) whose name contains `deviceFilter`, the most capable type.
void Context::chooseDevice(const std::string& deviceFilter) {
    vk::raii::PhysicalDevices devices(instance_);
    const std::string filter = lower(deviceFilter);
    std::string seen;
    int bestScore = -1;
    for (vk::raii::PhysicalDevice& candidate : devices) {
        const DeviceDescription description = describe(candidate);
        seen += (seen.empty() ? "" : ", ") + description.name;
        if (!filter.empty() && lower(description.name).find(filter) == std::string::npos) continue;
        if (candidate.getProperties().apiVersion < VK_API_VERSION_1_3 || !graphicsComputeFamily(candidate, *surface_)) continue;
        const int score = preference(candidate.getProperties().deviceType);
        if (score > bestScore) {
            bestScore = score;
            physicalDevice_ = std::move(candidate);
            description_ = description;
        }
    }
    if (bestScore < 0) {
        if (!filter.empty())
            throw ThrongException(Error{Error::Kind::BadInput,
                                        "no Vulkan 1.3 device matches --device '" + deviceFilter + "' (devices: " +
                                            (seen.empty() ? "none" : seen) + "; see 'throng devices')",
                                        {}});
        throw VulkanError(std::string("no Vulkan 1.3 device with graphics and compute") + (*surface_ ? " that can present to the window" : "") +
                          " was found (devices: " +
                          (seen.empty() ? std::string("none") : seen) + "); Debian: install mesa-vulkan-drivers for lavapipe");
    }
    limits_ = physicalDevice_.getProperties().limits;
    if (const std::optional<std::uint64_t> cap = byteLimitFromEnvironment("THRONG_STORAGE_BUFFER_LIMIT", UINT32_MAX))
        limits_.maxStorageBufferRange = std::min(limits_.maxStorageBufferRange, static_cast<std::uint32_t>(*cap));
    if (const std::optional<std::uint64_t> cap = byteLimitFromEnvironment("THRONG_DEVICE_MEMORY_LIMIT", UINT64_MAX)) memoryCap_ = *cap;
    memory_ = physicalDevice_.getMemoryProperties();
    queueFamily_ = *graphicsComputeFamily(physicalDevice_, *surface_);
    log::info("Vulkan device: " + description_.name + " (" + description_.type + ", " + description_.driver + ")");
}

void Context::createDevice() {
    const float priority = 1.0F;
    const vk::DeviceQueueCreateInfo queueInfo{.queueFamilyIndex = queueFamily_, .queueCount = 1, .pQueuePriorities = &priority};
    // maintenance4 is required of every 1.3 device; glslang emits LocalSizeId, which needs it.
    vk::PhysicalDeviceVulkan13Features features13{.synchronization2 = VK_TRUE, .dynamicRendering = VK_TRUE, .maintenance4 = VK_TRUE};
    const auto supported = physicalDevice_.getFeatures2<vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan12Features,
                                                        vk::PhysicalDeviceVulkan13Features>();
    if (!supported.get<vk::PhysicalDeviceVulkan13Features>().dynamicRendering ||
        !supported.get<vk::PhysicalDeviceVulkan13Features>().synchronization2)
        throw VulkanError("device '" + description_.name + "' lacks dynamic rendering or synchronization2");
    // The visibility path keeps the nearest sphere per pixel with 64-bit atomicMin; enabled
    // where the device has it (the path refuses to start where it doesn't).
    const auto& supported12 = supported.get<vk::PhysicalDeviceVulkan12Features>();
    int64Atomics_ = supported12.shaderBufferInt64Atomics == VK_TRUE && physicalDevice_.getFeatures().shaderInt64 == VK_TRUE;
    vk::PhysicalDeviceVulkan12Features features12{.pNext = &features13, .shaderBufferInt64Atomics = int64Atomics_ ? VK_TRUE : VK_FALSE};
    // Point sprites bigger than one pixel (the fast path's impostors) need largePoints.
    const vk::PhysicalDeviceFeatures2 features2{.pNext = &features12,
                                                .features = {.largePoints = physicalDevice_.getFeatures().largePoints,
                                                             .shaderInt64 = int64Atomics_ ? VK_TRUE : VK_FALSE}};
    std::vector<const char*> deviceExtensions;
    if (*surface_) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    const vk::DeviceCreateInfo deviceInfo{.pNext = &features2,
                                          .queueCreateInfoCount = 1,
                                          .pQueueCreateInfos = &queueInfo,
                                          .enabledExtensionCount = static_cast<std::uint32_t>(deviceExtensions.size()),
                                          .ppEnabledExtensionNames = deviceExtensions.data()};
    device_ = vk::raii::Device(physicalDevice_, deviceInfo);
    queue_ = vk::raii::Queue(device_, queueFamily_, 0);
}

Context::~Context() {
    if (*device_) device_.waitIdle();
}

std::uint32_t Context::memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags required) const {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1U << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required) return i;
    throw VulkanError("device '" + description_.name + "' has no memory type with " + vk::to_string(required));
}

std::uint32_t Context::memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags preferred,
                                  vk::MemoryPropertyFlags required) const {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1U << i)) && (memory_.memoryTypes[i].propertyFlags & preferred) == preferred) return i;
    return memoryType(typeBits, required);
}

vk::MemoryPropertyFlags Context::memoryFlags(std::uint32_t type) const { return memory_.memoryTypes[type].propertyFlags; }

std::uint64_t Context::largestDeviceHeap() const {
    std::uint64_t largest = 0;
    for (std::uint32_t i = 0; i < memory_.memoryHeapCount; ++i)
        if (memory_.memoryHeaps[i].flags & vk::MemoryHeapFlagBits::eDeviceLocal) largest = std::max<std::uint64_t>(largest, memory_.memoryHeaps[i].size);
    return std::min(largest, memoryCap_);
}

vk::SampleCountFlagBits Context::sampleCount(std::uint32_t wanted) const {
    const vk::SampleCountFlags both = limits_.framebufferColorSampleCounts & limits_.framebufferDepthSampleCounts;
    for (std::uint32_t count = std::min<std::uint32_t>(wanted, 64); count > 1; count /= 2)
        if (both & static_cast<vk::SampleCountFlagBits>(count)) return static_cast<vk::SampleCountFlagBits>(count);
    return vk::SampleCountFlagBits::e1;
}

std::vector<DeviceDescription> listDevices() {
    vk::raii::Context loader;
    const vk::ApplicationInfo application{.pApplicationName = "throng", .apiVersion = VK_API_VERSION_1_3};
    try {
        vk::raii::Instance instance(loader, vk::InstanceCreateInfo{.pApplicationInfo = &application});
        std::vector<DeviceDescription> out;
        for (const vk::raii::PhysicalDevice& device : vk::raii::PhysicalDevices(instance)) out.push_back(describe(device));
        return out;
    } catch (const vk::SystemError& e) {
        throw VulkanError(std::string("cannot list Vulkan devices: ") + e.what());
    }
}

}  // namespace throng::gpu
