#include "throng/viewer/window.h"

#include <cstdlib>
#include <optional>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace throng::viewer {
namespace {

constexpr int kGlfwKeys[] = {GLFW_KEY_ESCAPE, GLFW_KEY_SPACE, GLFW_KEY_EQUAL, GLFW_KEY_MINUS, GLFW_KEY_UP, GLFW_KEY_DOWN, GLFW_KEY_LEFT_BRACKET,
                             GLFW_KEY_RIGHT_BRACKET, GLFW_KEY_M, GLFW_KEY_P, GLFW_KEY_F, GLFW_KEY_C,
                             GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E, GLFW_KEY_F1, GLFW_KEY_H, GLFW_KEY_B, GLFW_KEY_R};
static_assert(std::size(kGlfwKeys) == kKeyCount);

// The keypad's + and - work too.
std::optional<Key> keyFromGlfw(int code) {
    if (code == GLFW_KEY_KP_ADD) return Key::Plus;
    if (code == GLFW_KEY_KP_SUBTRACT) return Key::Minus;
    for (std::size_t k = 0; k < kKeyCount; ++k)
        if (kGlfwKeys[k] == code) return static_cast<Key>(k);
    return std::nullopt;
}

bool keyDown(GLFWwindow* window, Key key) {
    if (glfwGetKey(window, kGlfwKeys[static_cast<std::size_t>(key)]) == GLFW_PRESS) return true;
    if (key == Key::Plus) return glfwGetKey(window, GLFW_KEY_KP_ADD) == GLFW_PRESS;
    if (key == Key::Minus) return glfwGetKey(window, GLFW_KEY_KP_SUBTRACT) == GLFW_PRESS;
    return false;
}

std::string glfwErrorText() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description != nullptr ? description : "unknown GLFW error";
}

}  // namespace

Result<std::unique_ptr<Window>> Window::create(const WindowCreateInfo& info) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const bool noDisplay = (display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0');
    const std::string hint = "; use 'throng render --out FILE.png' to render without a display";
    if (noDisplay) return Error{Error::Kind::Runtime, "no display to open a window on (DISPLAY is not set)" + hint, {}};
    if (glfwInit() != GLFW_TRUE) return Error{Error::Kind::Runtime, "cannot open the display: " + glfwErrorText() + hint, {}};
    if (glfwVulkanSupported() != GLFW_TRUE) {
        glfwTerminate();
        return Error{Error::Kind::Runtime, "GLFW finds no Vulkan loader (Debian: libvulkan1)" + hint, {}};
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    std::unique_ptr<Window> window(new Window());
    window->window_ = glfwCreateWindow(static_cast<int>(info.width), static_cast<int>(info.height), info.title.c_str(), nullptr, nullptr);
    if (window->window_ == nullptr) {
        const std::string reason = glfwErrorText();
        glfwTerminate();
        return Error{Error::Kind::Runtime, "cannot create a window: " + reason + hint, {}};
    }
    glfwSetWindowUserPointer(window->window_, window.get());
    // GLFW's scroll callback replaces the HUD's; ImGui's GLFW backend chains to the previous
    // one when installed afterwards, so both see the wheel.
    glfwSetScrollCallback(window->window_, [](GLFWwindow* handle, double /*x*/, double y) {
        static_cast<Window*>(glfwGetWindowUserPointer(handle))->scroll_ += static_cast<float>(y);
    });
    // Presses are queued as they arrive, so a key tapped between two slow frames still counts
    // (polling would miss a press and release that both fall between polls).
    glfwSetKeyCallback(window->window_, [](GLFWwindow* handle, int code, int /*scancode*/, int action, int /*mods*/) {
        if (action != GLFW_PRESS) return;
        if (const std::optional<Key> key = keyFromGlfw(code)) static_cast<Window*>(glfwGetWindowUserPointer(handle))->pressed_.push_back(*key);
    });
    return window;
}

Window::~Window() {
    if (window_ != nullptr) glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return {names, names + count};
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    if (glfwCreateWindowSurface(instance, window_, nullptr, &surface) != VK_SUCCESS) return VK_NULL_HANDLE;
    return surface;
}

FrameInput Window::poll(bool uiWantsMouse, bool uiTypesText) {
    glfwPollEvents();
    FrameInput input;
    for (std::size_t k = 0; k < input.held.size(); ++k) input.held[k] = !uiTypesText && keyDown(window_, static_cast<Key>(k));
    if (!uiTypesText) input.pressed = std::move(pressed_);
    pressed_.clear();
    glm::dvec2 cursor;
    glfwGetCursorPos(window_, &cursor.x, &cursor.y);
    const bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool other = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                       glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    if (haveCursor_ && !uiWantsMouse && (left || other)) input.mouseDelta = glm::vec2(cursor - lastCursor_);
    input.orbiting = left && !uiWantsMouse;
    input.panning = other && !uiWantsMouse;
    input.scroll = uiWantsMouse ? 0.0F : scroll_;
    scroll_ = 0.0F;
    lastCursor_ = cursor;
    haveCursor_ = true;
    return input;
}

void Window::waitForEvents() const { glfwWaitEventsTimeout(0.1); }
bool Window::closeRequested() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::requestClose() const { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

vk::Extent2D Window::framebufferExtent() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {static_cast<std::uint32_t>(std::max(width, 0)), static_cast<std::uint32_t>(std::max(height, 0))};
}

void Window::resize(std::uint32_t width, std::uint32_t height) const {
    glfwSetWindowSize(window_, static_cast<int>(width), static_cast<int>(height));
}

}  // namespace throng::viewer
