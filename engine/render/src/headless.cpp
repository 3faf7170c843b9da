#include "throng/render/headless.h"

#include <chrono>
#include <cstring>

namespace throng::render {
namespace {

constexpr vk::Format kColorFormat = vk::Format::eR8G8B8A8Srgb;  // linear shading, sRGB-encoded output
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

void transition(const vk::raii::CommandBuffer& commands, vk::Image image, vk::ImageAspectFlags aspect,
                vk::ImageLayout from, vk::ImageLayout to, vk::PipelineStageFlags2 srcStage, vk::AccessFlags2 srcAccess,
                vk::PipelineStageFlags2 dstStage, vk::AccessFlags2 dstAccess) {
    const vk::ImageMemoryBarrier2 barrier{.srcStageMask = srcStage, .srcAccessMask = srcAccess, .dstStageMask = dstStage,
                                          .dstAccessMask = dstAccess, .oldLayout = from, .newLayout = to, .image = image,
                                          .subresourceRange = {aspect, 0, 1, 0, 1}};
    commands.pipelineBarrier2(vk::DependencyInfo{.imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &barrier});
}

}  // namespace

glm::vec3 skyColor() { return {0.62F, 0.70F, 0.78F}; }

SceneUniforms makeScene(const Camera& camera, float aspect, float groundHalfExtent) {
    SceneUniforms scene;
    scene.viewProjection = camera.viewProjection(aspect);
    scene.cameraPosition = glm::vec4(camera.eye, 1.0F);
    scene.lightDirection = glm::vec4(glm::normalize(glm::vec3(-0.45F, 0.8F, -0.35F)), 0.0F);
    scene.lightColor = glm::vec4(0.95F, 0.9F, 0.82F, 0.0F);
    scene.skyColor = glm::vec4(0.32F, 0.36F, 0.42F, 0.0F);
    scene.bounceColor = glm::vec4(0.12F, 0.11F, 0.10F, 0.0F);
    const float distance = glm::length(camera.eye - camera.target);
    scene.groundParams = glm::vec4(groundHalfExtent, 2.0F, distance * 1.6F + 20.0F, distance * 3.5F + 60.0F);
    scene.fogColor = glm::vec4(skyColor(), 0.0F);
    return scene;
}

HeadlessFrame renderHeadless(const gpu::Context& context, const Palette& palette,
                             std::span<const crowd::CharacterState> characters, const SceneUniforms& scene,
                             const HeadlessOptions& options) {
    using Clock = std::chrono::steady_clock;
    const auto setupStart = Clock::now();
    const vk::SampleCountFlagBits samples = context.sampleCount(options.msaa);
    const vk::Extent2D extent{options.width, options.height};
    CrowdRenderer renderer(context, palette,
                           {.colorFormat = kColorFormat, .depthFormat = kDepthFormat, .samples = samples, .framesInFlight = 1,
                            .maxCharacters = static_cast<std::uint32_t>(characters.size())});

    using Usage = vk::ImageUsageFlagBits;
    const bool multisampled = samples != vk::SampleCountFlagBits::e1;
    gpu::Image resolved(context, {.extent = extent, .format = kColorFormat, .usage = Usage::eColorAttachment | Usage::eTransferSrc});
    gpu::Image msaaColor;
    if (multisampled)
        msaaColor = gpu::Image(context, {.extent = extent, .format = kColorFormat,
                                         .usage = Usage::eColorAttachment | Usage::eTransientAttachment, .samples = samples});
    gpu::Image depth(context, {.extent = extent, .format = kDepthFormat, .usage = Usage::eDepthStencilAttachment,
                               .samples = samples, .aspect = vk::ImageAspectFlagBits::eDepth});
    // Rows in the readback buffer start every `rowTexels` texels, not every `width`: the copy
    // is told the pitch, and the PNG writer reads with the same stride.
    const std::uint32_t rowTexels = (options.width + 63U) / 64U * 64U;
    const std::size_t rowBytes = std::size_t{rowTexels} * 4;
    gpu::Buffer readback(context, {.size = rowBytes * options.height, .usage = vk::BufferUsageFlagBits::eTransferDst,
                                   .intent = gpu::MemoryIntent::Readback});
    const std::size_t instanceBytes = characters.size() * renderer.jointsPerCharacter() * sizeof(InstanceGpu);
    gpu::Buffer instanceReadback;
    if (options.readInstances && instanceBytes > 0)
        instanceReadback = gpu::Buffer(context, {.size = instanceBytes, .usage = vk::BufferUsageFlagBits::eTransferDst,
                                                 .intent = gpu::MemoryIntent::Readback});

    const auto frameStart = Clock::now();
    renderer.update(0, characters, scene);
    gpu::immediateSubmit(context, [&](const vk::raii::CommandBuffer& commands) {
        renderer.recordCompute(commands, 0);
        using Stage = vk::PipelineStageFlagBits2;
        using Access = vk::AccessFlagBits2;
        const vk::Image target = multisampled ? msaaColor.handle() : resolved.handle();
        transition(commands, target, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined,
                   vk::ImageLayout::eColorAttachmentOptimal, Stage::eNone, Access::eNone, Stage::eColorAttachmentOutput,
                   Access::eColorAttachmentWrite);
        if (multisampled)
            transition(commands, resolved.handle(), vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined,
                       vk::ImageLayout::eColorAttachmentOptimal, Stage::eNone, Access::eNone, Stage::eColorAttachmentOutput,
                       Access::eColorAttachmentWrite);
        transition(commands, depth.handle(), vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
                   vk::ImageLayout::eDepthAttachmentOptimal, Stage::eNone, Access::eNone,
                   Stage::eEarlyFragmentTests | Stage::eLateFragmentTests, Access::eDepthStencilAttachmentWrite);
        const glm::vec3 sky = skyColor();
        vk::RenderingAttachmentInfo color{.imageView = multisampled ? msaaColor.view() : resolved.view(),
                                          .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
                                          .loadOp = vk::AttachmentLoadOp::eClear,
                                          .storeOp = multisampled ? vk::AttachmentStoreOp::eDontCare : vk::AttachmentStoreOp::eStore,
                                          .clearValue = vk::ClearColorValue(std::array<float, 4>{sky.r, sky.g, sky.b, 1.0F})};
        if (multisampled) {
            color.resolveMode = vk::ResolveModeFlagBits::eAverage;
            color.resolveImageView = resolved.view();
            color.resolveImageLayout = vk::ImageLayout::eColorAttachmentOptimal;
        }
        const vk::RenderingAttachmentInfo depthAttachment{.imageView = depth.view(),
                                                          .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
                                                          .loadOp = vk::AttachmentLoadOp::eClear,
                                                          .storeOp = vk::AttachmentStoreOp::eDontCare,
                                                          .clearValue = vk::ClearDepthStencilValue{1.0F, 0}};
        commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent}, .layerCount = 1, .colorAttachmentCount = 1,
                                                  .pColorAttachments = &color, .pDepthAttachment = &depthAttachment});
        renderer.recordDraw(commands, 0, extent);
        commands.endRendering();
        transition(commands, resolved.handle(), vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal,
                   vk::ImageLayout::eTransferSrcOptimal, Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite,
                   Stage::eCopy, Access::eTransferRead);
        commands.copyImageToBuffer(resolved.handle(), vk::ImageLayout::eTransferSrcOptimal, readback.handle(),
                                   vk::BufferImageCopy{.bufferRowLength = rowTexels,
                                                       .imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                                       .imageExtent = {options.width, options.height, 1}});
        if (instanceReadback.size() > 0)
            commands.copyBuffer(renderer.instances(0).handle(), instanceReadback.handle(), vk::BufferCopy{.size = instanceBytes});
        // The host reads both copies after the fence.
        const vk::MemoryBarrier2 toHost{.srcStageMask = Stage::eCopy, .srcAccessMask = Access::eTransferWrite,
                                        .dstStageMask = Stage::eHost, .dstAccessMask = Access::eHostRead};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
    });

    const auto frameEnd = Clock::now();
    HeadlessFrame frame;
    frame.setupMilliseconds = std::chrono::duration<double, std::milli>(frameStart - setupStart).count();
    frame.frameMilliseconds = std::chrono::duration<double, std::milli>(frameEnd - frameStart).count();
    frame.width = options.width;
    frame.height = options.height;
    frame.samples = static_cast<std::uint32_t>(samples);
    readback.invalidate();
    frame.rgba.resize(std::size_t{options.width} * options.height * 4);
    for (std::uint32_t y = 0; y < options.height; ++y)
        std::memcpy(frame.rgba.data() + std::size_t{y} * options.width * 4, readback.mapped() + y * rowBytes,
                    std::size_t{options.width} * 4);
    if (instanceReadback.size() > 0) {
        instanceReadback.invalidate();
        frame.instances.resize(instanceBytes / sizeof(InstanceGpu));
        std::memcpy(frame.instances.data(), instanceReadback.mapped(), instanceBytes);
    }
    return frame;
}

}  // namespace throng::render
