#include "throng/crowd/spatial_hash.h"

#include <algorithm>
#include <cmath>

namespace throng::crowd {

void SpatialHash::build(std::span<const glm::vec2> positions, float cellSize) {
    positions_ = positions;
    sorted_.resize(positions.size());
    cellOf_.resize(positions.size());
    if (positions.empty()) return;
    glm::vec2 lo(1e30F), hi(-1e30F);
    for (const glm::vec2& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Grow cells if a scattered crowd would need an absurd grid; queries stay correct, only slower.
    constexpr float kMaxCellsPerSide = 2048.0F;
    const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
    cellSize = std::max({cellSize, extent / kMaxCellsPerSide, 1e-3F});
    origin_ = lo;
    inverseCell_ = 1.0F / cellSize;
    columns_ = static_cast<int>((hi.x - lo.x) * inverseCell_) + 1;
    rows_ = static_cast<int>((hi.y - lo.y) * inverseCell_) + 1;
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
