#include "throng/render/crowd_renderer.h"

#include "throng/shaders/ground_frag.h"
#include "throng/shaders/ground_vert.h"
#include "throng/shaders/resolve_comp.h"
#include "throng/shaders/sphere_frag.h"
#include "throng/shaders/sphere_vert.h"

namespace throng::render {
namespace {

struct ResolvePush {
    std::uint32_t characterCount;
    std::uint32_t jointsPerCharacter;
};

constexpr std::uint32_t kWorkgroupSize = 64;  // resolve.comp's local_size_x

}  // namespace

SphereMesh makeUnitSphere(std::uint32_t segments, std::uint32_t rings) {
    SphereMesh mesh;
    const float pi = glm::pi<float>();
    mesh.positions.push_back({0.0F, 1.0F, 0.0F});
    for (std::uint32_t ring = 1; ring < rings; ++ring) {
        const float polar = pi * static_cast<float>(ring) / static_cast<float>(rings);
        for (std::uint32_t segment = 0; segment < segments; ++segment) {
            const float azimuth = 2.0F * pi * static_cast<float>(segment) / static_cast<float>(segments);
            mesh.positions.push_back({std::sin(polar) * std::sin(azimuth), std::cos(polar), std::sin(polar) * std::cos(azimuth)});
        }
    }
    mesh.positions.push_back({0.0F, -1.0F, 0.0F});
    const auto bottom = static_cast<std::uint16_t>(mesh.positions.size() - 1);
    auto ringVertex = [&](std::uint32_t ring, std::uint32_t segment) {
        return static_cast<std::uint16_t>(1 + (ring - 1) * segments + segment % segments);
    };
    for (std::uint32_t s = 0; s < segments; ++s) {  // top cap
        mesh.indices.insert(mesh.indices.end(), {0, ringVertex(1, s), ringVertex(1, s + 1)});
    }
    for (std::uint32_t ring = 1; ring + 1 < rings; ++ring)
        for (std::uint32_t s = 0; s < segments; ++s) {
            const std::uint16_t a = ringVertex(ring, s), b = ringVertex(ring, s + 1), c = ringVertex(ring + 1, s),
                                d = ringVertex(ring + 1, s + 1);
            mesh.indices.insert(mesh.indices.end(), {a, c, d, a, d, b});
        }
    for (std::uint32_t s = 0; s < segments; ++s) {  // bottom cap
        mesh.indices.insert(mesh.indices.end(), {bottom, ringVertex(rings - 1, s + 1), ringVertex(rings - 1, s)});
    }
    return mesh;
}

std::uint64_t CrowdRenderer::maxCharactersFor(const gpu::Context& context, std::uint32_t jointsPerCharacter) {
    return context.limits().maxStorageBufferRange / (sizeof(InstanceGpu) * std::max(jointsPerCharacter, 1U));
}

CrowdRenderer::CrowdRenderer(const gpu::Context& context, const Palette& palette, const CrowdRendererCreateInfo& info)
    : context_(&context), jointsPerCharacter_(palette.jointsPerCharacter()), maxCharacters_(info.maxCharacters) {
    const std::uint64_t fits = maxCharactersFor(context, jointsPerCharacter_);
    if (info.maxCharacters > fits)
        throw ThrongException(Error{Error::Kind::BadInput,
                                    std::to_string(info.maxCharacters) + " characters of " + std::to_string(jointsPerCharacter_) +
                                        " joints exceed this device's storage buffer limit of " +
                                        std::to_string(context.limits().maxStorageBufferRange) + " bytes (at most " +
                                        std::to_string(fits) + " characters)",
                                    {}});
    const SphereMesh sphere = makeUnitSphere(info.sphereSegments, info.sphereRings);
    sphereIndexCount_ = static_cast<std::uint32_t>(sphere.indices.size());
    sphereVertices_ = gpu::Buffer(context, {.size = sphere.positions.size() * sizeof(glm::vec3),
                                            .usage = vk::BufferUsageFlagBits::eVertexBuffer});
    sphereIndices_ = gpu::Buffer(context, {.size = sphere.indices.size() * sizeof(std::uint16_t),
                                           .usage = vk::BufferUsageFlagBits::eIndexBuffer});
    gpu::uploadToDeviceLocal(context, sphereVertices_, std::as_bytes(std::span(sphere.positions)));
    gpu::uploadToDeviceLocal(context, sphereIndices_, std::as_bytes(std::span(sphere.indices)));

    using Stage = vk::ShaderStageFlagBits;
    const vk::ShaderStageFlags all = Stage::eCompute | Stage::eVertex | Stage::eFragment;
    const gpu::DescriptorBinding bindings[] = {
        {0, vk::DescriptorType::eStorageBuffer, Stage::eCompute}, {1, vk::DescriptorType::eStorageBuffer, Stage::eCompute},
        {2, vk::DescriptorType::eStorageBuffer, Stage::eCompute}, {3, vk::DescriptorType::eStorageBuffer, Stage::eCompute},
        {4, vk::DescriptorType::eStorageBuffer, Stage::eCompute | Stage::eVertex},
        {5, vk::DescriptorType::eUniformBuffer, all}};
    setLayout_ = gpu::createDescriptorSetLayout(context, bindings);
    const vk::PushConstantRange push{.stageFlags = Stage::eCompute, .offset = 0, .size = sizeof(ResolvePush)};
    pipelineLayout_ = vk::raii::PipelineLayout(context.device(), vk::PipelineLayoutCreateInfo{
                                                                     .setLayoutCount = 1,
                                                                     .pSetLayouts = &*setLayout_,
                                                                     .pushConstantRangeCount = 1,
                                                                     .pPushConstantRanges = &push});
    const auto resolve = gpu::createShaderModule(context, kResolveCompSpirv);
    resolvePipeline_ = gpu::createComputePipeline(context, resolve, pipelineLayout_);
    const auto sphereVert = gpu::createShaderModule(context, kSphereVertSpirv);
    const auto sphereFrag = gpu::createShaderModule(context, kSphereFragSpirv);
    const auto groundVert = gpu::createShaderModule(context, kGroundVertSpirv);
    const auto groundFrag = gpu::createShaderModule(context, kGroundFragSpirv);
    gpu::GraphicsPipelineInfo sphereInfo{
        .vertexShader = &sphereVert,
        .fragmentShader = &sphereFrag,
        .layout = &pipelineLayout_,
        .vertexBindings = {{.binding = 0, .stride = sizeof(glm::vec3), .inputRate = vk::VertexInputRate::eVertex}},
        .vertexAttributes = {{.location = 0, .binding = 0, .format = vk::Format::eR32G32B32Sfloat, .offset = 0}},
        .topology = vk::PrimitiveTopology::eTriangleList,
        .cullMode = vk::CullModeFlagBits::eBack,
        .depthWrite = true,
        .colorFormat = info.colorFormat,
        .depthFormat = info.depthFormat,
        .samples = info.samples};
    spherePipeline_ = gpu::createGraphicsPipeline(context, sphereInfo);
    gpu::GraphicsPipelineInfo groundInfo{.vertexShader = &groundVert, .fragmentShader = &groundFrag, .layout = &pipelineLayout_,
                                         .vertexBindings = {}, .vertexAttributes = {}, .topology = vk::PrimitiveTopology::eTriangleList,
                                         .cullMode = vk::CullModeFlagBits::eNone, .depthWrite = true, .colorFormat = info.colorFormat,
                                         .depthFormat = info.depthFormat, .samples = info.samples};
    groundPipeline_ = gpu::createGraphicsPipeline(context, groundInfo);

    const vk::DescriptorPoolSize sizes[] = {{vk::DescriptorType::eStorageBuffer, 5 * info.framesInFlight},
                                            {vk::DescriptorType::eUniformBuffer, info.framesInFlight}};
    descriptorPool_ = vk::raii::DescriptorPool(context.device(), vk::DescriptorPoolCreateInfo{
                                                                     .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                                     .maxSets = info.framesInFlight,
                                                                     .poolSizeCount = 2,
                                                                     .pPoolSizes = sizes});
    const std::uint64_t characters = std::max(info.maxCharacters, 1U);
    for (std::uint32_t f = 0; f < info.framesInFlight; ++f) {
        FrameResources frame;
        frame.characters = gpu::Buffer(context, {.size = characters * sizeof(crowd::CharacterState),
                                                 .usage = vk::BufferUsageFlagBits::eStorageBuffer,
                                                 .intent = gpu::MemoryIntent::HostUpload});
        frame.scene = gpu::Buffer(context, {.size = sizeof(SceneUniforms), .usage = vk::BufferUsageFlagBits::eUniformBuffer,
                                            .intent = gpu::MemoryIntent::HostUpload});
        frame.instances = gpu::Buffer(context, {.size = characters * jointsPerCharacter_ * sizeof(InstanceGpu),
                                                .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc});
        vk::raii::DescriptorSets sets(context.device(), vk::DescriptorSetAllocateInfo{
                                                            .descriptorPool = *descriptorPool_, .descriptorSetCount = 1,
                                                            .pSetLayouts = &*setLayout_});
        frame.descriptors = std::move(sets.front());
        const gpu::BufferBinding writes[] = {{0, vk::DescriptorType::eStorageBuffer, palette.poses().handle()},
                                             {1, vk::DescriptorType::eStorageBuffer, palette.clips().handle()},
                                             {2, vk::DescriptorType::eStorageBuffer, palette.jointRadii().handle()},
                                             {3, vk::DescriptorType::eStorageBuffer, frame.characters.handle()},
                                             {4, vk::DescriptorType::eStorageBuffer, frame.instances.handle()},
                                             {5, vk::DescriptorType::eUniformBuffer, frame.scene.handle()}};
        gpu::writeDescriptorSet(context, *frame.descriptors, writes);
        frames_.push_back(std::move(frame));
    }
}

void CrowdRenderer::update(std::uint32_t frame, std::span<const crowd::CharacterState> characters, const SceneUniforms& scene) {
    if (characters.size() > maxCharacters_)
        throw ThrongException(Error{Error::Kind::BadInput, "more characters than the renderer was created for", {}});
    FrameResources& resources = frames_[frame];
    resources.characters.write(std::as_bytes(characters));
    resources.scene.write(std::as_bytes(std::span(&scene, 1)));
    resources.characterCount = static_cast<std::uint32_t>(characters.size());
}

void CrowdRenderer::recordCompute(const vk::raii::CommandBuffer& commands, std::uint32_t frame) const {
    const FrameResources& resources = frames_[frame];
    const std::uint32_t instances = resources.characterCount * jointsPerCharacter_;
    commands.bindPipeline(vk::PipelineBindPoint::eCompute, *resolvePipeline_);
    commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipelineLayout_, 0, *resources.descriptors, {});
    const ResolvePush push{resources.characterCount, jointsPerCharacter_};
    commands.pushConstants<ResolvePush>(*pipelineLayout_, vk::ShaderStageFlagBits::eCompute, 0, push);
    commands.dispatch((instances + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
    // The vertex shader reads what the compute pass just wrote: make the shader writes
    // available and visible to vertex-stage storage reads before any draw starts. (Transfer
    // reads cover --dump-instances, which copies the same buffer out.)
    const vk::BufferMemoryBarrier2 resolved{
        .srcStageMask = vk::PipelineStageFlagBits2::eComputeShader,
        .srcAccessMask = vk::AccessFlagBits2::eShaderStorageWrite,
        .dstStageMask = vk::PipelineStageFlagBits2::eVertexShader | vk::PipelineStageFlagBits2::eCopy,
        .dstAccessMask = vk::AccessFlagBits2::eShaderStorageRead | vk::AccessFlagBits2::eTransferRead,
        .buffer = resources.instances.handle(),
        .offset = 0,
        .size = VK_WHOLE_SIZE};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &resolved});
}

void CrowdRenderer::recordDraw(const vk::raii::CommandBuffer& commands, std::uint32_t frame, vk::Extent2D extent) const {
    const FrameResources& resources = frames_[frame];
    commands.setViewport(0, vk::Viewport{0.0F, 0.0F, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0F, 1.0F});
    commands.setScissor(0, vk::Rect2D{{0, 0}, extent});
    commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelineLayout_, 0, *resources.descriptors, {});
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *groundPipeline_);
    commands.draw(6, 1, 0, 0);
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *spherePipeline_);
    commands.bindVertexBuffers(0, sphereVertices_.handle(), vk::DeviceSize{0});
    commands.bindIndexBuffer(sphereIndices_.handle(), 0, vk::IndexType::eUint16);
    commands.drawIndexed(sphereIndexCount_, resources.characterCount * jointsPerCharacter_, 0, 0, 0);
}

}  // namespace throng::render
