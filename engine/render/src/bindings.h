#pragma once
// The descriptor bindings of the one pipeline layout every shader shares, named once for C++.
// The numbers come from shaders/binding_numbers.h, which shaders/bindings.glsl includes too,
// so the GLSL declarations and the C++ tables can't drift apart. (Private to render: it needs the
// throng_shaders target's include directories.)

#include <array>
#include <cstdint>

#include "binding_numbers.h"
#include "throng/gpu/vulkan.h"

namespace throng::render {

/// Binding number of each buffer in descriptor set 0.
enum class Binding : std::uint32_t {
    Poses = THRONG_BINDING_POSES,                    ///< Palette: every clip's baked poses (storage, read only).
    Clips = THRONG_BINDING_CLIPS,                    ///< ClipGpu per clip (storage, read only).
    JointRadii = THRONG_BINDING_JOINT_RADII,         ///< Sphere radius per joint of every clip (storage, read only).
    Characters = THRONG_BINDING_CHARACTERS,          ///< CharacterState per character, per frame (storage, read only).
    Instances = THRONG_BINDING_INSTANCES,            ///< InstanceGpu per joint: compute (or CPU) writes, vertex reads.
    SceneUniforms = THRONG_BINDING_SCENE_UNIFORMS,   ///< SceneUniforms (uniform buffer).
    DrawArguments = THRONG_BINDING_DRAW_ARGUMENTS,   ///< Fast path: the indirect draw the culling pass fills.
    InstanceOwners = THRONG_BINDING_INSTANCE_OWNERS, ///< Fast path: (character, joint) per compacted instance.
    JointDetail = THRONG_BINDING_JOINT_DETAIL,       ///< Level-of-detail flag and foot per joint of every clip, then each clip's kept joints (storage, read only).
    Bones = THRONG_BINDING_BONES,                    ///< BoneGpu per bone of every clip's body (storage, read only).
    BoneInstances = THRONG_BINDING_BONE_INSTANCES,   ///< Bone bodies: BoneInstanceGpu per visible bone, compute writes.
    BindPoses = THRONG_BINDING_BIND_POSES,           ///< Skinned bodies: bind-pose transform per joint of every clip (read only).
    SkinJoints = THRONG_BINDING_SKIN_JOINTS,         ///< Skinned bodies: skinning transform per joint of each skinned character, compute writes.
    SkinCharacters = THRONG_BINDING_SKIN_CHARACTERS, ///< Skinned bodies: the skinned characters, per skeleton, compute writes.
    SkinDraws = THRONG_BINDING_SKIN_DRAWS,           ///< Skinned bodies: SkinDrawGpu per skeleton, compute counts instances.
    BodyLevels = THRONG_BINDING_BODY_LEVELS,         ///< Bone bodies: BodyLevelGpu per character, compute writes.
    Visibility = THRONG_BINDING_VISIBILITY,          ///< Visibility path: (distance, instance) per pixel, compute splats (fragment shaders read VisibilityTexels).
    CharacterLists = THRONG_BINDING_CHARACTER_LISTS, ///< Bone bodies: the characters each body writer takes, listed by the planning pass.
    Shadows = THRONG_BINDING_SHADOWS,                ///< Visibility path, bone bodies: the contact shadows' darkening per pixel, compute splats (fragment shaders read ShadowTexels).
    ShadingTiles = THRONG_BINDING_SHADING_TILES,     ///< Visibility path: the shading's squares (shading_tiles.glsl), compute marks and lists, vertex reads.
    VisibilityTexels = THRONG_BINDING_VISIBILITY_TEXELS,  ///< Visibility path: the visibility buffer as a uniform texel buffer (R32G32_UINT), fragment reads.
    ShadowTexels = THRONG_BINDING_SHADOW_TEXELS,     ///< Visibility path, bone bodies: the contact shadows as a uniform texel buffer (R32_UINT), fragment reads.
    SkinJointTexels = THRONG_BINDING_SKIN_JOINT_TEXELS,  ///< Skinned bodies: skinJoints as a uniform texel buffer (R32G32B32A32_SFLOAT, two per joint), vertex reads.
    LevelFades = THRONG_BINDING_LEVEL_FADES,         ///< Bone bodies: each character's cross-fades between levels, kept from frame to frame (the planning pass reads and writes).
    InstanceTexels = THRONG_BINDING_INSTANCE_TEXELS,  ///< Visibility path: `instances` as a uniform texel buffer (R32G32B32A32_SFLOAT, three per joint), the shading's reads.
    BoneInstanceTexels = THRONG_BINDING_BONE_INSTANCE_TEXELS,  ///< Visibility path, bone bodies: `boneInstances` the same (four per bone).
};

/// Every binding, in number order.
inline constexpr std::array<Binding, 26> kAllBindings{
    Binding::Poses,          Binding::Clips,      Binding::JointRadii, Binding::Characters,     Binding::Instances,
    Binding::SceneUniforms,  Binding::DrawArguments, Binding::InstanceOwners, Binding::JointDetail, Binding::Bones,
    Binding::BoneInstances,  Binding::BindPoses,  Binding::SkinJoints, Binding::SkinCharacters, Binding::SkinDraws,
    Binding::BodyLevels,     Binding::Visibility, Binding::CharacterLists, Binding::Shadows,        Binding::ShadingTiles,
    Binding::VisibilityTexels, Binding::ShadowTexels, Binding::SkinJointTexels, Binding::LevelFades, Binding::InstanceTexels,
    Binding::BoneInstanceTexels};

/// The descriptor type of each binding: the scene's uniform buffer, the texel views, and
/// storage buffers for the rest.
[[nodiscard]] inline vk::DescriptorType descriptorType(Binding binding) {
    switch (binding) {
    case Binding::SceneUniforms: return vk::DescriptorType::eUniformBuffer;
    case Binding::VisibilityTexels:
    case Binding::ShadowTexels:
    case Binding::SkinJointTexels:
    case Binding::InstanceTexels:
    case Binding::BoneInstanceTexels: return vk::DescriptorType::eUniformTexelBuffer;
    default: return vk::DescriptorType::eStorageBuffer;
    }
}

/// The binding number, for Vulkan structs.
[[nodiscard]] constexpr std::uint32_t bindingIndex(Binding binding) { return static_cast<std::uint32_t>(binding); }

}  // namespace throng::render
