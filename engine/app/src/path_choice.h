#pragma once
// The render path Throng picks when the user names none (render, bench and the demo).

#include <optional>
#include <span>
#include <string_view>

#include "throng/gpu/context.h"
#include "throng/render/offscreen.h"

namespace throng::app {

/// Whether the visibility path is the better default on this device: a CPU rasteriser
/// (lavapipe), where it draws the fast path's bodies in half its time or less and smooths them
/// without multisampling, with the 64-bit atomics it needs. On a GPU the fast path stays.
[[nodiscard]] bool visibilitySuits(const gpu::Context& context);

/// Whether the visibility path's per-pixel buffer holds a frame of `extent` on this device; when
/// it does not, says so ("`who`a WxH `noun` is more than ...: drawing with the fast path").
[[nodiscard]] bool visibilityHoldsFrame(const gpu::Context& context, vk::Extent2D extent, std::string_view who, std::string_view noun);

/// The path a visibility path Throng picked itself draws `body` with: bone bodies alone go to
/// the fast path, as the visibility path clips a bone wider than 255 pixels on screen (a
/// close-up), which auto never shows, as it skins every character that near.
[[nodiscard]] render::RenderPath pickedPathFor(render::Body body);

/// Builds `offscreen` for `characters` characters. With `choosePath` (no --path given) and
/// options.path fast, the visibility path for skin and auto bodies where it suits the device
/// (bone bodies keep the fast path, which draws a close-up's bones whole), giving way to the fast
/// path (which draws in batches) for a crowd past what one of the visibility path's batches
/// holds or a frame past its per-pixel buffer, and saying so once.
void emplaceOffscreen(std::optional<render::OffscreenRenderer>& offscreen, const gpu::Context& context, const render::Palette& palette,
                      std::span<const motion::BakedClip> clips, render::OffscreenOptions options, std::size_t characters, bool choosePath);

}  // namespace throng::app
