#include "skin_meshes.h"

#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace throng::render::detail {
namespace {

// Meshes already made in this process, by skeleton: the clip's name and every joint's name,
// parent and bind position (two clips that agree on all of it have the same body).
std::shared_ptr<const motion::BodyMesh> meshFor(const motion::BakedClip& clip) {
    static std::mutex guard;
    static std::map<std::string, std::shared_ptr<const motion::BodyMesh>> made;
    std::string key;
    const std::vector<motion::JointPose> bind = motion::bodyBindPose(clip);
    for (std::size_t j = 0; j < bind.size(); ++j) {
        const glm::vec3 at = bind[j].translation;
        key += clip.jointNames[j] + '/' + std::to_string(clip.parents[j]) + '/' + std::to_string(at.x) + ',' + std::to_string(at.y) + ',' +
               std::to_string(at.z) + ';';
    }
    for (const motion::BodyBone& bone : clip.body) key += std::to_string(bone.radiusStart) + ',' + std::to_string(bone.radiusEnd) + ';';
    const std::lock_guard lock(guard);
    auto& mesh = made[key];
    if (!mesh) mesh = std::make_shared<const motion::BodyMesh>(motion::makeBodyMesh(clip));
    return mesh;
}

}  // namespace

SkinMeshes::SkinMeshes(const gpu::Context& context, std::span<const motion::BakedClip> clips, const Palette& palette) {
    std::vector<std::shared_ptr<const motion::BodyMesh>> meshes;
    std::vector<motion::SkinVertex> vertices;
    std::vector<std::uint32_t> indices;
    for (const std::size_t first : palette.skeletonClips()) {
        meshes.push_back(meshFor(clips[first]));
        const motion::BodyMesh& mesh = *meshes.back();
        draws_.push_back({.indexCount = static_cast<std::uint32_t>(mesh.indices.size()), .instanceCount = 0,
                          .firstIndex = static_cast<std::uint32_t>(indices.size()),
                          .vertexOffset = static_cast<std::int32_t>(vertices.size()), .firstInstance = 0});
        vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    // Every clip's joints take their skeleton's bind pose, in joint-radius order.
    std::vector<motion::JointPose> bind;
    for (const std::uint32_t skeleton : palette.clipSkeletons()) {
        const std::vector<motion::JointPose>& pose = meshes.at(skeleton)->bind;
        bind.insert(bind.end(), pose.begin(), pose.end());
    }
    if (vertices.empty()) vertices.emplace_back();  // buffers need a size; no draw reads them
    if (indices.empty()) indices.push_back(0);
    if (bind.empty()) bind.emplace_back();
    using Usage = vk::BufferUsageFlagBits;
    vertices_ = gpu::Buffer(context, {.size = vertices.size() * sizeof(motion::SkinVertex), .usage = Usage::eVertexBuffer,
                                      .intent = gpu::MemoryIntent::DeviceLocal});
    indices_ = gpu::Buffer(context, {.size = indices.size() * sizeof(std::uint32_t), .usage = Usage::eIndexBuffer,
                                     .intent = gpu::MemoryIntent::DeviceLocal});
    bindPoses_ = gpu::Buffer(context, {.size = bind.size() * sizeof(motion::JointPose), .usage = Usage::eStorageBuffer,
                                       .intent = gpu::MemoryIntent::DeviceLocal});
    gpu::uploadToDeviceLocal(context, vertices_, std::as_bytes(std::span(vertices)));
    gpu::uploadToDeviceLocal(context, indices_, std::as_bytes(std::span(indices)));
    gpu::uploadToDeviceLocal(context, bindPoses_, std::as_bytes(std::span(bind)));
}

}  // namespace throng::render::detail
