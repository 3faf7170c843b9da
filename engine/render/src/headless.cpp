#include "throng/gpu/barriers.h"
#include "throng/render/headless.h"

#include <chrono>
#include <cstring>

namespace throng::render {
namespace {

constexpr vk::Format kColorFormat = vk::Format::eR8G8B8A8Srgb;  // linear shading, sRGB-encoded output
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;


}  // namespace

glm::vec3 skyColor() { return {0.62F, 0.70F, 0.78F}; }

SceneUniforms makeScene(const Camera& camera, vk::Extent2D viewport, float groundHalfExtent) {
    SceneUniforms scene;
    const float width = static_cast<float>(viewport.width), height = static_cast<float>(std::max(viewport.height, 1U));
    scene.viewProjection = camera.viewProjection(width / height);
    scene.inverseViewProjection = glm::inverse(scene.viewProjection);
    const float focal = 0.5F * height / std::tan(glm::radians(camera.verticalFovDegrees) * 0.5F);
    scene.viewport = glm::vec4(width, height, focal, 255.0F);
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

struct OffscreenRenderer::Targets {
    gpu::Image resolved, msaaColor, depth;
    gpu::Buffer readback;
    std::uint32_t rowTexels = 0;
    vk::raii::CommandPool pool{nullptr};
    vk::raii::CommandBuffer commands{nullptr};
    vk::raii::Fence done{nullptr};
    vk::raii::QueryPool timestamps{nullptr};
};

OffscreenRenderer::OffscreenRenderer(const gpu::Context& context, const Palette& palette, std::span<const motion::BakedClip> clips,
                                     std::uint32_t maxCharacters, const HeadlessOptions& options)
    : context_(&context), clips_(clips), options_(options), samples_(context.sampleCount(options.msaa)),
      renderer_(context, palette, {.path = options.path, .colorFormat = kColorFormat, .depthFormat = kDepthFormat, .samples = samples_,
                                   .framesInFlight = 1, .maxCharacters = std::max(maxCharacters, 1U), .sphereSegments = 12,
                                   .sphereRings = 8, .lodPixels = options.lodPixels}),
      targets_(std::make_unique<Targets>()) {
    using Usage = vk::ImageUsageFlagBits;
    const vk::Extent2D extent{options.width, options.height};
    Targets& t = *targets_;
    t.resolved = gpu::Image(context, {.extent = extent, .format = kColorFormat, .usage = Usage::eColorAttachment | Usage::eTransferSrc});
    if (samples_ != vk::SampleCountFlagBits::e1)
        t.msaaColor = gpu::Image(context, {.extent = extent, .format = kColorFormat,
                                           .usage = Usage::eColorAttachment | Usage::eTransientAttachment, .samples = samples_});
    t.depth = gpu::Image(context, {.extent = extent, .format = kDepthFormat, .usage = Usage::eDepthStencilAttachment,
                                   .samples = samples_, .aspect = vk::ImageAspectFlagBits::eDepth});
    // Rows in the readback buffer start every `rowTexels` texels, not every `width`: the copy
    // is told the pitch, and pixels() reads with the same stride.
    t.rowTexels = (options.width + 63U) / 64U * 64U;
    t.readback = gpu::Buffer(context, {.size = std::size_t{t.rowTexels} * 4 * options.height,
                                       .usage = vk::BufferUsageFlagBits::eTransferDst, .intent = gpu::MemoryIntent::Readback});
    t.pool = vk::raii::CommandPool(context.device(), vk::CommandPoolCreateInfo{.flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                                               .queueFamilyIndex = context.queueFamily()});
    t.commands = std::move(vk::raii::CommandBuffers(context.device(), vk::CommandBufferAllocateInfo{
                                                                          .commandPool = *t.pool, .level = vk::CommandBufferLevel::ePrimary,
                                                                          .commandBufferCount = 1}).front());
    t.done = vk::raii::Fence(context.device(), vk::FenceCreateInfo{});
    if (context.limits().timestampComputeAndGraphics)
        t.timestamps = vk::raii::QueryPool(context.device(), vk::QueryPoolCreateInfo{.queryType = vk::QueryType::eTimestamp, .queryCount = 3});
}

OffscreenRenderer::~OffscreenRenderer() { context_->device().waitIdle(); }

FrameTimings OffscreenRenderer::render(std::span<const crowd::CharacterState> characters, const SceneUniforms& scene) {
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
    FrameTimings timings;
    Targets& t = *targets_;
    const auto frameStart = Clock::now();
    renderer_.update(0, characters, scene);
    if (options_.path == RenderPath::Cpu) {
        cpuInstances_.resize(characters.size() * renderer_.jointsPerCharacter());
        resolveInstancesOnCpu(clips_, characters, renderer_.jointsPerCharacter(), cpuInstances_);
        renderer_.uploadInstances(0, cpuInstances_);
    }
    lastCharacters_ = static_cast<std::uint32_t>(characters.size());
    timings.uploadMs = ms(Clock::now() - frameStart);

    const vk::Extent2D extent{options_.width, options_.height};
    const bool multisampled = samples_ != vk::SampleCountFlagBits::e1;
    const vk::raii::CommandBuffer& commands = t.commands;
    commands.reset();
    commands.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    if (*t.timestamps) {
        commands.resetQueryPool(*t.timestamps, 0, 3);
        commands.writeTimestamp2(Stage::eTopOfPipe, *t.timestamps, 0);
    }
    renderer_.recordCompute(commands, 0);
    if (*t.timestamps) commands.writeTimestamp2(Stage::eComputeShader, *t.timestamps, 1);
    // Earlier frames wrote these images (and the copy read one): order after them, discard contents.
    const vk::Image target = multisampled ? t.msaaColor.handle() : t.resolved.handle();
    gpu::transitionImage(commands, target, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined, vk::ImageLayout::eColorAttachmentOptimal,
               Stage::eColorAttachmentOutput | Stage::eCopy, Access::eColorAttachmentWrite, Stage::eColorAttachmentOutput,
               Access::eColorAttachmentWrite);
    if (multisampled)
        gpu::transitionImage(commands, t.resolved.handle(), vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined,
                   vk::ImageLayout::eColorAttachmentOptimal, Stage::eCopy, Access::eNone, Stage::eColorAttachmentOutput,
                   Access::eColorAttachmentWrite);
    gpu::transitionImage(commands, t.depth.handle(), vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
               vk::ImageLayout::eDepthAttachmentOptimal, Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
               Access::eDepthStencilAttachmentWrite, Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
               Access::eDepthStencilAttachmentWrite | Access::eDepthStencilAttachmentRead);
    const glm::vec3 sky = skyColor();
    vk::RenderingAttachmentInfo color{.imageView = multisampled ? t.msaaColor.view() : t.resolved.view(),
                                      .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
                                      .loadOp = vk::AttachmentLoadOp::eClear,
                                      .storeOp = multisampled ? vk::AttachmentStoreOp::eDontCare : vk::AttachmentStoreOp::eStore,
                                      .clearValue = vk::ClearColorValue(std::array<float, 4>{sky.r, sky.g, sky.b, 1.0F})};
    if (multisampled) {
        color.resolveMode = vk::ResolveModeFlagBits::eAverage;
        color.resolveImageView = t.resolved.view();
        color.resolveImageLayout = vk::ImageLayout::eColorAttachmentOptimal;
    }
    const vk::RenderingAttachmentInfo depthAttachment{.imageView = t.depth.view(), .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
                                                      .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eDontCare,
                                                      .clearValue = vk::ClearDepthStencilValue{1.0F, 0}};
    commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent}, .layerCount = 1, .colorAttachmentCount = 1,
                                              .pColorAttachments = &color, .pDepthAttachment = &depthAttachment});
    renderer_.recordDraw(commands, 0, extent);
    commands.endRendering();
    if (*t.timestamps) commands.writeTimestamp2(Stage::eColorAttachmentOutput, *t.timestamps, 2);
    gpu::transitionImage(commands, t.resolved.handle(), vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal,
               vk::ImageLayout::eTransferSrcOptimal, Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite, Stage::eCopy,
               Access::eTransferRead);
    // The previous frame's host read of the readback buffer finished at its fence.
    commands.copyImageToBuffer(t.resolved.handle(), vk::ImageLayout::eTransferSrcOptimal, t.readback.handle(),
                               vk::BufferImageCopy{.bufferRowLength = t.rowTexels,
                                                   .imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                                   .imageExtent = {options_.width, options_.height, 1}});
    const vk::MemoryBarrier2 toHost{.srcStageMask = Stage::eCopy, .srcAccessMask = Access::eTransferWrite,
                                    .dstStageMask = Stage::eHost, .dstAccessMask = Access::eHostRead};
    commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
    commands.end();
    context_->device().resetFences(*t.done);
    const vk::CommandBufferSubmitInfo commandInfo{.commandBuffer = *commands};
    context_->queue().submit2(vk::SubmitInfo2{.commandBufferInfoCount = 1, .pCommandBufferInfos = &commandInfo}, *t.done);
    THRONG_VK_CHECK(context_->device().waitForFences(*t.done, VK_TRUE, UINT64_MAX));
    const auto readStart = Clock::now();
    t.readback.invalidate();
    timings.readbackMs = ms(Clock::now() - readStart);
    if (*t.timestamps) {
        std::array<std::uint64_t, 3> ticks{};
        if ((*context_->device()).getQueryPoolResults(*t.timestamps, 0, 3, sizeof(ticks), ticks.data(), sizeof(std::uint64_t),
                                                      vk::QueryResultFlagBits::e64) == vk::Result::eSuccess) {
            const double msPerTick = static_cast<double>(context_->limits().timestampPeriod) * 1e-6;
            timings.computeMs = static_cast<double>(ticks[1] - ticks[0]) * msPerTick;
            timings.drawMs = static_cast<double>(ticks[2] - ticks[1]) * msPerTick;
        }
    }
    timings.frameMs = ms(Clock::now() - frameStart);
    return timings;
}

