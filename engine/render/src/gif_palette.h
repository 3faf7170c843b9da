#pragma once
// A GIF's 256 colours: one palette, chosen by median cut from the video's first frame (each
// colour the mean of its box's pixels), and the
// mapping of any RGBA8 pixel to it through a 32 x 32 x 32 table, after a 4 x 4 ordered dither
// that hides the table's 8-level steps in the sky's and fog's gradients. The palette and the
// dither depend only on the pixels, so the same frames give the same GIF bytes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::render {

class GifPalette {
public:
    static constexpr std::size_t kColours = 256;

    /// The palette for a width x height RGBA8 frame, rows `stride` bytes apart.
    GifPalette(const std::uint8_t* rgba, std::uint32_t width, std::uint32_t height, std::size_t stride);

    /// Writes the frame's palette indices, rows `indexStride` bytes apart.
    void map(const std::uint8_t* rgba, std::uint32_t width, std::uint32_t height, std::size_t stride, std::uint8_t* indices,
             std::size_t indexStride) const;
    /// The colours as FFmpeg's PAL8 wants them: 0xAARRGGBB in native byte order, opaque; the
    /// entries a frame with fewer colours leaves unused stay 0 (transparent), and FFmpeg's
    /// encoder takes one of them to mark pixels unchanged since the previous frame.
    [[nodiscard]] const std::array<std::uint32_t, kColours>& argb() const { return argb_; }

private:
    std::array<std::uint32_t, kColours> argb_{};
    std::vector<std::uint8_t> nearest_;  ///< Per 5-bit RGB cell, the index of the nearest colour.
};

}  // namespace throng::render
