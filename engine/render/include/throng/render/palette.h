#pragma once
// The baked clips on the GPU: every clip's poses in one device-local storage buffer (uploaded
// once through a staging buffer), plus the clip table, per-joint sphere radii and per-joint
// level-of-detail and foot information.

#include <span>
#include <vector>

#include "throng/gpu/resources.h"
#include "throng/render/gpu_types.h"

namespace throng::render {

/// Per joint of `clip`, what shaders/bindings.glsl's jointInfo holds: bit 0 jointDetail; bits
/// 8-9 footLeg (0, or 1 + the leg whose foot the joint is in). The legs' ankles are ClipGpu's.
[[nodiscard]] std::vector<std::uint32_t> packJointInfo(const motion::BakedClip& clip);

/// `clip`'s body (BakedClip::body) as shaders/gpu_types.glsl's bone table, with each part's
/// clothing and flattening.
[[nodiscard]] std::vector<BoneGpu> packBodyBones(const motion::BakedClip& clip);

class Palette {
public:
    /// Uploads `clips`. Throws ThrongException (BadInput) if the poses don't fit the device's
    /// maxStorageBufferRange, naming both sizes.
    Palette(const gpu::Context& context, std::span<const motion::BakedClip> clips);

    [[nodiscard]] const gpu::Buffer& poses() const { return poses_; }
    [[nodiscard]] const gpu::Buffer& clips() const { return clips_; }
    [[nodiscard]] const gpu::Buffer& jointRadii() const { return jointRadii_; }
    /// Per joint (indexed like jointRadii), packJointInfo's level of detail and foot; after
    /// every clip's, each clip's list of the joints a distant character keeps (ClipGpu::firstCoarseJoint).
    [[nodiscard]] const gpu::Buffer& jointInfo() const { return jointInfo_; }
    /// Every clip's body bones (packBodyBones), from ClipGpu::firstBone.
    [[nodiscard]] const gpu::Buffer& bones() const { return bones_; }
    /// The most bones any clip's body has: room per character for bone bodies.
    [[nodiscard]] std::uint32_t bonesPerCharacter() const { return bonesPerCharacter_; }
    /// k: the largest joint count of any clip; every character gets k instances.
    [[nodiscard]] std::uint32_t jointsPerCharacter() const { return jointsPerCharacter_; }
    [[nodiscard]] std::size_t poseBytes() const { return poseBytes_; }
    /// Skinned bodies: per distinct skeleton (ClipGpu::skeleton), the first clip that has it.
    [[nodiscard]] const std::vector<std::size_t>& skeletonClips() const { return skeletonClips_; }
    /// Per clip, its skeleton (ClipGpu::skeleton).
    [[nodiscard]] const std::vector<std::uint32_t>& clipSkeletons() const { return clipSkeletons_; }
    /// Tallest skeleton of any clip, metres (bounds characters for culling).
    [[nodiscard]] float maxHeight() const { return maxHeight_; }

private:
    gpu::Buffer poses_, clips_, jointRadii_, jointInfo_, bones_;
    std::uint32_t jointsPerCharacter_ = 0;
    std::uint32_t bonesPerCharacter_ = 0;
    std::size_t poseBytes_ = 0;
    std::vector<std::size_t> skeletonClips_;
    std::vector<std::uint32_t> clipSkeletons_;
    float maxHeight_ = 0.0F;
};

}  // namespace throng::render
