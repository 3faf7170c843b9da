#include "surface_nets.h"

#include <array>
#include <cmath>

namespace throng::motion::detail {
namespace {

glm::vec3 cornerOffset(int corner) { return {static_cast<float>(corner & 1), static_cast<float>((corner >> 1) & 1), static_cast<float>((corner >> 2) & 1)}; }

// The twelve edges of a cell, as pairs of corners (bit 0: +x, bit 1: +y, bit 2: +z).
constexpr std::array<std::array<int, 2>, 12> kCellEdges = [] {
    std::array<std::array<int, 2>, 12> edges{};
    std::size_t n = 0;
    for (int corner = 0; corner < 8; ++corner)
        for (int bit = 1; bit < 8; bit <<= 1)
            if ((corner & bit) == 0) edges[n++] = {corner, corner | bit};
    return edges;
}();

// Each cell the surface crosses gets a vertex at the mean of its edges' crossings; -1 elsewhere.
std::vector<std::int32_t> placeVertices(const DistanceGrid& grid, glm::ivec3 cells, std::vector<glm::vec3>& positions) {
    std::vector<std::int32_t> cellVertex(static_cast<std::size_t>(cells.x) * static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(cells.z), -1);
    std::size_t cellIndex = 0;
    for (int k = 0; k < cells.z; ++k)
        for (int j = 0; j < cells.y; ++j)
            for (int i = 0; i < cells.x; ++i, ++cellIndex) {
                std::array<float, 8> value{};
                int inside = 0;
                for (int c = 0; c < 8; ++c) {
                    value[static_cast<std::size_t>(c)] = grid.at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                    inside += value[static_cast<std::size_t>(c)] < 0.0F ? 1 : 0;
                }
                if (inside == 0 || inside == 8) continue;
                glm::vec3 sum(0.0F);
                int crossings = 0;
                for (const auto& [a, b] : kCellEdges) {
                    const float va = value[static_cast<std::size_t>(a)], vb = value[static_cast<std::size_t>(b)];
                    if ((va < 0.0F) == (vb < 0.0F)) continue;
                    const float t = va / (va - vb);
                    sum += glm::mix(cornerOffset(a), cornerOffset(b), t);
                    ++crossings;
                }
                cellVertex[cellIndex] = static_cast<std::int32_t>(positions.size());
                positions.push_back(grid.origin + grid.cell * (glm::vec3(i, j, k) + sum / static_cast<float>(crossings)));
            }
    return cellVertex;
}

// A grid face whose corners alternate in sign (a saddle) would join four quads along one
// edge of the mesh. Such a face is resolved by moving its corner nearest the surface to the
// other side (by a hair, so the crossings barely move), until no face is ambiguous.
void resolveSaddles(DistanceGrid& grid) {
    constexpr float kHair = 1e-7F;
    for (int pass = 0; pass < 16; ++pass) {
        int changed = 0;
        for (int k = 0; k < grid.size.z; ++k)
            for (int j = 0; j < grid.size.y; ++j)
                for (int i = 0; i < grid.size.x; ++i)
                    for (int a = 0; a < 3; ++a) {  // the face across axis a at point (i, j, k)
                        glm::ivec3 p(i, j, k), eb(0), ec(0);
                        eb[(a + 1) % 3] = 1;
                        ec[(a + 2) % 3] = 1;
                        const glm::ivec3 far = p + eb + ec;
                        if (far.x >= grid.size.x || far.y >= grid.size.y || far.z >= grid.size.z) continue;
                        const std::array<std::size_t, 4> corner{grid.index(p.x, p.y, p.z), grid.index(p.x + eb.x, p.y + eb.y, p.z + eb.z),
                                                                grid.index(far.x, far.y, far.z), grid.index(p.x + ec.x, p.y + ec.y, p.z + ec.z)};
                        const auto inside = [&](std::size_t c) { return grid.values[corner[c]] < 0.0F; };
                        if (inside(0) != inside(2) || inside(1) != inside(3) || inside(0) == inside(1)) continue;
                        std::size_t nearest = 0;
                        for (std::size_t c = 1; c < 4; ++c)
                            if (std::abs(grid.values[corner[c]]) < std::abs(grid.values[corner[nearest]])) nearest = c;
                        float& value = grid.values[corner[nearest]];
                        value = value < 0.0F ? kHair : -kHair;
                        ++changed;
                    }
        if (changed == 0) return;
    }
}

}  // namespace

NetMesh surfaceNets(DistanceGrid grid) {
    NetMesh mesh;
    const glm::ivec3 cells = grid.size - 1;
    if (cells.x < 1 || cells.y < 1 || cells.z < 1) return mesh;
    resolveSaddles(grid);
    const std::vector<std::int32_t> cellVertex = placeVertices(grid, cells, mesh.positions);
    const auto vertexOf = [&](glm::ivec3 cell) {
        return static_cast<std::uint32_t>(cellVertex[static_cast<std::size_t>(cell.x) + static_cast<std::size_t>(cells.x) * (static_cast<std::size_t>(cell.y) + static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(cell.z))]);
    };
    // Every grid edge the surface crosses joins the four cells around it into a quad, wound
    // counter-clockwise seen from the outside end of the edge.
    for (int k = 0; k < grid.size.z; ++k)
        for (int j = 0; j < grid.size.y; ++j)
            for (int i = 0; i < grid.size.x; ++i) {
                const glm::ivec3 point(i, j, k);
                const bool inside = grid.at(i, j, k) < 0.0F;
                for (int a = 0; a < 3; ++a) {
                    const int b = (a + 1) % 3, c = (a + 2) % 3;
                    if (point[a] + 1 >= grid.size[a] || point[b] < 1 || point[c] < 1 || point[b] >= cells[b] || point[c] >= cells[c]) continue;
                    glm::ivec3 next = point;
                    ++next[a];
                    if (inside == (grid.at(next.x, next.y, next.z) < 0.0F)) continue;
                    glm::ivec3 eb(0), ec(0);
                    eb[b] = 1;
                    ec[c] = 1;
                    std::array<std::uint32_t, 4> quad{vertexOf(point - eb - ec), vertexOf(point - ec), vertexOf(point), vertexOf(point - eb)};
                    if (!inside) std::swap(quad[1], quad[3]);  // the outside is toward -a
                    const auto& p = mesh.positions;
                    const bool shortFirst = glm::distance(p[quad[0]], p[quad[2]]) <= glm::distance(p[quad[1]], p[quad[3]]);
                    const std::array<std::uint32_t, 6> triangles = shortFirst ? std::array<std::uint32_t, 6>{quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]}
                                                                              : std::array<std::uint32_t, 6>{quad[0], quad[1], quad[3], quad[1], quad[2], quad[3]};
                    mesh.indices.insert(mesh.indices.end(), triangles.begin(), triangles.end());
                }
            }
    return mesh;
}

}  // namespace throng::motion::detail
