#include "throng/render/png.h"

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
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

Result<bool> writePng(const std::string& path, std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba,
                      std::size_t strideBytes) {
    std::vector<std::uint8_t> encoded;
    // Encode in memory first so the file is written in one atomic step.
    if (stbi_write_png_to_func(&appendBytes, &encoded, static_cast<int>(width), static_cast<int>(height), 4, rgba,
                               static_cast<int>(strideBytes)) == 0)
        return Error{Error::Kind::Runtime, "PNG encoding failed", {path, 0, 0}};
    return writeFileAtomically(path, {reinterpret_cast<const char*>(encoded.data()), encoded.size()});
}

}  // namespace throng::render
