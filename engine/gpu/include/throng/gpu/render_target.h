#pragma once
// The attachments every frame of the scene draws into: an optional MSAA colour image and a
// depth image, sized once, plus the colour output they resolve into. The output belongs to
// the caller (an offscreen image, or this frame's swapchain image), so the presenter and the
// offscreen renderer record the same scene pass through begin() and end().

#include <array>
#include <optional>

#include "throng/gpu/resources.h"

namespace throng::gpu {

struct RenderTargetCreateInfo {
    vk::Extent2D extent;                                          ///< Pixels, > 0 each way.
    vk::Format colorFormat = vk::Format::eR8G8B8A8Srgb;           ///< The output's format.
    vk::Format depthFormat = vk::Format::eD32Sfloat;
    vk::SampleCountFlagBits samples = vk::SampleCountFlagBits::e1;  ///< > 1 adds an MSAA colour image.
};

/// Where the scene pass writes its final colour: an image in any layout whose contents may be
/// discarded, and its view.
struct ColorOutput {
    vk::Image image;
    vk::ImageView view;
};

class RenderTarget {
public:
    RenderTarget(const Context& context, const RenderTargetCreateInfo& info);

    /// Transitions the attachments (discarding what earlier frames left in them, after those
    /// frames' writes and copies) and begins dynamic rendering that clears colour to `clear`
    /// (linear RGBA) and depth to 1, and resolves MSAA into `output`. With `keptFrom` (one
    /// sample only), the output's colour is kept instead of cleared: it is in that layout, as
    /// the last frame left it. With `clearDepth` false, depth starts undefined: for draws that
    /// set it themselves where they test it (a CPU device clears the whole attachment otherwise).
    void begin(const vk::raii::CommandBuffer& commands, const ColorOutput& output, const std::array<float, 4>& clear,
               std::optional<vk::ImageLayout> keptFrom = std::nullopt, bool clearDepth = true) const;
    /// Ends rendering; `output` is then in ColorAttachmentOptimal with the frame in it.
    void end(const vk::raii::CommandBuffer& commands) const;

    [[nodiscard]] vk::Extent2D extent() const { return info_.extent; }
    [[nodiscard]] vk::Format colorFormat() const { return info_.colorFormat; }
    [[nodiscard]] vk::Format depthFormat() const { return info_.depthFormat; }
    [[nodiscard]] vk::SampleCountFlagBits samples() const { return info_.samples; }
    [[nodiscard]] bool multisampled() const { return info_.samples != vk::SampleCountFlagBits::e1; }

private:
    RenderTargetCreateInfo info_;
    Image msaaColor_, depth_;
};

}  // namespace throng::gpu
