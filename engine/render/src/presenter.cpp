#include "throng/gpu/barriers.h"
#include "throng/render/presenter.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "throng/render/headless.h"
#include "throng/render/png.h"

namespace throng::render {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;


bool isBgr(vk::Format format) { return format == vk::Format::eB8G8R8A8Srgb || format == vk::Format::eB8G8R8A8Unorm; }

}  // namespace

Presenter::Presenter(const gpu::Context& context, const Window& window, const PresenterCreateInfo& info)
    : context_(&context), window_(&window), info_(info), samples_(context.sampleCount(info.msaa)) {
    const auto families = context.physicalDevice().getQueueFamilyProperties();
    timestampsSupported_ = context.limits().timestampComputeAndGraphics && families[context.queueFamily()].timestampValidBits > 0;
    chooseFormatAndMode();
    // The HUD draws over the resolved image: load what the scene left, keep the layout for
    // the barrier that follows (present or screenshot copy).
    const vk::AttachmentDescription attachment{.format = format_,
                                               .samples = vk::SampleCountFlagBits::e1,
                                               .loadOp = vk::AttachmentLoadOp::eLoad,
                                               .storeOp = vk::AttachmentStoreOp::eStore,
                                               .stencilLoadOp = vk::AttachmentLoadOp::eDontCare,
                                               .stencilStoreOp = vk::AttachmentStoreOp::eDontCare,
                                               .initialLayout = vk::ImageLayout::eColorAttachmentOptimal,
                                               .finalLayout = vk::ImageLayout::eColorAttachmentOptimal};
    const vk::AttachmentReference reference{.attachment = 0, .layout = vk::ImageLayout::eColorAttachmentOptimal};
    const vk::SubpassDescription subpass{.pipelineBindPoint = vk::PipelineBindPoint::eGraphics,
                                         .colorAttachmentCount = 1, .pColorAttachments = &reference};
    // The scene's resolve writes the image before the HUD reads and blends onto it.
    const vk::SubpassDependency dependency{.srcSubpass = VK_SUBPASS_EXTERNAL, .dstSubpass = 0,
                                           .srcStageMask = vk::PipelineStageFlagBits::eColorAttachmentOutput,
                                           .dstStageMask = vk::PipelineStageFlagBits::eColorAttachmentOutput,
                                           .srcAccessMask = vk::AccessFlagBits::eColorAttachmentWrite,
                                           .dstAccessMask = vk::AccessFlagBits::eColorAttachmentRead | vk::AccessFlagBits::eColorAttachmentWrite};
    overlayPass_ = vk::raii::RenderPass(context.device(), vk::RenderPassCreateInfo{.attachmentCount = 1, .pAttachments = &attachment,
                                                                                   .subpassCount = 1, .pSubpasses = &subpass,
                                                                                   .dependencyCount = 1, .pDependencies = &dependency});
    createSwapchain();
    recreations_ = 0;
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
        Slot slot;
        slot.pool = vk::raii::CommandPool(context.device(), vk::CommandPoolCreateInfo{
                                                                .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                                .queueFamilyIndex = context.queueFamily()});
        slot.commands = std::move(vk::raii::CommandBuffers(context.device(), vk::CommandBufferAllocateInfo{
                                                                                 .commandPool = *slot.pool,
                                                                                 .level = vk::CommandBufferLevel::ePrimary,
                                                                                 .commandBufferCount = 1})
                                      .front());
        slot.imageAvailable = vk::raii::Semaphore(context.device(), vk::SemaphoreCreateInfo{});
        slot.inFlight = vk::raii::Fence(context.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled});
        if (timestampsSupported_)
            slot.timestamps = vk::raii::QueryPool(context.device(), vk::QueryPoolCreateInfo{.queryType = vk::QueryType::eTimestamp,
                                                                                            .queryCount = 4});
        slots_.push_back(std::move(slot));
    }
}

Presenter::~Presenter() { context_->device().waitIdle(); }

const char* Presenter::presentModeName() const {
    switch (presentMode_) {
        case vk::PresentModeKHR::eFifo: return "FIFO";
        case vk::PresentModeKHR::eMailbox: return "MAILBOX";
        case vk::PresentModeKHR::eImmediate: return "IMMEDIATE";
        default: return "other";
    }
}

