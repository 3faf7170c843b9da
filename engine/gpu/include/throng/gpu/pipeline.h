#pragma once
// Small stateless builders for shader modules, descriptor layouts and pipelines
// (vulkan-guide's vk_pipelines.h idea): each takes a plain struct and returns an owner.

#include <span>
#include <vector>

#include "throng/gpu/context.h"

namespace throng::gpu {

/// A shader module from SPIR-V words (embedded in the binary at build time).
[[nodiscard]] vk::raii::ShaderModule createShaderModule(const Context& context, std::span<const std::uint32_t> spirv);

/// One binding of a descriptor set layout.
struct DescriptorBinding {
    std::uint32_t binding = 0;
    vk::DescriptorType type = vk::DescriptorType::eStorageBuffer;
    vk::ShaderStageFlags stages;
};

[[nodiscard]] vk::raii::DescriptorSetLayout createDescriptorSetLayout(const Context& context,
                                                                      std::span<const DescriptorBinding> bindings);

/// Writes whole buffers into a descriptor set, one per binding.
struct BufferBinding {
    std::uint32_t binding = 0;
    vk::DescriptorType type = vk::DescriptorType::eStorageBuffer;
    vk::Buffer buffer;
    vk::DeviceSize range = VK_WHOLE_SIZE;
    vk::BufferView texelView{};  ///< For the texel buffer types: the view bound instead of the buffer.
};
void writeDescriptorSet(const Context& context, vk::DescriptorSet set, std::span<const BufferBinding> bindings);

/// `constants` specialise the shader's 32-bit constants with constant_id 0, 1, ... in order.
[[nodiscard]] vk::raii::Pipeline createComputePipeline(const Context& context, const vk::raii::ShaderModule& shader,
                                                       const vk::raii::PipelineLayout& layout, std::span<const std::uint32_t> constants = {});

/// Everything a graphics pipeline for dynamic rendering needs. Viewport and scissor are dynamic.
struct GraphicsPipelineInfo {
    const vk::raii::ShaderModule* vertexShader = nullptr;
    const vk::raii::ShaderModule* fragmentShader = nullptr;  ///< None: a depth-only draw (colorWrite must be off).
    const vk::raii::PipelineLayout* layout = nullptr;
    std::vector<vk::VertexInputBindingDescription> vertexBindings;
    std::vector<vk::VertexInputAttributeDescription> vertexAttributes;
    vk::PrimitiveTopology topology = vk::PrimitiveTopology::eTriangleList;
    vk::CullModeFlags cullMode = vk::CullModeFlagBits::eBack;
    bool depthTest = true;         ///< Off: no depth test and no depth written (depthWrite is then moot).
    bool depthWrite = true;
    vk::CompareOp depthCompare = vk::CompareOp::eLess;
    vk::Format colorFormat = vk::Format::eR8G8B8A8Unorm;
    vk::Format depthFormat = vk::Format::eD32Sfloat;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;
    bool alphaToCoverage = false;  ///< Fragment alpha decides which samples are covered (smooth edges with MSAA).
    bool alphaBlend = false;       ///< Fragment colour blended over the target by its alpha (the target's alpha kept).
    bool colorWrite = true;        ///< Off: the colour attachment is left as it is.
};

[[nodiscard]] vk::raii::Pipeline createGraphicsPipeline(const Context& context, const GraphicsPipelineInfo& info);

}  // namespace throng::gpu
