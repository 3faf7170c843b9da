#pragma once
// Presents frames to a window: the swapchain (recreated on resize or when out of date), two
// frames in flight, the MSAA colour and depth targets, GPU timestamps around the compute and
// draw passes, an overlay render pass for the HUD, and screenshots of the presented image.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "throng/gpu/resources.h"
#include "throng/render/window.h"

namespace throng::render {

struct PresenterCreateInfo {
    bool vsync = true;           ///< FIFO; false picks MAILBOX, else IMMEDIATE, where supported.
    std::uint32_t msaa = 4;      ///< Wanted samples, lowered to what the device supports.
};

/// GPU time of the last completed frame in this slot, from timestamp queries (ms); negative
/// when the device has no timestamps.
struct GpuTimings {
    double computeMs = -1.0;
    double drawMs = -1.0;
};

class Presenter {
public:
    static constexpr std::uint32_t kFramesInFlight = 2;

    Presenter(const gpu::Context& context, const Window& window, const PresenterCreateInfo& info);
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;
    ~Presenter();

    /// Waits for the next frame slot and acquires a swapchain image. Returns the slot, or
    /// nullopt when there is nothing to draw into this time (minimised, or the swapchain was
    /// just recreated): the caller skips the frame.
    std::optional<std::uint32_t> beginFrame();

    using Recorder = std::function<void(const vk::raii::CommandBuffer&)>;
    /// Records compute, then the scene inside dynamic rendering (MSAA, resolved into the
    /// swapchain image), then the overlay inside overlayRenderPass(); submits and presents.
    /// With `screenshotPath`, also saves the presented image as PNG (waiting for it).
    Result<bool> endFrame(const Recorder& compute, const Recorder& scene, const Recorder& overlay,
                          const std::optional<std::string>& screenshotPath);

    [[nodiscard]] vk::Extent2D extent() const { return extent_; }
    [[nodiscard]] vk::Format colorFormat() const { return format_; }
    [[nodiscard]] vk::Format depthFormat() const { return vk::Format::eD32Sfloat; }
    [[nodiscard]] vk::SampleCountFlagBits samples() const { return samples_; }
    [[nodiscard]] std::uint32_t imageCount() const { return static_cast<std::uint32_t>(images_.size()); }
    [[nodiscard]] vk::RenderPass overlayRenderPass() const { return *overlayPass_; }
    [[nodiscard]] const GpuTimings& lastTimings() const { return timings_; }
    [[nodiscard]] const char* presentModeName() const;
    /// Swapchain recreations so far (resizes, out-of-date), for the HUD and tests.
    [[nodiscard]] std::uint32_t recreations() const { return recreations_; }

private:
    void chooseFormatAndMode();
    void createSwapchain();
    void readTimestamps(std::uint32_t slot);

    const gpu::Context* context_;
    const Window* window_;
    PresenterCreateInfo info_;
    vk::SampleCountFlagBits samples_;
    vk::Format format_ = vk::Format::eUndefined;
    vk::ColorSpaceKHR colorSpace_{};
    vk::PresentModeKHR presentMode_ = vk::PresentModeKHR::eFifo;
    vk::Extent2D extent_;
    vk::raii::SwapchainKHR swapchain_{nullptr};
    std::vector<vk::Image> images_;
    std::vector<vk::raii::ImageView> views_;
    std::vector<vk::raii::Framebuffer> framebuffers_;
    std::vector<vk::raii::Semaphore> renderFinished_;  ///< One per swapchain image: reused only after that image comes back.
    gpu::Image msaaColor_, depth_;
    vk::raii::RenderPass overlayPass_{nullptr};

    struct Slot {
        vk::raii::CommandPool pool{nullptr};
        vk::raii::CommandBuffer commands{nullptr};
        vk::raii::Semaphore imageAvailable{nullptr};
        vk::raii::Fence inFlight{nullptr};
        vk::raii::QueryPool timestamps{nullptr};
        bool timestampsWritten = false;
    };
    std::vector<Slot> slots_;
    std::uint32_t slot_ = 0;
    std::uint32_t image_ = 0;
    bool timestampsSupported_ = false;
    GpuTimings timings_;
    std::uint32_t recreations_ = 0;
};

}  // namespace throng::render