void Presenter::chooseFormatAndMode() {
    const gpu::Context& context = *context_;
    const vk::raii::PhysicalDevice& gpu = context.physicalDevice();
    {
        const auto formats = gpu.getSurfaceFormatsKHR(context.surface());
        vk::SurfaceFormatKHR chosen = formats.front();
        for (const vk::SurfaceFormatKHR& f : formats)
            if ((f.format == vk::Format::eB8G8R8A8Srgb || f.format == vk::Format::eR8G8B8A8Srgb) &&
                f.colorSpace == vk::ColorSpaceKHR::eSrgbNonlinear)
                chosen = f;
        format_ = chosen.format;
        colorSpace_ = chosen.colorSpace;
        const auto modes = gpu.getSurfacePresentModesKHR(context.surface());
        const auto has = [&](vk::PresentModeKHR m) { return std::find(modes.begin(), modes.end(), m) != modes.end(); };
        presentMode_ = vk::PresentModeKHR::eFifo;  // always available
        if (!info_.vsync) presentMode_ = has(vk::PresentModeKHR::eMailbox) ? vk::PresentModeKHR::eMailbox
                                         : has(vk::PresentModeKHR::eImmediate) ? vk::PresentModeKHR::eImmediate
                                                                                : vk::PresentModeKHR::eFifo;
    }
}

void Presenter::createSwapchain() {
    const gpu::Context& context = *context_;
    context.device().waitIdle();  // nothing may still use the old images
    const vk::SurfaceCapabilitiesKHR capabilities = context.physicalDevice().getSurfaceCapabilitiesKHR(context.surface());
    extent_ = capabilities.currentExtent;
    if (extent_.width == UINT32_MAX) {
        const vk::Extent2D wanted = window_->framebufferExtent();
        extent_ = vk::Extent2D{std::clamp(wanted.width, capabilities.minImageExtent.width, capabilities.maxImageExtent.width),
                               std::clamp(wanted.height, capabilities.minImageExtent.height, capabilities.maxImageExtent.height)};
    }
    std::uint32_t count = capabilities.minImageCount + 1;
    if (capabilities.maxImageCount > 0) count = std::min(count, capabilities.maxImageCount);
    vk::raii::SwapchainKHR replacement(
        context.device(),
        vk::SwapchainCreateInfoKHR{.surface = context.surface(), .minImageCount = count, .imageFormat = format_,
                                   .imageColorSpace = colorSpace_, .imageExtent = extent_, .imageArrayLayers = 1,
                                   .imageUsage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc,
                                   .imageSharingMode = vk::SharingMode::eExclusive, .preTransform = capabilities.currentTransform,
                                   .compositeAlpha = vk::CompositeAlphaFlagBitsKHR::eOpaque, .presentMode = presentMode_,
                                   .clipped = VK_TRUE, .oldSwapchain = *swapchain_});
    framebuffers_.clear();
    views_.clear();
    swapchain_ = std::move(replacement);
    images_ = swapchain_.getImages();
    renderFinished_.clear();
    for (vk::Image image : images_) {
        views_.emplace_back(context.device(), vk::ImageViewCreateInfo{.image = image, .viewType = vk::ImageViewType::e2D,
                                                                      .format = format_,
                                                                      .subresourceRange = {vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1}});
        renderFinished_.emplace_back(context.device(), vk::SemaphoreCreateInfo{});
        framebuffers_.emplace_back(context.device(), vk::FramebufferCreateInfo{.renderPass = *overlayPass_, .attachmentCount = 1,
                                                                                   .pAttachments = &*views_.back(),
                                                                                   .width = extent_.width, .height = extent_.height,
                                                                                   .layers = 1});
    }
    using Usage = vk::ImageUsageFlagBits;
    if (samples_ != vk::SampleCountFlagBits::e1)
        msaaColor_ = gpu::Image(context, {.extent = extent_, .format = format_, .usage = Usage::eColorAttachment | Usage::eTransientAttachment,
                                          .samples = samples_});
    depth_ = gpu::Image(context, {.extent = extent_, .format = depthFormat(), .usage = Usage::eDepthStencilAttachment,
                                  .samples = samples_, .aspect = vk::ImageAspectFlagBits::eDepth});
    ++recreations_;
}

