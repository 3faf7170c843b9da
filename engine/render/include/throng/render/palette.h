#pragma once
// The baked clips on the GPU: every clip's poses in one device-local storage buffer (uploaded
// once through a staging buffer), plus the clip table and per-joint sphere radii.

#include <span>

#include "throng/gpu/resources.h"
#include "throng/render/gpu_types.h"

namespace throng::render {

class Palette {
public:
    /// Uploads `clips`. Throws ThrongException (BadInput) if the poses don't fit the device's
    /// maxStorageBufferRange, naming both sizes.
    Palette(const gpu::Context& context, std::span<const motion::BakedClip> clips);

    [[nodiscard]] const gpu::Buffer& poses() const { return poses_; }
    [[nodiscard]] const gpu::Buffer& clips() const { return clips_; }
    [[nodiscard]] const gpu::Buffer& jointRadii() const { return jointRadii_; }
    /// Per joint (indexed like jointRadii), 1 when distant characters may leave it out.
    [[nodiscard]] const gpu::Buffer& jointDetail() const { return jointDetail_; }
    /// k: the largest joint count of any clip; every character gets k instances.
    [[nodiscard]] std::uint32_t jointsPerCharacter() const { return jointsPerCharacter_; }
    [[nodiscard]] std::size_t poseBytes() const { return poseBytes_; }
    /// Tallest skeleton of any clip, metres (bounds characters for culling).
    [[nodiscard]] float maxHeight() const { return maxHeight_; }

private:
    gpu::Buffer poses_, clips_, jointRadii_, jointDetail_;
    std::uint32_t jointsPerCharacter_ = 0;
    std::size_t poseBytes_ = 0;
    float maxHeight_ = 0.0F;
};

}  // namespace throng::render
