#include "throng/gpu/render_target.h"

#include <stdexcept>

#include "throng/gpu/barriers.h"

namespace throng::gpu {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

RenderTarget::RenderTarget(const Context& context, const RenderTargetCreateInfo& info) : info_(info) {
    using Usage = vk::ImageUsageFlagBits;
    if (multisampled())
        msaaColor_ = Image(context, {.extent = info.extent, .format = info.colorFormat,
                                     .usage = Usage::eColorAttachment | Usage::eTransientAttachment, .samples = info.samples});
    depth_ = Image(context, {.extent = info.extent, .format = info.depthFormat, .usage = Usage::eDepthStencilAttachment,
                             .samples = info.samples, .aspect = vk::ImageAspectFlagBits::eDepth});
}

void RenderTarget::begin(const vk::raii::CommandBuffer& commands, const ColorOutput& output, const std::array<float, 4>& clear,
                         std::optional<vk::ImageLayout> keptFrom, bool clearDepth) const {
    const auto color = vk::ImageAspectFlagBits::eColor;
    if (keptFrom && multisampled()) throw std::logic_error("RenderTarget::begin: only a single-sampled frame keeps its colour");
    // Earlier frames wrote these images, and a copy may have read the output: order after
    // them and discard the contents (or keep the output's). A swapchain's acquire semaphore is
    // waited at colour output, so the output's transition also starts after the image is really free.
    transitionImage(commands, output.image, color, keptFrom.value_or(vk::ImageLayout::eUndefined), vk::ImageLayout::eColorAttachmentOptimal,
                    Stage::eColorAttachmentOutput | Stage::eCopy, Access::eColorAttachmentWrite, Stage::eColorAttachmentOutput,
                    Access::eColorAttachmentWrite | (keptFrom ? Access::eColorAttachmentRead : vk::AccessFlags2{}));
    if (multisampled())
        transitionImage(commands, msaaColor_.handle(), color, vk::ImageLayout::eUndefined, vk::ImageLayout::eColorAttachmentOptimal,
                        Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite, Stage::eColorAttachmentOutput,
                        Access::eColorAttachmentWrite);
    const auto depthTests = Stage::eEarlyFragmentTests | Stage::eLateFragmentTests;
    transitionImage(commands, depth_.handle(), vk::ImageAspectFlagBits::eDepth, vk::ImageLayout::eUndefined,
                    vk::ImageLayout::eDepthAttachmentOptimal, depthTests, Access::eDepthStencilAttachmentWrite, depthTests,
                    Access::eDepthStencilAttachmentWrite | Access::eDepthStencilAttachmentRead);

    vk::RenderingAttachmentInfo colorAttachment{.imageView = multisampled() ? msaaColor_.view() : output.view,
                                                .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
                                                .loadOp = keptFrom ? vk::AttachmentLoadOp::eLoad : vk::AttachmentLoadOp::eClear,
                                                .storeOp = multisampled() ? vk::AttachmentStoreOp::eDontCare : vk::AttachmentStoreOp::eStore,
                                                .clearValue = vk::ClearColorValue(clear)};
    if (multisampled()) {
        colorAttachment.resolveMode = vk::ResolveModeFlagBits::eAverage;
        colorAttachment.resolveImageView = output.view;
        colorAttachment.resolveImageLayout = vk::ImageLayout::eColorAttachmentOptimal;
    }
    const vk::RenderingAttachmentInfo depthAttachment{.imageView = depth_.view(),
                                                      .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
                                                      .loadOp = clearDepth ? vk::AttachmentLoadOp::eClear : vk::AttachmentLoadOp::eDontCare,
                                                      .storeOp = vk::AttachmentStoreOp::eDontCare,
                                                      .clearValue = vk::ClearDepthStencilValue{1.0F, 0}};
    commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, info_.extent}, .layerCount = 1, .colorAttachmentCount = 1,
                                              .pColorAttachments = &colorAttachment, .pDepthAttachment = &depthAttachment});
}

void RenderTarget::end(const vk::raii::CommandBuffer& commands) const { commands.endRendering(); }

}  // namespace throng::gpu
