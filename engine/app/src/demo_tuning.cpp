#include "demo_tuning.h"

#include <algorithm>
#include <cmath>

#include "path_choice.h"
#include "throng/core/log.h"
#include "throng/render/render_path.h"

namespace throng::app {
// On a CPU device (lavapipe) the defaults a GPU handles easily are too slow to be interactive:
// a smaller crowd, the visibility path and no multisampling keep the demo interactive on two
// cores. Options the user gave are never changed.
std::string tuneForDevice(DemoCommand& command, const gpu::Context& context) {
    if (context.description().type != "CPU") return {};
    std::string picked;
    if (command.tuneCharacters) {
        command.crowd.characters = kCpuDemoCharacters;
        picked += std::to_string(kCpuDemoCharacters) + " characters";
    }
    // The visibility path draws the fast path's bodies for half its time or less on a CPU
    // rasteriser, and smooths them without multisampling (DemoSession keeps the fast path for a
    // crowd past what one of its batches holds, or a window past its per-pixel buffer).
    if (command.tunePath && command.crowd.path == render::RenderPath::Fast && visibilitySuits(context)) {
        command.crowd.path = render::RenderPath::Visibility;
        // Bone bodies alone are the fast path's (pickedPathFor), as in render.
        picked += std::string(picked.empty() ? "" : ", ") + "visibility path" +
                  (pickedPathFor(command.crowd.body) == render::RenderPath::Fast ? " (fast for bone bodies)" : "");
    }
    if (command.tuneMsaa) {
        command.crowd.msaa = kCpuDemoMsaa;
        picked += std::string(picked.empty() ? "" : ", ") + std::to_string(kCpuDemoMsaa) + "x MSAA";
    }
    return picked;
}

std::int64_t reshapedCrowdSize(std::int64_t planned, double factor, std::int64_t groups, std::int64_t batch, std::int64_t tracks) {
    const std::int64_t scaled = std::llround(static_cast<double>(planned) * factor);
    std::int64_t most = kMaxCharacters;
    if (batch > 0 && scaled > batch) {
        most = std::min<std::int64_t>(most, batch);
        log::warning("the visibility path draws at most " + std::to_string(most) + " characters on this device: the crowd stops there");
    }
    if (tracks > 0 && scaled > tracks) {
        most = std::min(most, tracks);
        log::warning("the trajectory file has " + std::to_string(tracks) + " tracks: the crowd stops there");
    }
    return std::max(groups, std::min(scaled, most));
}

}  // namespace throng::app
