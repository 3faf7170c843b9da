#include "throng/render/png.h"

#include <climits>
#include <string>
#include <vector>

#include "throng/core/atomic_file.h"

// stb is a third-party single-header library; its implementation doesn't meet our warning flags.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace throng::render {
namespace {
void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::string*>(context);
    out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

Result<std::string> encodePng(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba, std::size_t strideBytes) {
    constexpr std::uint32_t kLargestSide = 1U << 15;  // stb takes int sizes; rows of 4 bytes each stay far below INT_MAX
    if (width == 0 || height == 0 || width > kLargestSide || height > kLargestSide || strideBytes < std::size_t{width} * 4 ||
        strideBytes > INT_MAX)
        return Error{Error::Kind::BadInput, "cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + " PNG", {}};
    // A frame is opaque (the sky covers what nothing else does), but the colour target's alpha
    // holds whatever the last shader wrote there, such as the sprites' rim coverage: written as
    // RGB, so no viewer shows those pixels see-through.
    std::vector<std::uint8_t> rgb(std::size_t{width} * height * 3);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            for (std::size_t c = 0; c < 3; ++c)
                rgb[(std::size_t{y} * width + x) * 3 + c] = rgba[y * strideBytes + std::size_t{x} * 4 + c];
    std::string encoded;
    // Encoded in memory first so the file is written in one atomic step (or to stdout).
    if (stbi_write_png_to_func(&appendBytes, &encoded, static_cast<int>(width), static_cast<int>(height), 3, rgb.data(),
                               static_cast<int>(width * 3)) == 0)
        return Error{Error::Kind::Runtime, "PNG encoding failed", {}};
    return encoded;
}

Result<bool> writePng(const std::string& path, std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba,
                      std::size_t strideBytes) {
    auto encoded = encodePng(width, height, rgba, strideBytes);
    if (!encoded) return Error{encoded.error().kind, encoded.error().message, {path, 0, 0}};
    return writeFileAtomically(path, encoded.value());
}

}  // namespace throng::render
