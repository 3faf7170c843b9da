#include "throng/viewer/presenter.h"

#include <algorithm>
#include <array>
#include <utility>

#include "throng/gpu/barriers.h"
#include "throng/render/png.h"
#include "throng/render/scene_look.h"

namespace throng::viewer {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;
enum Mark : std::uint32_t { kStart, kComputed, kDrawn, kMarks };  // timestamps per frame
constexpr std::uint64_t kTimedEvery = 8;  // frames per one whose passes are timed for the HUD

bool isBgr(vk::Format format) { return format == vk::Format::eB8G8R8A8Srgb || format == vk::Format::eB8G8R8A8Unorm; }

}  // namespace

Presenter::Slot::Slot(const gpu::Context& context)
    : commands(context), imageAvailable(context.device(), vk::SemaphoreCreateInfo{}),
      inFlight(context.device(), vk::FenceCreateInfo{.flags = vk::FenceCreateFlagBits::eSignaled}), timer(context, kMarks) {}

Presenter::Presenter(const gpu::Context& context, const Window& window, const PresenterCreateInfo& info)
    : context_(&context), window_(&window), info_(info), samples_(context.sampleCount(info.msaa)) {
    chooseFormatAndMode();
    createOverlayPass();
    createSwapchain();
    recreations_ = 0;
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) slots_.push_back(std::make_unique<Slot>(context));
}

void Presenter::createOverlayPass() {
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
    overlayPass_ = vk::raii::RenderPass(context_->device(), vk::RenderPassCreateInfo{.attachmentCount = 1, .pAttachments = &attachment,
                                                                                     .subpassCount = 1, .pSubpasses = &subpass,
                                                                                     .dependencyCount = 1, .pDependencies = &dependency});
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
    target_ = std::make_unique<gpu::RenderTarget>(
        context, gpu::RenderTargetCreateInfo{.extent = extent_, .colorFormat = format_, .depthFormat = depthFormat(), .samples = samples_});
    ++recreations_;
}

std::optional<std::uint32_t> Presenter::waitForSlot() {
    const vk::Extent2D wanted = window_->framebufferExtent();
    if (wanted.width == 0 || wanted.height == 0) {  // minimised: sleep until something changes
        window_->waitForEvents();
        return std::nullopt;
    }
    if (wanted != extent_) {
        createSwapchain();
        return std::nullopt;
    }
    Slot& slot = *slots_[slot_];
    THRONG_VK_CHECK(context_->device().waitForFences(*slot.inFlight, VK_TRUE, UINT64_MAX));
    if (const auto intervals = slot.timed ? slot.timer.intervalsMs() : std::nullopt) timings_ = {(*intervals)[kStart], (*intervals)[kComputed]};
    handOverCapture(slot);
    return slot_;
}

void Presenter::handOverCapture(Slot& slot) {
    const std::optional<double> label = std::exchange(slot.pendingLabel, std::nullopt);
    if (!label || !captureSink_) return;
    const std::vector<std::uint8_t> rgba = opaqueRgba(*slot.capture);
    captureSink_(rgba.data(), slot.capture->extent(), *label);
}

void Presenter::flushCaptures() {
    context_->device().waitIdle();
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) handOverCapture(*slots_[(slot_ + i) % kFramesInFlight]);  // oldest first
}

