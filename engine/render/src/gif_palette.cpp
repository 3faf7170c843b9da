#include "gif_palette.h"

#include <algorithm>
#include <limits>

namespace throng::render {
namespace {

constexpr int kLevels = 32;  // cells per channel of the histogram and of the lookup table
constexpr std::uint32_t kCells = kLevels * kLevels * kLevels;

std::uint32_t cellOf(int r, int g, int b) { return static_cast<std::uint32_t>((r >> 3) << 10 | (g >> 3) << 5 | (b >> 3)); }
int channelOf(std::uint32_t cell, int channel) { return static_cast<int>(cell >> (10 - 5 * channel)) & (kLevels - 1); }
int cellCentre(int level) { return level * 8 + 4; }  // the 8-bit value a cell stands for

// A box of occupied histogram cells; median cut splits the fullest boxes at their median.
struct Box {
    std::vector<std::uint32_t> cells;
    std::uint64_t pixels = 0;
    int widestChannel = 0;
    int width = 0;  ///< Levels spanned along widestChannel.
};

Box makeBox(std::vector<std::uint32_t> cells, const std::vector<std::uint32_t>& histogram) {
    Box box{std::move(cells)};
    std::array<int, 3> lo{kLevels, kLevels, kLevels}, hi{-1, -1, -1};
    for (const std::uint32_t cell : box.cells) {
        box.pixels += histogram[cell];
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], channelOf(cell, c));
            hi[c] = std::max(hi[c], channelOf(cell, c));
        }
    }
    for (int c = 0; c < 3; ++c)
        if (hi[c] - lo[c] > box.width) box.width = hi[c] - lo[c], box.widestChannel = c;
    return box;
}

}  // namespace

GifPalette::GifPalette(const std::uint8_t* rgba, std::uint32_t width, std::uint32_t height, std::size_t stride) : nearest_(kCells) {
    std::vector<std::uint32_t> histogram(kCells, 0);
    std::vector<std::array<std::uint64_t, 3>> sums(kCells, {0, 0, 0});  // the cell's pixels' own values, for exact means
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint8_t* p = rgba + y * stride + std::size_t{x} * 4;
            const std::uint32_t cell = cellOf(p[0], p[1], p[2]);
            ++histogram[cell];
            for (std::size_t c = 0; c < 3; ++c) sums[cell][c] += p[c];
        }
    std::vector<std::uint32_t> occupied;
    for (std::uint32_t cell = 0; cell < kCells; ++cell)
        if (histogram[cell] > 0) occupied.push_back(cell);
    std::vector<Box> boxes{makeBox(std::move(occupied), histogram)};
    // Split the box with the most pixels among those that can split, at its pixels' median
    // along its widest channel (ties to the lower index: the same frame, the same palette).
    while (boxes.size() < kColours) {
        std::size_t chosen = boxes.size();
        for (std::size_t b = 0; b < boxes.size(); ++b)
            if (boxes[b].cells.size() > 1 && boxes[b].width > 0 && (chosen == boxes.size() || boxes[b].pixels > boxes[chosen].pixels))
                chosen = b;
        if (chosen == boxes.size()) break;
        Box& box = boxes[chosen];
        const int channel = box.widestChannel;
        std::sort(box.cells.begin(), box.cells.end(), [&](std::uint32_t a, std::uint32_t b) {
            return channelOf(a, channel) != channelOf(b, channel) ? channelOf(a, channel) < channelOf(b, channel) : a < b;
        });
        std::uint64_t below = 0;
        std::size_t split = 1;
        for (; split < box.cells.size() - 1; ++split) {
            below += histogram[box.cells[split - 1]];
            if (2 * below >= box.pixels) break;
        }
        std::vector<std::uint32_t> upper(box.cells.begin() + static_cast<std::ptrdiff_t>(split), box.cells.end());
        box.cells.resize(split);
        box = makeBox(std::move(box.cells), histogram);
        boxes.push_back(makeBox(std::move(upper), histogram));
    }
    std::array<std::array<int, 3>, kColours> colours{};
    for (std::size_t b = 0; b < boxes.size(); ++b) {
        std::array<std::uint64_t, 3> sum{};
        for (const std::uint32_t cell : boxes[b].cells)
            for (std::size_t c = 0; c < 3; ++c) sum[c] += sums[cell][c];
        const std::uint64_t pixels = std::max<std::uint64_t>(boxes[b].pixels, 1);
        for (std::size_t c = 0; c < 3; ++c) colours[b][c] = static_cast<int>((sum[c] + pixels / 2) / pixels);  // rounded mean
        argb_[b] = 0xFF000000U | static_cast<std::uint32_t>(colours[b][0]) << 16 | static_cast<std::uint32_t>(colours[b][1]) << 8 |
                   static_cast<std::uint32_t>(colours[b][2]);
    }
    for (std::uint32_t cell = 0; cell < kCells; ++cell) {
        int best = std::numeric_limits<int>::max();
        for (std::size_t b = 0; b < boxes.size(); ++b) {
            int distance = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = cellCentre(channelOf(cell, c)) - colours[b][static_cast<std::size_t>(c)];
                distance += d * d;
            }
            if (distance < best) best = distance, nearest_[cell] = static_cast<std::uint8_t>(b);
        }
    }
}

void GifPalette::map(const std::uint8_t* rgba, std::uint32_t width, std::uint32_t height, std::size_t stride, std::uint8_t* indices,
                     std::size_t indexStride) const {
    // Bayer's 4 x 4 thresholds, centred, in eighths of a cell.
    constexpr std::array<int, 16> kBayer{0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint8_t* p = rgba + y * stride + std::size_t{x} * 4;
            const int offset = kBayer[(y & 3U) * 4 + (x & 3U)] / 2 - 4;  // -4 .. 3: half a cell either way
            const auto dithered = [&](int channel) { return std::clamp(int{p[channel]} + offset, 0, 255); };
            indices[y * indexStride + x] = nearest_[cellOf(dithered(0), dithered(1), dithered(2))];
        }
}

}  // namespace throng::render
