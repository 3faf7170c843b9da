#pragma once
// Surface nets (Gibson 1998): a closed triangle mesh of the zero set of a sampled signed
// distance field, one vertex per grid cell the surface crosses (the mean of its edge
// crossings) and one quad per grid edge it crosses, joining the four cells around that edge.
// The field must be positive (outside) on the grid's border, so the mesh is watertight.

#include <cstdint>
#include <vector>

#include "throng/core/math.h"

namespace throng::motion::detail {

/// Samples of a field on a regular grid: point (i, j, k) is origin + cell * (i, j, k).
struct DistanceGrid {
    glm::ivec3 size{0};     ///< Points along each axis.
    glm::vec3 origin{0.0F};
    float cell = 1.0F;
    std::vector<float> values;  ///< x fastest, then y, then z. Negative inside.

    [[nodiscard]] std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) + static_cast<std::size_t>(size.x) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(size.y) * static_cast<std::size_t>(k));
    }
    [[nodiscard]] float at(int i, int j, int k) const { return values[index(i, j, k)]; }
};

struct NetMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;  ///< Triangles, counter-clockwise seen from outside.
};

/// The grid is taken by value: faces whose corners alternate in sign are first resolved by
/// nudging a corner across, so every mesh edge joins exactly two triangles.
[[nodiscard]] NetMesh surfaceNets(DistanceGrid grid);

}  // namespace throng::motion::detail
