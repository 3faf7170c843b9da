#include "throng/render/crowd_renderer.h"

#include <cstring>

#include "throng/render/bindings.h"
#include "throng/shaders/ground_frag.h"
#include "throng/shaders/ground_vert.h"
#include "throng/shaders/impostor_frag.h"
#include "throng/shaders/impostor_vert.h"
#include "throng/shaders/resolve_comp.h"
#include "throng/shaders/resolve_cull_comp.h"
#include "throng/shaders/sphere_frag.h"
#include "throng/shaders/sphere_paper_vert.h"
#include "throng/shaders/sphere_vert.h"

namespace throng::render {
namespace {

constexpr std::uint32_t kWorkgroupSize = 64;  // local_size_x of both compute shaders

}  // namespace

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& m) {
    const auto row = [&](int i) { return glm::vec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    // Gribb and Hartmann: clip-space inequalities -w <= x, y <= w and 0 <= z <= w as planes.
    std::array<glm::vec4, 6> planes{row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(2), row(3) - row(2)};
    for (glm::vec4& p : planes) p /= glm::length(glm::vec3(p));
    return planes;
}

void resolveInstancesOnCpu(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> characters,
                           std::uint32_t jointsPerCharacter, std::span<InstanceGpu> out) {
    for (std::size_t m = 0; m < characters.size(); ++m) {
        const crowd::CharacterState& c = characters[m];
        const motion::BakedClip& clip = clips[c.clip];
        const glm::vec4 color(glm::unpackUnorm4x8(c.color));
        for (std::uint32_t j = 0; j < jointsPerCharacter; ++j) {
            InstanceGpu& instance = out[m * jointsPerCharacter + j];
            if (j >= static_cast<std::uint32_t>(clip.jointCount())) {
                instance = {glm::vec4(0.0F), glm::vec4(0, 0, 0, 1), glm::vec4(0.0F)};
                continue;
            }
            const crowd::JointWorld joint = crowd::sampleJointWorld(clip, c, static_cast<int>(j));
            instance = {glm::vec4(joint.position, joint.radius),
                        glm::vec4(joint.orientation.x, joint.orientation.y, joint.orientation.z, joint.orientation.w),
                        glm::vec4(glm::vec3(color), 1.0F)};
        }
    }
}

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
    : context_(&context), path_(info.path), cullRadius_(0.8F * palette.maxHeight()), cullHeight_(0.5F * palette.maxHeight()),
      lodPixels_(info.lodPixels),
      jointsPerCharacter_(palette.jointsPerCharacter()), maxCharacters_(info.maxCharacters) {
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
    // One layout for every path keeps the descriptor plumbing single; unused bindings cost nothing.
    // Every binding is visible to every stage because every shader declares every buffer
    // (shaders/bindings.glsl); those that compute writes are readonly outside compute.
    const auto storage = vk::DescriptorType::eStorageBuffer;
    const gpu::DescriptorBinding bindings[] = {
        {bindingIndex(Binding::Poses), storage, all},          {bindingIndex(Binding::Clips), storage, all},
        {bindingIndex(Binding::JointRadii), storage, all},     {bindingIndex(Binding::Characters), storage, all},
        {bindingIndex(Binding::Instances), storage, all},      {bindingIndex(Binding::SceneUniforms), vk::DescriptorType::eUniformBuffer, all},
        {bindingIndex(Binding::DrawArguments), storage, all},  {bindingIndex(Binding::InstanceOwners), storage, all},
        {bindingIndex(Binding::JointDetail), storage, all}};
    setLayout_ = gpu::createDescriptorSetLayout(context, bindings);
    const vk::PushConstantRange push{.stageFlags = all, .offset = 0, .size = sizeof(PushConstants)};
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
    if (path_ == RenderPath::Paper) {
        const auto paperVert = gpu::createShaderModule(context, kSpherePaperVertSpirv);
        sphereInfo.vertexShader = &paperVert;
        paperPipeline_ = gpu::createGraphicsPipeline(context, sphereInfo);
    }
    if (path_ == RenderPath::Fast) {
        const auto cull = gpu::createShaderModule(context, kResolveCullCompSpirv);
        cullPipeline_ = gpu::createComputePipeline(context, cull, pipelineLayout_);
        const auto impostorVert = gpu::createShaderModule(context, kImpostorVertSpirv);
        const auto impostorFrag = gpu::createShaderModule(context, kImpostorFragSpirv);
        gpu::GraphicsPipelineInfo impostorInfo{.vertexShader = &impostorVert, .fragmentShader = &impostorFrag,
                                               .layout = &pipelineLayout_, .vertexBindings = {}, .vertexAttributes = {},
                                               .topology = vk::PrimitiveTopology::ePointList,
                                               .cullMode = vk::CullModeFlagBits::eNone, .depthWrite = true,
                                               .colorFormat = info.colorFormat, .depthFormat = info.depthFormat,
                                               .samples = info.samples, .alphaToCoverage = info.samples != vk::SampleCountFlagBits::e1};
        impostorPipeline_ = gpu::createGraphicsPipeline(context, impostorInfo);
    }

    const vk::DescriptorPoolSize sizes[] = {{vk::DescriptorType::eStorageBuffer, 8 * info.framesInFlight},
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
                                                .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc,
                                                .intent = path_ == RenderPath::Cpu ? gpu::MemoryIntent::HostUpload
                                                                                   : gpu::MemoryIntent::DeviceLocal});
        const std::uint64_t fastEntries = path_ == RenderPath::Fast ? characters * jointsPerCharacter_ : 1;
        frame.drawArguments = gpu::Buffer(context, {.size = sizeof(DrawArguments),
                                                    .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer |
                                                             vk::BufferUsageFlagBits::eTransferSrc});
        frame.instanceOwners = gpu::Buffer(context, {.size = fastEntries * 2 * sizeof(std::uint32_t),
                                                     .usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc});
        vk::raii::DescriptorSets sets(context.device(), vk::DescriptorSetAllocateInfo{
                                                            .descriptorPool = *descriptorPool_, .descriptorSetCount = 1,
                                                            .pSetLayouts = &*setLayout_});
        frame.descriptors = std::move(sets.front());
        const gpu::BufferBinding writes[] = {
            {bindingIndex(Binding::Poses), vk::DescriptorType::eStorageBuffer, palette.poses().handle()},
            {bindingIndex(Binding::Clips), vk::DescriptorType::eStorageBuffer, palette.clips().handle()},
            {bindingIndex(Binding::JointRadii), vk::DescriptorType::eStorageBuffer, palette.jointRadii().handle()},
            {bindingIndex(Binding::Characters), vk::DescriptorType::eStorageBuffer, frame.characters.handle()},
            {bindingIndex(Binding::Instances), vk::DescriptorType::eStorageBuffer, frame.instances.handle()},
            {bindingIndex(Binding::SceneUniforms), vk::DescriptorType::eUniformBuffer, frame.scene.handle()},
            {bindingIndex(Binding::DrawArguments), vk::DescriptorType::eStorageBuffer, frame.drawArguments.handle()},
            {bindingIndex(Binding::InstanceOwners), vk::DescriptorType::eStorageBuffer, frame.instanceOwners.handle()},
            {bindingIndex(Binding::JointDetail), vk::DescriptorType::eStorageBuffer, palette.jointDetail().handle()}};
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
    resources.push = {resources.characterCount, jointsPerCharacter_, cullRadius_, cullHeight_, {}, lodPixels_, {}};
    const std::array<glm::vec4, 6> planes = frustumPlanes(scene.viewProjection);
    std::copy(planes.begin(), planes.end(), resources.push.frustum);
}

