#include "throng/gpu/pipeline.h"

#include <stdexcept>
#include <vector>

namespace throng::gpu {

vk::raii::ShaderModule createShaderModule(const Context& context, std::span<const std::uint32_t> spirv) {
    return {context.device(), vk::ShaderModuleCreateInfo{.codeSize = spirv.size_bytes(), .pCode = spirv.data()}};
}

vk::raii::DescriptorSetLayout createDescriptorSetLayout(const Context& context, std::span<const DescriptorBinding> bindings) {
    std::vector<vk::DescriptorSetLayoutBinding> vkBindings;
    for (const DescriptorBinding& b : bindings)
        vkBindings.push_back({.binding = b.binding, .descriptorType = b.type, .descriptorCount = 1, .stageFlags = b.stages});
    return {context.device(), vk::DescriptorSetLayoutCreateInfo{.bindingCount = static_cast<std::uint32_t>(vkBindings.size()),
                                                                .pBindings = vkBindings.data()}};
}

void writeDescriptorSet(const Context& context, vk::DescriptorSet set, std::span<const BufferBinding> bindings) {
    std::vector<vk::DescriptorBufferInfo> infos;
    infos.reserve(bindings.size());  // pointers into it must stay valid
    std::vector<vk::WriteDescriptorSet> writes;
    for (const BufferBinding& b : bindings) {
        infos.push_back({.buffer = b.buffer, .offset = 0, .range = b.range});
        const bool texels = b.type == vk::DescriptorType::eUniformTexelBuffer || b.type == vk::DescriptorType::eStorageTexelBuffer;
        writes.push_back({.dstSet = set, .dstBinding = b.binding, .descriptorCount = 1, .descriptorType = b.type,
                          .pBufferInfo = texels ? nullptr : &infos.back(), .pTexelBufferView = texels ? &b.texelView : nullptr});
    }
    context.device().updateDescriptorSets(writes, {});
}

vk::raii::Pipeline createComputePipeline(const Context& context, const vk::raii::ShaderModule& shader,
                                         const vk::raii::PipelineLayout& layout, std::span<const std::uint32_t> constants) {
    std::vector<vk::SpecializationMapEntry> entries;
    for (std::uint32_t i = 0; i < constants.size(); ++i)
        entries.push_back({.constantID = i, .offset = i * static_cast<std::uint32_t>(sizeof(std::uint32_t)), .size = sizeof(std::uint32_t)});
    const vk::SpecializationInfo specialization{.mapEntryCount = static_cast<std::uint32_t>(entries.size()),
                                                .pMapEntries = entries.data(),
                                                .dataSize = constants.size_bytes(),
                                                .pData = constants.data()};
    const vk::ComputePipelineCreateInfo info{
        .stage = {.stage = vk::ShaderStageFlagBits::eCompute, .module = *shader, .pName = "main",
                  .pSpecializationInfo = constants.empty() ? nullptr : &specialization},
        .layout = *layout};
    return {context.device(), nullptr, info};
}

vk::raii::Pipeline createGraphicsPipeline(const Context& context, const GraphicsPipelineInfo& info) {
    if (!info.fragmentShader && info.colorWrite) throw std::logic_error("createGraphicsPipeline: a draw with no fragment shader writes no colour");
    std::vector<vk::PipelineShaderStageCreateInfo> stages{{.stage = vk::ShaderStageFlagBits::eVertex, .module = **info.vertexShader, .pName = "main"}};
    if (info.fragmentShader) stages.push_back({.stage = vk::ShaderStageFlagBits::eFragment, .module = **info.fragmentShader, .pName = "main"});
    const vk::PipelineVertexInputStateCreateInfo vertexInput{
        .vertexBindingDescriptionCount = static_cast<std::uint32_t>(info.vertexBindings.size()),
        .pVertexBindingDescriptions = info.vertexBindings.data(),
        .vertexAttributeDescriptionCount = static_cast<std::uint32_t>(info.vertexAttributes.size()),
        .pVertexAttributeDescriptions = info.vertexAttributes.data()};
    const vk::PipelineInputAssemblyStateCreateInfo inputAssembly{.topology = info.topology};
    const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
    const vk::PipelineRasterizationStateCreateInfo rasterization{.polygonMode = vk::PolygonMode::eFill,
                                                                 .cullMode = info.cullMode,
                                                                 .frontFace = vk::FrontFace::eCounterClockwise,
                                                                 .lineWidth = 1.0F};
    const vk::PipelineMultisampleStateCreateInfo multisample{
        .rasterizationSamples = info.samples, .alphaToCoverageEnable = info.alphaToCoverage ? VK_TRUE : VK_FALSE};
    const vk::PipelineDepthStencilStateCreateInfo depth{.depthTestEnable = info.depthTest ? VK_TRUE : VK_FALSE,
                                                        .depthWriteEnable = info.depthWrite ? VK_TRUE : VK_FALSE,
                                                        .depthCompareOp = info.depthCompare};
    const vk::PipelineColorBlendAttachmentState attachment{
        .blendEnable = info.alphaBlend ? VK_TRUE : VK_FALSE,
        .srcColorBlendFactor = vk::BlendFactor::eSrcAlpha,
        .dstColorBlendFactor = vk::BlendFactor::eOneMinusSrcAlpha,
        .colorBlendOp = vk::BlendOp::eAdd,
        .srcAlphaBlendFactor = vk::BlendFactor::eZero,
        .dstAlphaBlendFactor = vk::BlendFactor::eOne,
        .alphaBlendOp = vk::BlendOp::eAdd,
        .colorWriteMask = info.colorWrite ? vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG | vk::ColorComponentFlagBits::eB |
                                                vk::ColorComponentFlagBits::eA
                                          : vk::ColorComponentFlags{}};
    const vk::PipelineColorBlendStateCreateInfo blend{.attachmentCount = 1, .pAttachments = &attachment};
    const vk::DynamicState dynamicStates[] = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
    const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = 2, .pDynamicStates = dynamicStates};
    const vk::PipelineRenderingCreateInfo rendering{.colorAttachmentCount = 1,
                                                    .pColorAttachmentFormats = &info.colorFormat,
                                                    .depthAttachmentFormat = info.depthFormat};
    const vk::GraphicsPipelineCreateInfo pipeline{.pNext = &rendering,
                                                  .stageCount = static_cast<std::uint32_t>(stages.size()),
                                                  .pStages = stages.data(),
                                                  .pVertexInputState = &vertexInput,
                                                  .pInputAssemblyState = &inputAssembly,
                                                  .pViewportState = &viewport,
                                                  .pRasterizationState = &rasterization,
                                                  .pMultisampleState = &multisample,
                                                  .pDepthStencilState = &depth,
                                                  .pColorBlendState = &blend,
                                                  .pDynamicState = &dynamic,
                                                  .layout = **info.layout};
    return {context.device(), nullptr, pipeline};
}

}  // namespace throng::gpu
