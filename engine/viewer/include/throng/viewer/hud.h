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
    std::string mode;                     ///< Locomotion mode name.
    int following = -1;                   ///< Character the camera follows, -1 for none.
    std::uint32_t swapchainRecreations = 0;
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
    /// Builds this frame's widgets; returns the buttons pressed.
    ActionSet build(const HudStats& stats);
    /// Records the HUD's draw calls; call inside the presenter's overlay pass.
    void record(const vk::raii::CommandBuffer& commands) const;

private:
    vk::raii::DescriptorPool pool_{nullptr};
};

}  // namespace throng::viewer