Result<bool> Presenter::drawFrame(const FrameRecorders& recorders, const FrameCopies& copies) {
    const std::optional<std::string>& screenshotPath = copies.screenshotPath;
    Slot& slot = *slots_[slot_];
    std::uint32_t image = 0;
    try {
        const auto [result, index] = swapchain_.acquireNextImage(UINT64_MAX, *slot.imageAvailable);
        if (result != vk::Result::eSuccess && result != vk::Result::eSuboptimalKHR) return true;  // nothing acquired: skip
        image = index;
    } catch (const vk::OutOfDateKHRError&) {
        createSwapchain();
        return true;
    }
    // From here on the frame is always submitted: the fence is reset only just before it.
    const vk::raii::CommandBuffer& commands = slot.commands.begin();
    // The HUD's GPU figures from one frame in kTimedEvery: lavapipe flushes its work at every
    // timestamp, which cost a 2000-character frame about 0.6 ms.
    slot.timed = framesDrawn_++ % kTimedEvery == 0;
    const auto mark = [&](vk::PipelineStageFlags2 stage, std::uint32_t at) {
        if (slot.timed) slot.timer.mark(commands, stage, at);
    };
    if (slot.timed) slot.timer.reset(commands);
    mark(Stage::eTopOfPipe, kStart);
    recorders.compute(commands);
    mark(Stage::eComputeShader, kComputed);
    // The clear matches the fog, as offscreen.
    target_->begin(commands, {images_[image], *views_[image]}, render::skyClearColor(), std::nullopt, recorders.sceneNeedsClearedDepth);
    recorders.scene(commands);
    target_->end(commands);
    mark(Stage::eColorAttachmentOutput, kDrawn);
    commands.beginRenderPass(vk::RenderPassBeginInfo{.renderPass = *overlayPass_, .framebuffer = *framebuffers_[image],
                                                     .renderArea = {{0, 0}, extent_}},
                             vk::SubpassContents::eInline);
    recorders.overlay(commands);
    commands.endRenderPass();
    std::optional<gpu::ImageReadback> screenshot;
    if (screenshotPath) screenshot.emplace(*context_, extent_);
    const gpu::ImageReadback* capture = nullptr;
    if (copies.captureLabel) {
        if (!slot.capture || slot.capture->extent() != extent_) slot.capture.emplace(*context_, extent_);
        capture = &*slot.capture;
        slot.pendingLabel = copies.captureLabel;
    }
    recordPresentation(commands, images_[image], {screenshot ? &*screenshot : nullptr, capture});
    commands.end();

    context_->device().resetFences(*slot.inFlight);
    gpu::submit(*context_, commands, *slot.inFlight, *slot.imageAvailable, Stage::eColorAttachmentOutput, *renderFinished_[image]);
    bool stale = false;
    try {
        const vk::Result presented = context_->queue().presentKHR(vk::PresentInfoKHR{
            .waitSemaphoreCount = 1, .pWaitSemaphores = &*renderFinished_[image], .swapchainCount = 1,
            .pSwapchains = &*swapchain_, .pImageIndices = &image});
        stale = presented == vk::Result::eSuboptimalKHR;
    } catch (const vk::OutOfDateKHRError&) {
        stale = true;
    }
    slot_ = (slot_ + 1) % kFramesInFlight;

    Result<bool> saved = true;
    if (screenshot) {
        THRONG_VK_CHECK(context_->device().waitForFences(*slot.inFlight, VK_TRUE, UINT64_MAX));
        saved = saveScreenshot(*screenshot, *screenshotPath);
    }
    if (stale) createSwapchain();
    return saved;
}

void Presenter::recordPresentation(const vk::raii::CommandBuffer& commands, vk::Image image,
                                   const std::array<const gpu::ImageReadback*, 2>& readbacks) const {
    const auto color = vk::ImageAspectFlagBits::eColor;
    if (readbacks[0] == nullptr && readbacks[1] == nullptr) {
        gpu::transitionImage(commands, image, color, vk::ImageLayout::eColorAttachmentOptimal, vk::ImageLayout::ePresentSrcKHR,
                             Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite, Stage::eNone, Access::eNone);
        return;
    }
    gpu::transitionImage(commands, image, color, vk::ImageLayout::eColorAttachmentOptimal, vk::ImageLayout::eTransferSrcOptimal,
                         Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite, Stage::eCopy, Access::eTransferRead);
    for (const gpu::ImageReadback* readback : readbacks)
        if (readback != nullptr) readback->recordCopy(commands, image);
    gpu::transitionImage(commands, image, color, vk::ImageLayout::eTransferSrcOptimal, vk::ImageLayout::ePresentSrcKHR, Stage::eCopy,
                         Access::eTransferRead, Stage::eNone, Access::eNone);
}

std::vector<std::uint8_t> Presenter::opaqueRgba(const gpu::ImageReadback& readback) const {
    std::vector<std::uint8_t> rgba = readback.read();
    if (isBgr(format_))
        for (std::size_t p = 0; p < rgba.size(); p += 4) std::swap(rgba[p], rgba[p + 2]);
    for (std::size_t p = 3; p < rgba.size(); p += 4) rgba[p] = 255;  // the window is opaque
    return rgba;
}

Result<bool> Presenter::saveScreenshot(const gpu::ImageReadback& readback, const std::string& path) const {
    const std::vector<std::uint8_t> rgba = opaqueRgba(readback);
    return render::writePng(path, readback.extent().width, readback.extent().height, rgba.data(), std::size_t{readback.extent().width} * 4);
}

}  // namespace throng::viewer
