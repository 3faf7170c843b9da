#include "path_choice.h"

#include <string>

#include "throng/core/log.h"

namespace throng::app {

bool visibilitySuits(const gpu::Context& context) {
    return context.description().type == "CPU" && !render::CrowdRenderer::visibilityPathUnsupported(context);
}

bool visibilityHoldsFrame(const gpu::Context& context, vk::Extent2D extent, std::string_view who, std::string_view noun) {
    if (render::CrowdRenderer::visibilityFrameFits(context, extent)) return true;
    log::report(std::string(who) + "a " + std::to_string(extent.width) + "x" + std::to_string(extent.height) + " " + std::string(noun) +
                render::CrowdRenderer::visibilityPaddingNote(extent) + " is more than the visibility path's " + std::to_string(render::CrowdRenderer::visibilityPixelLimit(context)) +
                " pixels on this device: drawing with the fast path");
    return false;
}

render::RenderPath pickedPathFor(render::Body body) { return body == render::Body::Bones ? render::RenderPath::Fast : render::RenderPath::Visibility; }

void emplaceOffscreen(std::optional<render::OffscreenRenderer>& offscreen, const gpu::Context& context, const render::Palette& palette,
                      std::span<const motion::BakedClip> clips, render::OffscreenOptions options, std::size_t characters, bool choosePath) {
    offscreen.reset();  // one renderer's buffers at a time
    const bool picks = choosePath && options.path == render::RenderPath::Fast && visibilitySuits(context) &&
                       pickedPathFor(options.body) == render::RenderPath::Visibility &&
                       visibilityHoldsFrame(context, {options.width, options.height}, "", "frame");
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
