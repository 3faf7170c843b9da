#pragma once
// PNG output through stb_image_write, written atomically (no partial file on failure).

#include <cstdint>
#include <string>

#include "throng/core/error.h"

namespace throng::render {

/// Writes RGBA8 pixels; `strideBytes` is the distance between rows (>= width × 4).
[[nodiscard]] Result<bool> writePng(const std::string& path, std::uint32_t width, std::uint32_t height,
                                    const std::uint8_t* rgba, std::size_t strideBytes);

}  // namespace throng::render
