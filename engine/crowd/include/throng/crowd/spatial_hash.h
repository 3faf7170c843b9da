#pragma once
// A uniform grid over the ground for neighbour queries: rebuilt from scratch each step with a
// counting sort (O(n), no allocation once warm), then queried cell by cell.

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "throng/core/math.h"

namespace throng::crowd {

class SpatialHash {
public:
    /// Sorts `positions` into cells of `cellSize` metres covering their bounding box.
    void build(std::span<const glm::vec2> positions, float cellSize);

    /// Point indices in cell order: each cell's points are contiguous, so data copied into
    /// this order is scanned with sequential reads.
    [[nodiscard]] std::span<const std::uint32_t> sorted() const { return sorted_; }

    /// Calls visit(begin, end) with each range [begin, end) of sorted() positions whose cells
    /// overlap the square of half-side `radius` around `centre`; callers filter by distance.
    template <typename Visit>
    void forEachCellRange(glm::vec2 centre, float radius, Visit&& visit) const {
        if (sorted_.empty()) return;
        const int x0 = cellX(centre.x - radius), x1 = cellX(centre.x + radius);
        const int y0 = cellY(centre.y - radius), y1 = cellY(centre.y + radius);
        for (int y = y0; y <= y1; ++y) {
            // Cells of one row are adjacent in sorted order: one range per row.
            const std::size_t row = static_cast<std::size_t>(y) * columns_;
            visit(cellStart_[row + static_cast<std::size_t>(x0)], cellStart_[row + static_cast<std::size_t>(x1) + 1]);
        }
    }

    /// Calls visit(index) for every point within `radius` of `centre` (the point itself too).
    template <typename Visit>
    void forEachWithin(glm::vec2 centre, float radius, Visit&& visit) const {
        if (sorted_.empty()) return;
        const float radiusSq = radius * radius;
        const int x0 = cellX(centre.x - radius), x1 = cellX(centre.x + radius);
        const int y0 = cellY(centre.y - radius), y1 = cellY(centre.y + radius);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const std::size_t cell = static_cast<std::size_t>(y) * columns_ + static_cast<std::size_t>(x);
                for (std::uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
                    const std::uint32_t index = sorted_[k];
                    const glm::vec2 d = positions_[index] - centre;
                    if (glm::dot(d, d) <= radiusSq) visit(index);
                }
            }
    }

private:
    // Any float, NaN and infinities included, lands in a valid cell (clampedFloor): a cast of
    // an out-of-range float to int would be undefined behaviour.
    [[nodiscard]] int cellX(float x) const { return clampedFloor<int>((x - origin_.x) * inverseCell_, 0, columns_ - 1); }
    [[nodiscard]] int cellY(float y) const { return clampedFloor<int>((y - origin_.y) * inverseCell_, 0, rows_ - 1); }

    std::span<const glm::vec2> positions_;
    glm::vec2 origin_{0.0F};
    float inverseCell_ = 1.0F;
    int columns_ = 1, rows_ = 1;
    std::vector<std::uint32_t> cellStart_;  ///< Prefix sums: points of cell c are sorted_[cellStart_[c] .. cellStart_[c+1]).
    std::vector<std::uint32_t> sorted_;
    std::vector<std::uint32_t> cellOf_;
    std::vector<std::uint32_t> cursor_;
};

}  // namespace throng::crowd