void CrowdRenderer::uploadInstances(std::uint32_t frame, std::span<const InstanceGpu> instances) {
    if (path_ != RenderPath::Cpu) throw ThrongException(Error{Error::Kind::Runtime, "uploadInstances() is for the cpu path", {}});
    frames_[frame].instances.write(std::as_bytes(instances));
}

void CrowdRenderer::recordCompute(const vk::raii::CommandBuffer& commands, std::uint32_t frame) const {
    const FrameResources& resources = frames_[frame];
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    if (path_ == RenderPath::Paper || path_ == RenderPath::Cpu) return;  // no compute pass: the host or the vertex shader resolves
    commands.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *pipelineLayout_, 0, *resources.descriptors, {});
    commands.pushConstants<PushConstants>(*pipelineLayout_, vk::ShaderStageFlagBits::eCompute | vk::ShaderStageFlagBits::eVertex |
                                                                 vk::ShaderStageFlagBits::eFragment, 0, resources.push);
    if (path_ == RenderPath::Compute) {
        commands.bindPipeline(vk::PipelineBindPoint::eCompute, *resolvePipeline_);
        const std::uint32_t instances = resources.characterCount * jointsPerCharacter_;
        commands.dispatch((instances + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
        // The vertex shader reads what the compute pass just wrote: make the shader writes
        // available and visible to vertex-stage storage reads before any draw starts. (Transfer
        // reads cover --dump-instances, which copies the same buffer out.)
        const vk::BufferMemoryBarrier2 resolved{.srcStageMask = Stage::eComputeShader, .srcAccessMask = Access::eShaderStorageWrite,
                                                .dstStageMask = Stage::eVertexShader | Stage::eCopy,
                                                .dstAccessMask = Access::eShaderStorageRead | Access::eTransferRead,
                                                .buffer = resources.instances.handle(), .offset = 0, .size = VK_WHOLE_SIZE};
        commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &resolved});
        return;
    }
    // Fast path: reset the draw's counter (the previous frame's indirect read must finish first),
    // cull and compact, then hand the arguments to the indirect draw and the joints to the vertex shader.
    const vk::BufferMemoryBarrier2 previous{.srcStageMask = Stage::eDrawIndirect, .srcAccessMask = Access::eIndirectCommandRead,
                                            .dstStageMask = Stage::eCopy, .dstAccessMask = Access::eTransferWrite,
                                            .buffer = resources.drawArguments.handle(), .offset = 0, .size = VK_WHOLE_SIZE};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &previous});
    commands.updateBuffer<DrawArguments>(resources.drawArguments.handle(), 0, DrawArguments{});
    const vk::BufferMemoryBarrier2 reset{.srcStageMask = Stage::eCopy, .srcAccessMask = Access::eTransferWrite,
                                         .dstStageMask = Stage::eComputeShader,
                                         .dstAccessMask = Access::eShaderStorageRead | Access::eShaderStorageWrite,
                                         .buffer = resources.drawArguments.handle(), .offset = 0, .size = VK_WHOLE_SIZE};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &reset});
    commands.bindPipeline(vk::PipelineBindPoint::eCompute, *cullPipeline_);
    commands.dispatch((resources.characterCount + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
    const std::array<vk::BufferMemoryBarrier2, 3> culled{
        vk::BufferMemoryBarrier2{.srcStageMask = Stage::eComputeShader, .srcAccessMask = Access::eShaderStorageWrite,
                                 .dstStageMask = Stage::eDrawIndirect | Stage::eCopy,
                                 .dstAccessMask = Access::eIndirectCommandRead | Access::eTransferRead,
                                 .buffer = resources.drawArguments.handle(), .offset = 0, .size = VK_WHOLE_SIZE},
        vk::BufferMemoryBarrier2{.srcStageMask = Stage::eComputeShader, .srcAccessMask = Access::eShaderStorageWrite,
                                 .dstStageMask = Stage::eVertexShader | Stage::eCopy,
                                 .dstAccessMask = Access::eShaderStorageRead | Access::eTransferRead,
                                 .buffer = resources.instances.handle(), .offset = 0, .size = VK_WHOLE_SIZE},
        vk::BufferMemoryBarrier2{.srcStageMask = Stage::eComputeShader, .srcAccessMask = Access::eShaderStorageWrite,
                                 .dstStageMask = Stage::eCopy, .dstAccessMask = Access::eTransferRead,
                                 .buffer = resources.instanceOwners.handle(), .offset = 0, .size = VK_WHOLE_SIZE}};
    commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 3, .pBufferMemoryBarriers = culled.data()});
}

