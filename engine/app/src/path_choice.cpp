#include "path_choice.h"

#include <string>

#include "throng/core/log.h"

namespace throng::app {

bool visibilitySuits(const gpu::Context& context) { return context.description().type == "CPU" && context.hasInt64Atomics(); }

void emplaceOffscreen(std::optional<render::OffscreenRenderer>& offscreen, const gpu::Context& context, const render::Palette& palette,
                      std::span<const motion::BakedClip> clips, render::OffscreenOptions options, std::size_t characters, bool choosePath) {
    offscreen.reset();  // one renderer's buffers at a time
    // Not for bone bodies alone: the visibility path clips a bone wider than 255 pixels on screen
    // (a close-up), which auto never shows, as it skins every character that near.
    const bool picks = choosePath && options.path == render::RenderPath::Fast && options.body != render::Body::Bones && visibilitySuits(context);
    if (picks) options.path = render::RenderPath::Visibility;
    offscreen.emplace(context, palette, clips, options);
    const std::uint32_t most = offscreen->renderer().batchCharacters();
    if (!picks || characters <= most) return;
    log::report(std::to_string(characters) + " characters are more than the visibility path's " + std::to_string(most) +
                " on this device: drawing with the fast path");
    offscreen.reset();
    options.path = render::RenderPath::Fast;
    offscreen.emplace(context, palette, clips, options);
}

}  // namespace throng::app
