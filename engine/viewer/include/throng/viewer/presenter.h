#pragma once
// Presents frames to a window: the swapchain (recreated on resize or when out of date), two
// frames in flight, the shared render target (MSAA colour and depth) resolved into the
// swapchain image, GPU timestamps around the compute and draw passes, an overlay render pass
// for the HUD, screenshots of the presented image, and a capture of every presented image for
// a recording.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "throng/gpu/commands.h"
#include "throng/gpu/gpu_timer.h"
#include "throng/gpu/readback.h"
#include "throng/gpu/render_target.h"
#include "throng/viewer/window.h"

namespace throng::viewer {

struct PresenterCreateInfo {
    bool vsync = true;           ///< FIFO; false picks MAILBOX, else IMMEDIATE, where supported.
    std::uint32_t msaa = 4;      ///< Wanted samples, lowered to what the device supports.
};

/// GPU time of the last completed frame in a slot, from timestamp queries (ms); negative
/// when the device has no timestamps.
struct GpuTimings {
    double computeMs = -1.0;
    double drawMs = -1.0;
};

/// What one frame records: the compute work, the scene (inside the render target's dynamic
/// rendering) and the overlay (inside overlayRenderPass()).
struct FrameRecorders {
    using Recorder = std::function<void(const vk::raii::CommandBuffer&)>;
    Recorder compute;
    Recorder scene;
    Recorder overlay;
    bool sceneNeedsClearedDepth = true;  ///< False: the scene sets depth itself where it tests it.
};

/// What a frame copies out besides presenting.
struct FrameCopies {
    std::optional<std::string> screenshotPath;  ///< Save the presented image as PNG (drawFrame waits for it).
    /// Hand the presented image to the capture sink (no wait), with this caller's label
    /// (the recording's time of the frame).
    std::optional<double> captureLabel;
};

/// Receives a captured frame: RGBA8, opaque, rows extent.width * 4 bytes apart, top first,
/// and the label drawFrame was given for it.
using CaptureSink = std::function<void(const std::uint8_t* rgba, vk::Extent2D extent, double label)>;

class Presenter {
public:
    static constexpr std::uint32_t kFramesInFlight = 2;

    Presenter(const gpu::Context& context, const Window& window, const PresenterCreateInfo& info);
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;
    ~Presenter();

    /// Waits until the next frame slot's previous submission has finished, so its buffers may
    /// be rewritten. Returns the slot, or nullopt when there is nothing to draw into this time
    /// (minimised, or the swapchain was just rebuilt for a new size): skip the frame. Nothing
    /// is acquired or reset here, so skipping is always safe.
    std::optional<std::uint32_t> waitForSlot();

    /// Acquires a swapchain image, records the frame, submits and presents it, all in one
    /// call so that no path can acquire without submitting. Copies the presented image as
    /// `copies` asks. Call after waitForSlot() returned a slot.
    Result<bool> drawFrame(const FrameRecorders& recorders, const FrameCopies& copies);

    /// Where captured frames go. A frame drawn with a captureLabel is handed over when its slot
    /// comes round again (in waitForSlot, so the demo never waits on the frame it just
    /// submitted) or at flushCaptures(); frames arrive in the order they were drawn.
    void setCaptureSink(CaptureSink sink) { captureSink_ = std::move(sink); }
    /// Waits for the frames in flight and hands over every capture still pending, oldest first.
    void flushCaptures();

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
    struct Slot {
        explicit Slot(const gpu::Context& context);
        gpu::FrameCommands commands;
        vk::raii::Semaphore imageAvailable{nullptr};
        vk::raii::Fence inFlight{nullptr};
        gpu::GpuTimer timer;
        bool timed = false;  ///< Its last frame wrote the timer's timestamps.
        std::optional<gpu::ImageReadback> capture;  ///< Kept between frames; remade when the size changes.
        std::optional<double> pendingLabel;         ///< Its last frame was copied into `capture`, not yet handed over.
    };

    void chooseFormatAndMode();
    void createOverlayPass();
    void createSwapchain();
    /// Records everything after the overlay: the copies into `readbacks` (the non-null ones)
    /// and the transition to present.
    void recordPresentation(const vk::raii::CommandBuffer& commands, vk::Image image,
                            const std::array<const gpu::ImageReadback*, 2>& readbacks) const;
    Result<bool> saveScreenshot(const gpu::ImageReadback& readback, const std::string& path) const;
    /// The image's bytes as RGBA8 with alpha 255, whatever the swapchain's channel order.
    [[nodiscard]] std::vector<std::uint8_t> opaqueRgba(const gpu::ImageReadback& readback) const;
    void handOverCapture(Slot& slot);

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
    std::unique_ptr<gpu::RenderTarget> target_;
    vk::raii::RenderPass overlayPass_{nullptr};
    std::vector<std::unique_ptr<Slot>> slots_;
    std::uint32_t slot_ = 0;
    GpuTimings timings_;
    std::uint64_t framesDrawn_ = 0;
    std::uint32_t recreations_ = 0;
    CaptureSink captureSink_;
};

}  // namespace throng::viewer
