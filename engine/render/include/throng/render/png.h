#pragma once
// PNG output through stb_image_write, written atomically (no partial file on failure), to
// stdout for "-", or in place to a device (see throng/core/atomic_file.h).

#include <cstdint>
#include <string>

#include "throng/core/error.h"

namespace throng::render {

/// RGBA8 pixels encoded as an opaque RGB PNG file's bytes (alpha dropped); `strideBytes` is the distance between rows
/// (>= width × 4).
[[nodiscard]] Result<std::string> encodePng(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba,
                                            std::size_t strideBytes);

/// Encodes and writes RGBA8 pixels to `path` ("-" for stdout).
[[nodiscard]] Result<bool> writePng(const std::string& path, std::uint32_t width, std::uint32_t height,
                                    const std::uint8_t* rgba, std::size_t strideBytes);

}  // namespace throng::render
