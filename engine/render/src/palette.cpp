#include "throng/render/palette.h"

namespace throng::render {

std::vector<std::uint32_t> packJointInfo(const motion::BakedClip& clip) {
    std::vector<std::uint32_t> info(static_cast<std::size_t>(clip.jointCount()), 0U);
    for (std::size_t j = 0; j < info.size(); ++j) {
        const std::uint32_t leg = clip.footLeg.empty() ? 0U : clip.footLeg[j];
        const std::uint32_t ankle = leg == 0 ? 0U : static_cast<std::uint32_t>(clip.anatomy.legs[leg - 1].ankle);
        info[j] = (clip.jointDetail.empty() ? 0U : clip.jointDetail[j] & 1U) | (leg << 8U) | (ankle << 10U);
    }
    return info;
}

Palette::Palette(const gpu::Context& context, std::span<const motion::BakedClip> clips) {
    std::vector<motion::JointPose> poses;
    std::vector<ClipGpu> table;
    std::vector<float> radii;
    std::vector<std::uint32_t> jointInfo;
    for (const motion::BakedClip& clip : clips) {
        table.push_back({static_cast<std::uint32_t>(poses.size()), static_cast<std::uint32_t>(clip.jointCount()),
                         static_cast<std::uint32_t>(clip.frameCount), static_cast<std::uint32_t>(radii.size())});
        poses.insert(poses.end(), clip.poses.begin(), clip.poses.end());
        radii.insert(radii.end(), clip.jointRadius.begin(), clip.jointRadius.end());
        const std::vector<std::uint32_t> info = packJointInfo(clip);
        jointInfo.insert(jointInfo.end(), info.begin(), info.end());
        jointsPerCharacter_ = std::max(jointsPerCharacter_, static_cast<std::uint32_t>(clip.jointCount()));
        maxHeight_ = std::max(maxHeight_, static_cast<float>(clip.stature));
    }
    poseBytes_ = poses.size() * sizeof(motion::JointPose);
    const vk::DeviceSize limit = context.limits().maxStorageBufferRange;
    if (poseBytes_ > limit)
        throw ThrongException(Error{Error::Kind::BadInput,
                                    "the baked clips need " + std::to_string(poseBytes_) + " bytes of poses, over this device's " +
                                        std::to_string(limit) + "-byte storage buffer limit (use fewer or shorter clips)",
                                    {}});
    const auto storage = vk::BufferUsageFlagBits::eStorageBuffer;
    poses_ = gpu::Buffer(context, {.size = poseBytes_, .usage = storage, .intent = gpu::MemoryIntent::DeviceLocal});
    clips_ = gpu::Buffer(context, {.size = table.size() * sizeof(ClipGpu), .usage = storage, .intent = gpu::MemoryIntent::DeviceLocal});
    jointRadii_ = gpu::Buffer(context, {.size = radii.size() * sizeof(float), .usage = storage, .intent = gpu::MemoryIntent::DeviceLocal});
    gpu::uploadToDeviceLocal(context, poses_, std::as_bytes(std::span(poses)));
    gpu::uploadToDeviceLocal(context, clips_, std::as_bytes(std::span(table)));
    gpu::uploadToDeviceLocal(context, jointRadii_, std::as_bytes(std::span(radii)));
    jointInfo_ = gpu::Buffer(context, {.size = jointInfo.size() * sizeof(std::uint32_t), .usage = storage, .intent = gpu::MemoryIntent::DeviceLocal});
    gpu::uploadToDeviceLocal(context, jointInfo_, std::as_bytes(std::span(jointInfo)));
}

}  // namespace throng::render
