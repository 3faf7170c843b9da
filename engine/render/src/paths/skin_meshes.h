#pragma once
// Skinned bodies on the GPU (--body skin, and auto's nearest level): one generated mesh per
// skeleton (motion::makeBodyMesh), in one vertex and one index buffer, plus every clip's bind
// pose per joint, indexed like the joint radii (ClipGpu::firstJoint). Meshes are made once
// per skeleton per process and kept, so rebuilding a renderer (the demo's B key) is quick.

#include <span>
#include <vector>

#include "throng/gpu/resources.h"
#include "throng/render/gpu_types.h"
#include "throng/render/palette.h"

namespace throng::render::detail {

class SkinMeshes {
public:
    SkinMeshes(const gpu::Context& context, std::span<const motion::BakedClip> clips, const Palette& palette);

    [[nodiscard]] const gpu::Buffer& vertices() const { return vertices_; }
    [[nodiscard]] const gpu::Buffer& indices() const { return indices_; }
    [[nodiscard]] const gpu::Buffer& bindPoses() const { return bindPoses_; }
    /// Per skeleton, its mesh's draw with no instances and firstInstance 0.
    [[nodiscard]] const std::vector<SkinDrawGpu>& draws() const { return draws_; }

private:
    gpu::Buffer vertices_, indices_, bindPoses_;
    std::vector<SkinDrawGpu> draws_;
};

}  // namespace throng::render::detail
