#pragma once
// The one place the gpu module includes Vulkan-Hpp, so every user agrees on its configuration.

#define VULKAN_HPP_NO_STRUCT_CONSTRUCTORS  // designated initialisers read better
#include <vulkan/vulkan_format_traits.hpp>  // vk::blockSize
#include <vulkan/vulkan_raii.hpp>

#include <string>

#include "throng/core/error.h"

namespace throng::gpu {

/// A Vulkan failure during setup or rendering: the CLI prints it as one line, exit code 1.
class VulkanError : public ThrongException {
public:
    explicit VulkanError(const std::string& message) : ThrongException(Error{Error::Kind::Runtime, message, {}}) {}
};

/// Throws VulkanError naming the VkResult, the call and where it was made.
[[noreturn]] void throwVulkanError(vk::Result result, const char* call, const char* file, int line);

}  // namespace throng::gpu

/// Checks a Vulkan C or C++ call that returns a result (Sascha Willems' VK_CHECK, as a
/// VulkanError instead of an abort).
#define THRONG_VK_CHECK(call)                                                                  \
    do {                                                                                       \
        const vk::Result throngVkResult_ = static_cast<vk::Result>(call);                     \
        if (throngVkResult_ != vk::Result::eSuccess)                                           \
            ::throng::gpu::throwVulkanError(throngVkResult_, #call, __FILE__, __LINE__);       \
    } while (false)
