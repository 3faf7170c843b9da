#pragma once
// C++ mirrors of the GPU-shared structs in shaders/gpu_types.glsl (std430 / std140). The
// static_asserts keep the two declarations in step: change one, change both.

#include <array>
#include <cstddef>
#include <cstdint>

#include "throng/core/math.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/body_mesh.h"

namespace throng::render {

struct ClipGpu {
    std::uint32_t firstPose = 0;   ///< Index of frame 0, joint 0 in the pose array.
    std::uint32_t jointCount = 0;
    std::uint32_t frameCount = 0;
    std::uint32_t firstJoint = 0;  ///< Index of joint 0 in the joint-radius array.
    std::uint32_t firstBone = 0;   ///< Index of the clip's first bone in the bone table.
    std::uint32_t boneCount = 0;
    std::uint32_t skeleton = 0;    ///< Skinned bodies: the clip's skeleton, its mesh's index (clips of one skeleton share it).
    std::uint32_t coarseJointCount = 0;  ///< Joints a distant character keeps (those not BakedClip::jointDetail).
    std::uint32_t firstCoarseJoint = 0;  ///< Index in the joint-info array of the list of those joints, ascending.
    std::uint32_t leftAnkle = 0;   ///< The legs' ankle joints (motion::Anatomy::legs), about which a foot twists;
    std::uint32_t rightAnkle = 0;  ///< 0 for a skeleton without legs (whose feet never twist).
    std::uint32_t pad = 0;
};
static_assert(sizeof(ClipGpu) == 48);
static_assert(offsetof(ClipGpu, coarseJointCount) == 28);
static_assert(offsetof(ClipGpu, firstCoarseJoint) == 32);
static_assert(offsetof(ClipGpu, leftAnkle) == 36);
static_assert(offsetof(ClipGpu, skeleton) == 24);
static_assert(offsetof(ClipGpu, firstBone) == 16);
static_assert(offsetof(ClipGpu, boneCount) == 20);
static_assert(offsetof(ClipGpu, firstPose) == 0);
static_assert(offsetof(ClipGpu, jointCount) == 4);
static_assert(offsetof(ClipGpu, frameCount) == 8);
static_assert(offsetof(ClipGpu, firstJoint) == 12);

/// BoneGpu.child of a bone that ends at its tip offset (an End Site) instead of a joint.
inline constexpr std::uint32_t kBoneToEndSite = 0xffffffffU;

/// One bone of a clip's body (shaders/gpu_types.glsl BoneGpu).
struct BoneGpu {
    glm::vec4 tipOffset{0.0F};   ///< xyz: the bone's end in its joint's frame when child is kBoneToEndSite (metres).
    std::uint32_t joint = 0;
    std::uint32_t child = kBoneToEndSite;
    float radiusStart = 0.0F;
    float radiusEnd = 0.0F;
    std::uint32_t look = 0;      ///< Bits 0-1 clothing (0 skin, 1 shirt, 2 trousers, 3 shoes); bits 8-9 flattening (1 sole, 2 palm, 3 trunk).
    float thickness = 1.0F;
    float pad[2]{};
};
static_assert(sizeof(BoneGpu) == 48);
static_assert(offsetof(BoneGpu, joint) == 16);
static_assert(offsetof(BoneGpu, look) == 32);
static_assert(offsetof(BoneGpu, thickness) == 36);

/// One bone of one visible character (shaders/gpu_types.glsl BoneInstanceGpu).
struct BoneInstanceGpu {
    glm::vec4 start;    ///< World position and radius at the bone's start.
    glm::vec4 end;      ///< World position and radius at its end.
    glm::vec4 flatten;  ///< Unit axis and thickness over width (1: round).
    glm::vec4 color;    ///< Linear RGB, a = 1.
};
static_assert(sizeof(BoneInstanceGpu) == 64);

/// Skinned bodies: motion::SkinVertex is the vertex buffer's layout (skin.vert's attributes).
static_assert(sizeof(motion::SkinVertex) == 52);
static_assert(offsetof(motion::SkinVertex, normal) == 12);
static_assert(offsetof(motion::SkinVertex, girth) == 24);
static_assert(offsetof(motion::SkinVertex, mainBone) == 36);
static_assert(offsetof(motion::SkinVertex, joints) == 40);
static_assert(offsetof(motion::SkinVertex, weights) == 48);

/// One skeleton's indexed draw of its skinned mesh (VkDrawIndexedIndirectCommand), its
/// instance count accumulated by the compute pass; instances from firstInstance are entries
/// of the skinned-characters list.
struct SkinDrawGpu {
    std::uint32_t indexCount = 0;
    std::uint32_t instanceCount = 0;
    std::uint32_t firstIndex = 0;
    std::int32_t vertexOffset = 0;
    std::uint32_t firstInstance = 0;
};
static_assert(sizeof(SkinDrawGpu) == 20);

/// What the bone bodies' compute pass drew one character as (shaders/gpu_types.glsl BodyLevelGpu).
struct BodyLevelGpu {
    std::uint32_t level = 0;      ///< BodyLevel: 0 culled, 1 joint spheres, 2 bones, 3 skinned mesh.
    float pixelsTall = 0.0F;      ///< Its height on screen, as the level was chosen from.
    std::uint32_t firstBone = 0;  ///< Its bones' first entry in the bone instances, when boneCount > 0.
    std::uint32_t boneCount = 0;  ///< Bones drawn: at the bones level, or fading out under the skin.
};
static_assert(sizeof(BodyLevelGpu) == 16);

struct InstanceGpu {
    glm::vec4 positionRadius;  ///< World position (metres) and sphere radius; radius 0 draws nothing.
    glm::vec4 orientation;     ///< World orientation quaternion, x y z w.
    glm::vec4 color;           ///< Linear RGB, a = 1.
};
static_assert(sizeof(InstanceGpu) == 48);
static_assert(offsetof(InstanceGpu, positionRadius) == 0);
static_assert(offsetof(InstanceGpu, orientation) == 16);
static_assert(offsetof(InstanceGpu, color) == 32);

/// std140 uniform block `SceneUniforms` (Binding::SceneUniforms, declared in shaders/bindings.glsl).
struct SceneUniforms {
    glm::mat4 viewProjection{1.0F};
    glm::vec3 cameraPosition{0.0F};
    /// 1 when this frame follows the previous frame of the same crowd, whose cross-fades between
    /// levels of detail it continues (shaders/lod_fade.glsl); 0 for a still image, where every
    /// character is drawn at the level its size asks for.
    float levelFadesContinue = 0.0F;
    glm::vec3 lightDirection{0.0F, 1.0F, 0.0F};  ///< Unit vector toward the key light.
    /// The visibility path's epoch for this frame's keys (shaders/visibility.glsl): the renderer
    /// sets it, counting down frame by frame; whatever the caller leaves here is replaced.
    std::uint32_t visibilityEpoch = 0;
    glm::vec4 lightColor{1.0F};
    glm::vec4 skyColor{0.3F};
    glm::vec4 bounceColor{0.1F};
    glm::vec4 groundParams{100.0F, 1.0F, 100.0F, 200.0F};  ///< half extent, checker size, fog start, fog end
    glm::vec4 fogColor{0.7F};
    /// Inverse of Camera::viewProjectionAtEye: a pixel's near-plane point as an offset from the
    /// eye, the direction of its ray.
    glm::mat4 inverseViewProjectionAtEye{1.0F};
    glm::vec4 viewport{1.0F};  ///< width, height (pixels), vertical focal length (pixels), largest point size
};
static_assert(sizeof(SceneUniforms) == 64 + 7 * 16 + 64 + 16);
static_assert(offsetof(SceneUniforms, inverseViewProjectionAtEye) == 64 + 7 * 16);
static_assert(offsetof(SceneUniforms, cameraPosition) == 64);
static_assert(offsetof(SceneUniforms, levelFadesContinue) == 64 + 12);  // cameraPosition.w in the shaders' std140 block
static_assert(offsetof(SceneUniforms, fogColor) == 64 + 6 * 16);
static_assert(offsetof(SceneUniforms, visibilityEpoch) == 64 + 16 + 12);  // lightDirection.w in the std140 block

/// Push constants shared by every pipeline (`Push` in shaders/bindings.glsl).
struct PushConstants {
    std::uint32_t characterCount = 0;
    std::uint32_t jointsPerCharacter = 0;
    float cullRadius = 0.0F;   ///< Bounding-sphere radius of a character, metres.
    float cullHeight = 0.0F;   ///< Height of its centre above the ground.
    glm::vec4 frustum[6]{};    ///< World-space planes; inside where dot(xyz, p) + w >= 0.
    float lodPixels = 0.0F;    ///< Characters drawn shorter than this (pixels) leave detail joints out; 0: never.
    float bonePixels = 0.0F;   ///< Bone bodies: characters drawn at least this tall (pixels) draw bones, the rest joint spheres.
    float skinPixels = 0.0F;   ///< Characters drawn at least this tall (pixels) draw skinned meshes (bone bodies' path).
    /// The batch's first character in the whole crowd: a crowd past one storage buffer is drawn
    /// in batches, each indexed from 0, and a character's look is drawn from its crowd-wide index.
    std::uint32_t firstCharacter = 0;
};
static_assert(sizeof(PushConstants) == 16 + 6 * 16 + 16);

/// The indirect draw the fast path's compute pass fills (VkDrawIndirectCommand).
struct DrawArguments {
    std::uint32_t vertexCount = 0;
    std::uint32_t instanceCount = 1;
    std::uint32_t firstVertex = 0;
    std::uint32_t firstInstance = 0;
};
static_assert(sizeof(DrawArguments) == 16);

/// An indirect dispatch (VkDispatchIndirectCommand): workgroups along x, y and z.
struct DispatchArguments {
    std::uint32_t groupsX = 0;
    std::uint32_t groupsY = 1;
    std::uint32_t groupsZ = 1;
};
static_assert(sizeof(DispatchArguments) == 12);

/// The fast path's whole DrawArguments block (shaders/bindings.glsl): the indirect draw, then
/// how many characters the culling pass kept at each level of detail.
struct FastPathCounts {
    DrawArguments draw;
    std::uint32_t fullCharacters = 0;    ///< Visible, drawn with every joint.
    std::uint32_t coarseCharacters = 0;  ///< Visible, drawn with their major joints only.
    std::uint32_t boneCharacters = 0;    ///< Visible, drawn as bone bodies.
    std::uint32_t skinCharacters = 0;    ///< Visible, drawn as skinned meshes.
    DrawArguments boneDraw{4, 0, 0, 0};  ///< Bone bodies: a 4-vertex quad per bone instance.
    DispatchArguments jointSplat;        ///< The visibility path's splat of the joints written,
    DispatchArguments boneSplat;         ///< and of the bones (as many workgroups as they need).
    /// Bone bodies: the characters the planning pass listed for each body writer (joint spheres,
    /// bones, skin), and each writer's dispatch.
    std::array<std::uint32_t, 3> listed{};
    std::array<DispatchArguments, 3> writerDispatch{};
    std::uint32_t fadingCharacters = 0;  ///< Bone bodies: visible and drawn at two levels, cross-fading.
};
static_assert(sizeof(FastPathCounts) == 124);
static_assert(offsetof(FastPathCounts, fadingCharacters) == 120);
static_assert(offsetof(FastPathCounts, fullCharacters) == 16);
static_assert(offsetof(FastPathCounts, boneCharacters) == 24);
static_assert(offsetof(FastPathCounts, boneDraw) == 32);
static_assert(offsetof(FastPathCounts, jointSplat) == 48);
static_assert(offsetof(FastPathCounts, boneSplat) == 60);
static_assert(offsetof(FastPathCounts, writerDispatch) == 84);

// PoseGpu is motion::JointPose: vec4 rotation (x y z w), vec4 translation (xyz, w unused).
static_assert(sizeof(motion::JointPose) == 32);
static_assert(offsetof(motion::JointPose, rotation) == 0);
static_assert(offsetof(motion::JointPose, translation) == 16);
// CharacterGpu is crowd::CharacterState.
static_assert(offsetof(crowd::CharacterState, groundFrame) == 0);
static_assert(offsetof(crowd::CharacterState, clip) == 16);
static_assert(offsetof(crowd::CharacterState, frame) == 20);
static_assert(offsetof(crowd::CharacterState, scale) == 24);
static_assert(offsetof(crowd::CharacterState, color) == 28);
static_assert(offsetof(crowd::CharacterState, footTwist) == 32);
static_assert(offsetof(crowd::CharacterState, blendClip) == 40);
static_assert(offsetof(crowd::CharacterState, blendFrame) == 44);
static_assert(offsetof(crowd::CharacterState, blend) == 48);
static_assert(offsetof(crowd::CharacterState, fromClip) == 52);
static_assert(offsetof(crowd::CharacterState, fromFrame) == 56);
static_assert(offsetof(crowd::CharacterState, fromWeight) == 60);
static_assert(sizeof(crowd::CharacterState) == 64);

}  // namespace throng::render