std::vector<std::uint8_t> OffscreenRenderer::pixels() const {
    const Targets& t = *targets_;
    std::vector<std::uint8_t> rgba(std::size_t{options_.width} * options_.height * 4);
    for (std::uint32_t y = 0; y < options_.height; ++y)
        std::memcpy(rgba.data() + std::size_t{y} * options_.width * 4, t.readback.mapped() + std::size_t{y} * t.rowTexels * 4,
                    std::size_t{options_.width} * 4);
    return rgba;
}

namespace {
// Copies a device-local buffer's first `bytes` to the host.
std::vector<std::byte> download(const gpu::Context& context, const gpu::Buffer& source, std::size_t bytes) {
    if (bytes == 0) return {};
    gpu::Buffer staging(context, {.size = bytes, .usage = vk::BufferUsageFlagBits::eTransferDst, .intent = gpu::MemoryIntent::Readback});
    gpu::immediateSubmit(context, [&](const vk::raii::CommandBuffer& commands) {
        commands.copyBuffer(source.handle(), staging.handle(), vk::BufferCopy{.size = bytes});
        const vk::MemoryBarrier2 toHost{.srcStageMask = vk::PipelineStageFlagBits2::eCopy, .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                        .dstStageMask = vk::PipelineStageFlagBits2::eHost, .dstAccessMask = vk::AccessFlagBits2::eHostRead};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
    });
    staging.invalidate();
    return {staging.mapped(), staging.mapped() + bytes};
}
}  // namespace

std::size_t OffscreenRenderer::instanceCount() const {
    if (renderer_.path() != RenderPath::Fast) return std::size_t{lastCharacters_} * renderer_.jointsPerCharacter();
    const std::vector<std::byte> arguments = download(*context_, renderer_.drawArguments(0), sizeof(DrawArguments));
    DrawArguments draw;
    std::memcpy(&draw, arguments.data(), sizeof draw);
    return draw.vertexCount;
}

std::vector<InstanceGpu> OffscreenRenderer::instances() const {
    const std::size_t count = instanceCount();
    const std::vector<std::byte> bytes = download(*context_, renderer_.instances(0), count * sizeof(InstanceGpu));
    std::vector<InstanceGpu> out(count);
    if (count > 0) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<glm::uvec2> OffscreenRenderer::instanceOwners() const {
    if (renderer_.path() != RenderPath::Fast) return {};
    const std::size_t count = instanceCount();
    const std::vector<std::byte> bytes = download(*context_, renderer_.instanceOwners(0), count * sizeof(glm::uvec2));
    std::vector<glm::uvec2> out(count);
    if (count > 0) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

}  // namespace throng::render