void CrowdRenderer::recordDraw(const vk::raii::CommandBuffer& commands, std::uint32_t frame, vk::Extent2D extent) const {
    const FrameResources& resources = frames_[frame];
    commands.setViewport(0, vk::Viewport{0.0F, 0.0F, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0F, 1.0F});
    commands.setScissor(0, vk::Rect2D{{0, 0}, extent});
    commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelineLayout_, 0, *resources.descriptors, {});
    commands.pushConstants<PushConstants>(*pipelineLayout_, vk::ShaderStageFlagBits::eCompute | vk::ShaderStageFlagBits::eVertex |
                                                                 vk::ShaderStageFlagBits::eFragment, 0, resources.push);
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *groundPipeline_);
    commands.draw(6, 1, 0, 0);
    if (path_ == RenderPath::Fast) {
        commands.bindPipeline(vk::PipelineBindPoint::eGraphics, *impostorPipeline_);
        commands.drawIndirect(resources.drawArguments.handle(), 0, 1, sizeof(DrawArguments));
        return;
    }
    commands.bindPipeline(vk::PipelineBindPoint::eGraphics, path_ == RenderPath::Paper ? *paperPipeline_ : *spherePipeline_);
    commands.bindVertexBuffers(0, sphereVertices_.handle(), vk::DeviceSize{0});
    commands.bindIndexBuffer(sphereIndices_.handle(), 0, vk::IndexType::eUint16);
    commands.drawIndexed(sphereIndexCount_, resources.characterCount * jointsPerCharacter_, 0, 0, 0);
}

}  // namespace throng::render
