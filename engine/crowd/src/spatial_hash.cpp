#include "throng/crowd/spatial_hash.h"

#include <algorithm>
#include <cmath>

namespace throng::crowd {

void SpatialHash::build(std::span<const glm::vec2> positions, float cellSize) {
    positions_ = positions;
    sorted_.resize(positions.size());
    cellOf_.resize(positions.size());
    if (positions.empty()) return;
    // The grid covers the bounding box, kept within +-1e30 so its extent stays finite; points
    // beyond it (or NaN) still land in the edge cells, where queries find them.
    constexpr float kLargest = 1e30F;
    glm::vec2 lo(kLargest), hi(-kLargest);
    for (const glm::vec2& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    lo = glm::clamp(lo, -kLargest, kLargest);
    hi = glm::clamp(hi, lo, glm::vec2(kLargest));
    // Grow cells if a scattered crowd would need an absurd grid; queries stay correct, only slower.
    constexpr int kMaxCellsPerSide = 2048;
    const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
    cellSize = std::max({cellSize, extent / static_cast<float>(kMaxCellsPerSide), 1e-3F});
    origin_ = lo;
    inverseCell_ = 1.0F / cellSize;
    columns_ = clampedFloor<int>((hi.x - lo.x) * inverseCell_, 0, kMaxCellsPerSide) + 1;
    rows_ = clampedFloor<int>((hi.y - lo.y) * inverseCell_, 0, kMaxCellsPerSide) + 1;
    cellStart_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        cellOf_[i] = static_cast<std::uint32_t>(cellY(positions[i].y) * columns_ + cellX(positions[i].x));
        ++cellStart_[cellOf_[i] + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    // Stable placement keeps indices ascending inside each cell, so queries are deterministic.
    cursor_.assign(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t i = 0; i < positions.size(); ++i) sorted_[cursor_[cellOf_[i]]++] = static_cast<std::uint32_t>(i);
}

}  // namespace throng::crowd
