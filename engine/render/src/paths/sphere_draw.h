#pragma once
// Instanced sphere meshes, drawn by the paper, cpu and compute paths: one mesh instance per
// joint, k instances per character.

#include <cstdint>
#include <vector>

#include "render_path_impl.h"

namespace throng::render::detail {

/// Unit UV sphere: positions (which are also normals) and counter-clockwise triangle indices.
struct SphereMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint16_t> indices;
};
[[nodiscard]] SphereMesh makeUnitSphere(std::uint32_t segments, std::uint32_t rings);

class SphereDraw {
public:
    /// A mesh of 12 segments by 8 rings, drawn with `vertexSpirv` and the Phong sphere shader.
    SphereDraw(const PathSetup& setup, std::span<const std::uint32_t> vertexSpirv);
    /// Draws characterCount × k spheres.
    void record(const vk::raii::CommandBuffer& commands, const SlotBuffers& slot, std::uint32_t jointsPerCharacter) const;

private:
    gpu::Buffer vertices_, indices_;
    std::uint32_t indexCount_ = 0;
    vk::raii::Pipeline pipeline_{nullptr};
};

}  // namespace throng::render::detail