void Presenter::readTimestamps(std::uint32_t slot) {
    Slot& s = slots_[slot];
    if (!timestampsSupported_ || !s.timestampsWritten) return;
    std::array<std::uint64_t, 4> ticks{};
    const vk::Result result = (*context_->device()).getQueryPoolResults(*s.timestamps, 0, 4, sizeof(ticks), ticks.data(),
                                                                      sizeof(std::uint64_t), vk::QueryResultFlagBits::e64);
    if (result != vk::Result::eSuccess) return;
    const double msPerTick = static_cast<double>(context_->limits().timestampPeriod) * 1e-6;
    timings_.computeMs = static_cast<double>(ticks[1] - ticks[0]) * msPerTick;
    timings_.drawMs = static_cast<double>(ticks[2] - ticks[1]) * msPerTick;
}

std::optional<std::uint32_t> Presenter::beginFrame() {
    const vk::Extent2D wanted = window_->framebufferExtent();
    if (wanted.width == 0 || wanted.height == 0) {  // minimised: sleep until something changes
        window_->waitForEvents();
        return std::nullopt;
    }
    if (wanted != extent_) {
        createSwapchain();
        return std::nullopt;
    }
    Slot& slot = slots_[slot_];
    THRONG_VK_CHECK(context_->device().waitForFences(*slot.inFlight, VK_TRUE, UINT64_MAX));
    readTimestamps(slot_);
    try {
        const auto [result, index] = swapchain_.acquireNextImage(UINT64_MAX, *slot.imageAvailable);
        if (result != vk::Result::eSuccess && result != vk::Result::eSuboptimalKHR) return std::nullopt;
        image_ = index;
    } catch (const vk::OutOfDateKHRError&) {
        createSwapchain();
        return std::nullopt;
    }
    context_->device().resetFences(*slot.inFlight);
    return slot_;
}

