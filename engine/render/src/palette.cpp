#include "throng/render/palette.h"

namespace throng::render {

std::vector<std::uint32_t> packJointInfo(const motion::BakedClip& clip) {
    std::vector<std::uint32_t> info(static_cast<std::size_t>(clip.jointCount()), 0U);
    for (std::size_t j = 0; j < info.size(); ++j) {
        const std::uint32_t leg = clip.footLeg.empty() ? 0U : clip.footLeg[j];
        info[j] = (clip.jointDetail.empty() ? 0U : clip.jointDetail[j] & 1U) | (leg << 8U);
    }
    return info;
}

namespace {

// Leg l's ankle joint, about which its foot joints (BakedClip::footLeg) twist (0 when there is none).
std::uint32_t ankleOf(const motion::BakedClip& clip, std::size_t leg) {
    return leg < clip.anatomy.legs.size() && clip.anatomy.legs[leg].ankle >= 0 ? static_cast<std::uint32_t>(clip.anatomy.legs[leg].ankle) : 0U;
}

}  // namespace

std::vector<BoneGpu> packBodyBones(const motion::BakedClip& clip) {
    using Part = motion::BodyPart;
    constexpr std::uint32_t kSkin = 0, kShirt = 1, kTrousers = 2, kShoes = 3, kSole = 1U << 8U, kPalm = 2U << 8U, kTrunk = 3U << 8U;
    const auto look = [](Part part) -> std::uint32_t {
        switch (part) {
            case Part::Neck: case Part::Head: case Part::Finger: return kSkin;
            case Part::Hand: return kSkin | kPalm;
            case Part::Hips: return kTrousers | kTrunk;
            case Part::Spine: return kShirt | kTrunk;
            case Part::Thigh: case Part::Shin: return kTrousers;
            case Part::Foot: case Part::Toe: return kShoes | kSole;
            default: return kShirt;
        }
    };
    std::vector<BoneGpu> bones;
    for (const motion::BodyBone& bone : clip.body)
        bones.push_back({.tipOffset = glm::vec4(bone.tip, 0.0F), .joint = static_cast<std::uint32_t>(bone.joint),
                         .child = bone.child < 0 ? kBoneToEndSite : static_cast<std::uint32_t>(bone.child),
                         .radiusStart = bone.radiusStart, .radiusEnd = bone.radiusEnd, .look = look(bone.part),
                         .thickness = bone.thickness, .pad = {}});
    return bones;
}

namespace {

bool sameSkeleton(const motion::BakedClip& a, const motion::BakedClip& b) {
    if (a.jointNames != b.jointNames || a.parents != b.parents || a.body.size() != b.body.size()) return false;
    for (std::size_t i = 0; i < a.body.size(); ++i) {
        const motion::BodyBone &x = a.body[i], &y = b.body[i];
        if (x.joint != y.joint || x.child != y.child || x.tip != y.tip || x.radiusStart != y.radiusStart || x.radiusEnd != y.radiusEnd) return false;
    }
    // The same bind pose too: the offsets as played.
    const auto offsets = [](const motion::BakedClip& clip, std::size_t j) {
        const int first = clip.loop().first;
        const motion::JointPose& here = clip.pose(first, static_cast<int>(j));
        const motion::JointPose& parent = clip.pose(first, clip.parents[j]);
        return glm::inverse(parent.rotation) * (here.translation - parent.translation);
    };
    for (std::size_t j = 0; j < a.parents.size(); ++j)
        if (a.parents[j] >= 0 && glm::distance(offsets(a, j), offsets(b, j)) > 1e-4F) return false;
    return true;
}

}  // namespace

Palette::Palette(const gpu::Context& context, std::span<const motion::BakedClip> clips) {
    std::vector<motion::JointPose> poses;
    std::vector<ClipGpu> table;
    std::vector<float> radii;
    std::vector<std::uint32_t> jointInfo;
    std::vector<BoneGpu> bones;
    std::vector<std::uint32_t> coarseJoints;  // per clip, the joints a distant character keeps, after every clip's info
    for (const motion::BakedClip& clip : clips) {
        const std::vector<BoneGpu> body = packBodyBones(clip);
        // Clips of one skeleton (the same joints, tree and body) share a skinned mesh.
        std::uint32_t skeleton = 0;
        while (skeleton < skeletonClips_.size() && !sameSkeleton(clips[skeletonClips_[skeleton]], clip)) ++skeleton;
        if (skeleton == skeletonClips_.size()) skeletonClips_.push_back(static_cast<std::size_t>(&clip - clips.data()));
        clipSkeletons_.push_back(skeleton);
        const auto firstCoarse = static_cast<std::uint32_t>(coarseJoints.size());
        for (int j = 0; j < clip.jointCount(); ++j)
            if (clip.jointDetail.empty() || clip.jointDetail[static_cast<std::size_t>(j)] == 0) coarseJoints.push_back(static_cast<std::uint32_t>(j));
        table.push_back({.firstPose = static_cast<std::uint32_t>(poses.size()), .jointCount = static_cast<std::uint32_t>(clip.jointCount()),
                         .frameCount = static_cast<std::uint32_t>(clip.frameCount), .firstJoint = static_cast<std::uint32_t>(radii.size()),
                         .firstBone = static_cast<std::uint32_t>(bones.size()), .boneCount = static_cast<std::uint32_t>(body.size()),
                         .skeleton = skeleton, .coarseJointCount = static_cast<std::uint32_t>(coarseJoints.size()) - firstCoarse,
                         .firstCoarseJoint = firstCoarse, .leftAnkle = ankleOf(clip, 0), .rightAnkle = ankleOf(clip, 1)});
        bones.insert(bones.end(), body.begin(), body.end());
        bonesPerCharacter_ = std::max(bonesPerCharacter_, static_cast<std::uint32_t>(body.size()));
        poses.insert(poses.end(), clip.poses.begin(), clip.poses.end());
        radii.insert(radii.end(), clip.jointRadius.begin(), clip.jointRadius.end());
        const std::vector<std::uint32_t> info = packJointInfo(clip);
        jointInfo.insert(jointInfo.end(), info.begin(), info.end());
        jointsPerCharacter_ = std::max(jointsPerCharacter_, static_cast<std::uint32_t>(clip.jointCount()));
        maxHeight_ = std::max(maxHeight_, static_cast<float>(clip.stature));
    }
    // The coarse lists follow every clip's per-joint info, each clip's start shifted to match.
    for (ClipGpu& clip : table) clip.firstCoarseJoint += static_cast<std::uint32_t>(jointInfo.size());
    jointInfo.insert(jointInfo.end(), coarseJoints.begin(), coarseJoints.end());
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
    if (bones.empty()) bones.emplace_back();  // a buffer needs a size; boneCount 0 reads none
    bones_ = gpu::Buffer(context, {.size = bones.size() * sizeof(BoneGpu), .usage = storage, .intent = gpu::MemoryIntent::DeviceLocal});
    gpu::uploadToDeviceLocal(context, bones_, std::as_bytes(std::span(bones)));
}

}  // namespace throng::render
