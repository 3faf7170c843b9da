#pragma once
// The desktop window, through GLFW (the viewer module is the only one that includes it). It
// also collects the frame's input, so the demo reads keys and mouse as plain values.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "throng/core/error.h"
#include "throng/core/math.h"
#include "throng/gpu/vulkan.h"
#include "throng/viewer/controls.h"

struct GLFWwindow;

namespace throng::viewer {

struct WindowCreateInfo {
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    std::string title = "throng demo";
};

/// Input gathered since the previous frame.
struct FrameInput {
    std::vector<Key> pressed;    ///< Keys that went down, in order; none is lost however slow the frame.
    std::array<bool, kKeyCount> held{};  ///< Is down now.
    glm::vec2 mouseDelta{0.0F};  ///< Pixels moved while a button was held.
    bool orbiting = false;       ///< Left button held (and the HUD doesn't want the mouse).
    bool panning = false;        ///< Right or middle button held.
    float scroll = 0.0F;         ///< Wheel steps.
    [[nodiscard]] bool isHeld(Key k) const { return held[static_cast<std::size_t>(k)]; }
};

class Window {
public:
    /// Opens the window. With no display (no DISPLAY or WAYLAND_DISPLAY, or GLFW can't reach
    /// it) returns a Runtime error that points the user to `throng render`.
    static Result<std::unique_ptr<Window>> create(const WindowCreateInfo& info);
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;
    ~Window();

    /// Instance extensions Vulkan needs to present to this window.
    [[nodiscard]] static std::vector<std::string> requiredInstanceExtensions();
    /// Makes the window's surface on `instance`; VK_NULL_HANDLE on failure.
    [[nodiscard]] VkSurfaceKHR createSurface(VkInstance instance) const;

    /// Processes events and returns this frame's input. `uiWantsMouse` / `uiTypesText`
    /// stop clicks and keys meant for the HUD from reaching the demo.
    FrameInput poll(bool uiWantsMouse, bool uiTypesText);
    /// Blocks until something happens (used while minimised, so nothing spins).
    void waitForEvents() const;
    [[nodiscard]] bool closeRequested() const;
    void requestClose() const;
    /// Framebuffer size in pixels; 0 × 0 while minimised.
    [[nodiscard]] vk::Extent2D framebufferExtent() const;
    void resize(std::uint32_t width, std::uint32_t height) const;
    [[nodiscard]] GLFWwindow* handle() const { return window_; }

private:
    Window() = default;
    GLFWwindow* window_ = nullptr;
    glm::dvec2 lastCursor_{0.0};
    bool haveCursor_ = false;
    std::vector<Key> pressed_;  ///< Collected by the key callback between polls.
    float scroll_ = 0.0F;       ///< Accumulated by the scroll callback between polls.
};

}  // namespace throng::viewer
