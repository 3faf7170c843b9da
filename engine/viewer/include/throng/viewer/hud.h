#pragma once
// The demo's heads-up display through Dear ImGui (Debian's libimgui-dev, with its GLFW and
// Vulkan backends): frame statistics, GPU pass times, crowd figures, and the controls (from
// kControls) as buttons.

#include <array>
#include <string>
#include <vector>

#include "throng/viewer/controls.h"
#include "throng/viewer/presenter.h"

namespace throng::viewer {

/// What the HUD shows this frame.
struct HudStats {
    double frameMs = 0.0;                 ///< Wall-clock time of the last frame.
    std::vector<float> frameHistory;      ///< Recent frame times (ms), oldest first.
    double simulationMs = 0.0;            ///< CPU crowd step.
    GpuTimings gpu;                       ///< Compute and draw from timestamp queries.
    int characters = 0;
    std::uint32_t jointsPerCharacter = 0;
    std::string device;
    std::string presentMode;
    bool paused = false;
    float playbackSpeed = 1.0F;
    /// The walking pace and the blend it shows, a line each (of the followed character, else
    /// the crowd's mean): "pace +0.5 m/s: wants 1.80, walks 1.62 m/s", "walk 40% / run 60%".
    std::vector<std::string> pace;
    double simulatedSeconds = 0.0;        ///< Crowd time since the crowd was spawned.
    std::vector<std::string> groupModes;  ///< Locomotion mode of every group, in scene order.
    int following = -1;                   ///< Character the camera follows, -1 for none.
    std::uint32_t swapchainRecreations = 0;
    std::string renderPath;               ///< "fast", "compute", ...
    std::uint32_t msaa = 1;               ///< Samples in use.
    /// Characters drawn with every joint, with the major joints only (level of detail), and
    /// culled, as of the last completed frame; all -1 when the path doesn't report them.
    std::int64_t fullDetail = -1, coarseDetail = -1, culled = -1;
    /// With bodies, the characters drawn as skinned meshes and as bone bodies (the joint
    /// spheres are coarseDetail); -1 without.
    std::int64_t skinDetail = -1, boneDetail = -1;
    std::string tuning;                   ///< What was picked for this device, e.g. "1000 characters, 1x MSAA".
    std::string recording;                ///< While recording: "throng-recording-1.mp4, 3.2 s"; empty otherwise.
};

/// A HUD button's place in window pixels (the test drives the demo with real clicks).
struct ButtonRect {
    Action action;
    float x0, y0, x1, y1;
};

/// Which actions the HUD's buttons asked for this frame (keys ask for the same ones).
using ActionSet = std::array<bool, kActionCount>;

class Hud {
public:
    Hud(const gpu::Context& context, const Window& window, const Presenter& presenter);
    Hud(const Hud&) = delete;
    Hud& operator=(const Hud&) = delete;
    ~Hud();

    /// Whether the last frame's HUD wanted the mouse or keyboard (so the camera ignores them).
    [[nodiscard]] bool wantsMouse() const;
    [[nodiscard]] bool wantsKeyboard() const;
    /// Whether a HUD text field is being typed into. The HUD has none today, so keys always
    /// reach the demo, even while ImGui holds the keyboard for a pressed button (it does, for
    /// a moment after every click, and keys pressed then were lost).
    [[nodiscard]] bool wantsTextInput() const;
    /// Builds this frame's widgets (none while hidden); returns the buttons pressed.
    ActionSet build(const HudStats& stats);
    void setVisible(bool visible) { visible_ = visible; }
    [[nodiscard]] bool visible() const { return visible_; }
    /// Width of the panel's right edge from the window's left, pixels; 0 while hidden.
    [[nodiscard]] float panelRight() const { return visible_ ? panelRight_ : 0.0F; }
    /// The buttons as last drawn.
    [[nodiscard]] const std::vector<ButtonRect>& buttons() const { return buttons_; }
    /// Records the HUD's draw calls; call inside the presenter's overlay pass.
    void record(const vk::raii::CommandBuffer& commands) const;

private:
    void buildPanel(const HudStats& stats, ActionSet& actions);

    vk::raii::DescriptorPool pool_{nullptr};
    bool visible_ = true;
    float panelRight_ = 0.0F;
    std::vector<ButtonRect> buttons_;
};

}  // namespace throng::viewer