Result<bool> Presenter::endFrame(const Recorder& compute, const Recorder& scene, const Recorder& overlay,
                                 const std::optional<std::string>& screenshotPath) {
    Slot& slot = slots_[slot_];
    const vk::raii::CommandBuffer& commands = slot.commands;
    commands.reset();
    commands.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    if (timestampsSupported_) {
        commands.resetQueryPool(*slot.timestamps, 0, 4);
        commands.writeTimestamp2(Stage::eTopOfPipe, *slot.timestamps, 0);
    }
    compute(commands);
    if (timestampsSupported_) commands.writeTimestamp2(Stage::eComputeShader, *slot.timestamps, 1);

    const vk::Image target = images_[image_];
    const bool multisampled = samples_ != vk::SampleCountFlagBits::e1;
    // Previous frames may still be writing the shared MSAA and depth images: order after them.
    if (multisampled)
        gpu::transitionImage(commands, msaaColor_.handle(), vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined,
                     vk::ImageLayout::eColorAttachmentOptimal, Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite,
                     Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite);
    gpu::transitionImage(commands, depth_.handle(), vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
                 vk::ImageLayout::eDepthAttachmentOptimal, Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                 Access::eDepthStencilAttachmentWrite, Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                 Access::eDepthStencilAttachmentWrite | Access::eDepthStencilAttachmentRead);
    // The acquire semaphore is waited at colour output, so this transition starts after it.
    gpu::transitionImage(commands, target, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eUndefined, vk::ImageLayout::eColorAttachmentOptimal,
                 Stage::eColorAttachmentOutput, Access::eNone, Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite);
    const glm::vec3 sky = skyColor();  // the clear colour matches the fog, as offscreen
    vk::RenderingAttachmentInfo color{.imageView = multisampled ? msaaColor_.view() : *views_[image_],
                                      .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
                                      .loadOp = vk::AttachmentLoadOp::eClear,
                                      .storeOp = multisampled ? vk::AttachmentStoreOp::eDontCare : vk::AttachmentStoreOp::eStore,
                                      .clearValue = vk::ClearColorValue(std::array<float, 4>{sky.r, sky.g, sky.b, 1.0F})};
    if (multisampled) {
        color.resolveMode = vk::ResolveModeFlagBits::eAverage;
        color.resolveImageView = *views_[image_];
        color.resolveImageLayout = vk::ImageLayout::eColorAttachmentOptimal;
    }
    const vk::RenderingAttachmentInfo depth{.imageView = depth_.view(), .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
                                            .loadOp = vk::AttachmentLoadOp::eClear, .storeOp = vk::AttachmentStoreOp::eDontCare,
                                            .clearValue = vk::ClearDepthStencilValue{1.0F, 0}};
    commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, extent_}, .layerCount = 1, .colorAttachmentCount = 1,
                                              .pColorAttachments = &color, .pDepthAttachment = &depth});
    scene(commands);
    commands.endRendering();
    if (timestampsSupported_) commands.writeTimestamp2(Stage::eColorAttachmentOutput, *slot.timestamps, 2);

    commands.beginRenderPass(vk::RenderPassBeginInfo{.renderPass = *overlayPass_, .framebuffer = *framebuffers_[image_],
                                                     .renderArea = {{0, 0}, extent_}},
                             vk::SubpassContents::eInline);
    overlay(commands);
    commands.endRenderPass();

    gpu::Buffer readback;
    if (screenshotPath) {
        readback = gpu::Buffer(*context_, {.size = std::size_t{extent_.width} * extent_.height * 4,
                                           .usage = vk::BufferUsageFlagBits::eTransferDst, .intent = gpu::MemoryIntent::Readback});
        gpu::transitionImage(commands, target, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal,
                     vk::ImageLayout::eTransferSrcOptimal, Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite, Stage::eCopy,
                     Access::eTransferRead);
        commands.copyImageToBuffer(target, vk::ImageLayout::eTransferSrcOptimal, readback.handle(),
                                   vk::BufferImageCopy{.imageSubresource = {vk::ImageAspectFlagBits::eColor, 0, 0, 1},
                                                       .imageExtent = {extent_.width, extent_.height, 1}});
        gpu::transitionImage(commands, target, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eTransferSrcOptimal,
                     vk::ImageLayout::ePresentSrcKHR, Stage::eCopy, Access::eTransferRead, Stage::eNone, Access::eNone);
        const vk::MemoryBarrier2 toHost{.srcStageMask = Stage::eCopy, .srcAccessMask = Access::eTransferWrite,
                                        .dstStageMask = Stage::eHost, .dstAccessMask = Access::eHostRead};
        commands.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &toHost});
    } else {
        gpu::transitionImage(commands, target, vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal,
                     vk::ImageLayout::ePresentSrcKHR, Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite, Stage::eNone,
                     Access::eNone);
    }
    if (timestampsSupported_) {
        commands.writeTimestamp2(Stage::eAllCommands, *slot.timestamps, 3);
        slot.timestampsWritten = true;
    }
    commands.end();

    const vk::SemaphoreSubmitInfo wait{.semaphore = *slot.imageAvailable, .stageMask = Stage::eColorAttachmentOutput};
    const vk::SemaphoreSubmitInfo signal{.semaphore = *renderFinished_[image_], .stageMask = Stage::eAllCommands};
    const vk::CommandBufferSubmitInfo commandInfo{.commandBuffer = *commands};
    context_->queue().submit2(vk::SubmitInfo2{.waitSemaphoreInfoCount = 1, .pWaitSemaphoreInfos = &wait,
                                              .commandBufferInfoCount = 1, .pCommandBufferInfos = &commandInfo,
                                              .signalSemaphoreInfoCount = 1, .pSignalSemaphoreInfos = &signal},
                              *slot.inFlight);
    bool stale = false;
    try {
        const vk::Result presented = context_->queue().presentKHR(vk::PresentInfoKHR{
            .waitSemaphoreCount = 1, .pWaitSemaphores = &*renderFinished_[image_], .swapchainCount = 1,
            .pSwapchains = &*swapchain_, .pImageIndices = &image_});
        stale = presented == vk::Result::eSuboptimalKHR;
    } catch (const vk::OutOfDateKHRError&) {
        stale = true;
    }
    slot_ = (slot_ + 1) % kFramesInFlight;

    Result<bool> saved = true;
    if (screenshotPath) {
        THRONG_VK_CHECK(context_->device().waitForFences(*slot.inFlight, VK_TRUE, UINT64_MAX));
        readback.invalidate();
        std::vector<std::uint8_t> rgba(readback.size());
        std::memcpy(rgba.data(), readback.mapped(), rgba.size());
        if (isBgr(format_))
            for (std::size_t p = 0; p < rgba.size(); p += 4) std::swap(rgba[p], rgba[p + 2]);
        for (std::size_t p = 3; p < rgba.size(); p += 4) rgba[p] = 255;  // the window is opaque
        saved = writePng(*screenshotPath, extent_.width, extent_.height, rgba.data(), std::size_t{extent_.width} * 4);
    }
    if (stale) createSwapchain();
    return saved;
}

}  // namespace throng::render
