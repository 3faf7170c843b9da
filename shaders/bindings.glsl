// Every buffer of the one pipeline layout that all shaders share, declared once: descriptor
// set 0 with the binding numbers of binding_numbers.h (which C++ reads too, as
// throng::render::Binding), the scene uniforms and the push constants. Each shader includes
// this file and uses what it needs; the C++ layout exposes every binding to every stage.
//
// Buffers a compute pass writes (instances, draw arguments, instance owners) are readonly
// everywhere else: a vertex or fragment shader may only declare a writable storage buffer
// when the device enables vertexPipelineStoresAndAtomics / fragmentStoresAndAtomics. A
// compute shader that writes them defines THRONG_COMPUTE_WRITES before including this file.
#ifndef THRONG_BINDINGS_GLSL
#define THRONG_BINDINGS_GLSL

#include "binding_numbers.h"
#include "gpu_types.glsl"

#ifdef THRONG_COMPUTE_WRITES
#define THRONG_COMPUTE_OUTPUT
#else
#define THRONG_COMPUTE_OUTPUT readonly
#endif

// The baked palette: every clip's poses, frame-major from ClipGpu.firstPose (pose.glsl's clipFrames).
layout(set = 0, binding = THRONG_BINDING_POSES, std430) readonly buffer Palette { PoseGpu poses[]; };
layout(set = 0, binding = THRONG_BINDING_CLIPS, std430) readonly buffer Clips { ClipGpu clips[]; };
// Per joint of every clip, a sphere radius in metres (index ClipGpu.firstJoint + joint).
layout(set = 0, binding = THRONG_BINDING_JOINT_RADII, std430) readonly buffer JointRadii { float jointRadius[]; };
layout(set = 0, binding = THRONG_BINDING_CHARACTERS, std430) readonly buffer Characters { CharacterGpu characters[]; };
// Resolved joints: written by resolve.comp / resolve_cull.comp (or the CPU), drawn by the sphere passes.
layout(set = 0, binding = THRONG_BINDING_INSTANCES, std430) THRONG_COMPUTE_OUTPUT buffer Instances { InstanceGpu instances[]; };

// The scene uniforms, as a struct too: a stage may hand them on (visibility_tiles.vert does).
struct SceneData {
    mat4 viewProjection;
    vec4 cameraPosition;  // xyz; w: SceneUniforms::levelFadesContinue (lod_fade.glsl), read by the planning pass alone
    vec3 lightDirection;  // unit vector toward the key light
    uint visibilityEpoch;  // the visibility path's keys' this frame (visibility.glsl)
    vec4 lightColor;      // rgb
    vec4 skyColor;        // rgb: hemisphere ambient from above
    vec4 bounceColor;     // rgb: hemisphere ambient from below
    vec4 groundParams;    // x: half extent (m), y: checker size (m), z: fog start (m), w: fog end (m)
    vec4 fogColor;        // rgb
    mat4 inverseViewProjectionAtEye;  // a pixel's near-plane point, as an offset from the eye (Camera::viewProjectionAtEye)
    vec4 viewport;        // x: width, y: height (pixels), z: focal length in pixels (vertical), w: largest point size
};
layout(set = 0, binding = THRONG_BINDING_SCENE_UNIFORMS, std140) uniform SceneUniforms { SceneData scene; };

// Fast path: the indirect draw (VkDrawIndirectCommand) the culling pass fills, how many
// characters it kept at each level of detail, and the bone bodies' indirect draw
// (FastPathCounts in C++).
layout(set = 0, binding = THRONG_BINDING_DRAW_ARGUMENTS, std430) THRONG_COMPUTE_OUTPUT buffer DrawArguments {
    uint vertexCount;  // one point per visible joint, accumulated here
    uint instanceCount;
    uint firstVertex;
    uint firstInstance;
    uint fullCharacters;    // visible, drawn with every joint
    uint coarseCharacters;  // visible, drawn with their major joints only
    uint boneCharacters;    // visible, drawn as bone bodies (--body bones or auto)
    uint skinCharacters;    // visible, drawn as skinned meshes
    uint boneVertexCount;   // the bone bodies' indirect draw: a 4-vertex quad per bone,
    uint boneInstanceCount; // accumulated here
    uint boneFirstVertex;
    uint boneFirstInstance;
    // The visibility path's splats, dispatched indirectly (VkDispatchIndirectCommand): as many
    // workgroups as the joints and bones written need, grown by atomicMax as they are written,
    // so no workgroup starts only to find nothing to splat (on lavapipe an empty workgroup
    // costs about as much as a small joint's splat).
    uint jointSplatGroups, jointSplatRows, jointSplatLayers;
    uint boneSplatGroups, boneSplatRows, boneSplatLayers;
    // Bone bodies: how many characters the planning pass listed for each body writer (joint
    // spheres, bones, skin; characterLists), and each writer's dispatch, grown as they are listed.
    uint listed[3];
    uint writerDispatch[9];  // (x, y, z) per writer
    uint fadingCharacters;   // visible and drawn at two levels, cross-fading (lod_fade.glsl)
} draw;
// The splats' workgroup size.
const uint kSplatGroupSize = 64u;
// The most workgroups a splat asks for; past it each invocation loops over more items. The
// passes that write joints and bones are specialised with it (render::splatGroupLimit: 4096,
// 262,144 invocations, under every device's limit and enough to fill an H100).
layout(constant_id = 0) const uint kLargestSplatGroups = 4096u;

// The workgroups a splat of `items` items (one invocation each) asks for; it loops past
// kLargestSplatGroups.
uint splatGroupsFor(uint items) {
    return min((items + kSplatGroupSize - 1u) / kSplatGroupSize, kLargestSplatGroups);
}
// Bone bodies: per body writer (kWriter* in resolve_bones.comp), the characters it writes this
// frame, writer w's list from w * push.characterCount; then, from kLargeShadowList *
// push.characterCount, the contact shadows too large for the visibility path's one invocation
// a shadow (splat_shadows.comp lists them, splat_large_shadows.comp casts them): its dispatch
// (VkDispatchIndirectCommand, 3 uints), how many are listed, and the characters listed.
layout(set = 0, binding = THRONG_BINDING_CHARACTER_LISTS, std430) THRONG_COMPUTE_OUTPUT buffer CharacterLists { uint characterLists[]; };
const uint kLargeShadowList = THRONG_LARGE_SHADOW_LIST;  // after the body writers' lists (binding_numbers.h)
// In that list (C++'s LargeShadowList): its dispatch's workgroups first, then how many are
// listed, then from kLargeShadowFirst the characters.
const uint kLargeShadowListed = 3u, kLargeShadowFirst = 4u;
// Fast path: per compacted instance, the character and joint it belongs to.
layout(set = 0, binding = THRONG_BINDING_INSTANCE_OWNERS, std430) THRONG_COMPUTE_OUTPUT buffer InstanceOwners { uvec2 instanceOwners[]; };
// Per joint of every clip (index ClipGpu.firstJoint + joint), packed (render::packJointInfo):
// bit 0, 1 when a distant character may leave it out; bits 8-9, 0 or 1 + the leg whose foot
// the joint is in. After every clip's, each clip's list of the joints a distant character keeps
// (ClipGpu.firstCoarseJoint, coarseJointCount).
layout(set = 0, binding = THRONG_BINDING_JOINT_DETAIL, std430) readonly buffer JointInfo { uint jointInfo[]; };
// Bone bodies: every clip's bones (ClipGpu.firstBone, boneCount), and the visible characters'
// bones that resolve_bones.comp writes, counted by the draw arguments' instanceCount.
layout(set = 0, binding = THRONG_BINDING_BONES, std430) readonly buffer Bones { BoneGpu bones[]; };
layout(set = 0, binding = THRONG_BINDING_BONE_INSTANCES, std430) THRONG_COMPUTE_OUTPUT buffer BoneInstances { BoneInstanceGpu boneInstances[]; };
// Bone bodies: per character of the batch, its levels' recent frames (lod_fade.glsl's histories),
// as the planning pass left them last frame and writes them this one.
layout(set = 0, binding = THRONG_BINDING_LEVEL_FADES, std430) THRONG_COMPUTE_OUTPUT buffer LevelFades { uint levelFades[]; };

// Skinned bodies: per joint of every clip (ClipGpu.firstJoint + joint), its global transform in
// its mesh's bind pose; per visible skinned character (m * jointsPerCharacter + joint), the
// skinning transform the compute pass resolves (rotation; translation xyz, scale w); the
// skinned characters (index, and the lod_fade.glsl fade as float bits), listed per skeleton
// from its draw's firstInstance; the draws.
layout(set = 0, binding = THRONG_BINDING_BIND_POSES, std430) readonly buffer BindPoses { PoseGpu bindPoses[]; };
layout(set = 0, binding = THRONG_BINDING_SKIN_JOINTS, std430) THRONG_COMPUTE_OUTPUT buffer SkinJoints { PoseGpu skinJoints[]; };
layout(set = 0, binding = THRONG_BINDING_SKIN_CHARACTERS, std430) THRONG_COMPUTE_OUTPUT buffer SkinCharacters { uvec2 skinCharacters[]; };  // character, fade's bits
layout(set = 0, binding = THRONG_BINDING_SKIN_DRAWS, std430) THRONG_COMPUTE_OUTPUT buffer SkinDraws { SkinDrawGpu skinDraws[]; };

// Bone bodies: per character, the level it was drawn at (for --dump-bodies).
layout(set = 0, binding = THRONG_BINDING_BODY_LEVELS, std430) THRONG_COMPUTE_OUTPUT buffer BodyLevels { BodyLevelGpu bodyLevels[]; };

// Push constants shared by every pipeline (one layout for all paths).
layout(push_constant) uniform Push {
    uint characterCount;
    uint jointsPerCharacter;   // k: the largest joint count of any clip
    float cullRadius;          // bounding-sphere radius of a character, metres (fast path)
    float cullHeight;          // height of that sphere's centre above the ground, metres
    vec4 frustum[6];           // world-space planes, inside where dot(xyz, p) + w >= 0 (fast path)
    float lodPixels;           // characters shorter than this on screen skip detail joints; 0: never
    float bonePixels;          // bone bodies: characters at least this tall on screen draw bones, the rest joint spheres
    float skinPixels;          // characters at least this tall on screen draw skinned meshes
    uint firstCharacter;       // the batch's first character in the whole crowd (a crowd past one storage buffer is drawn in batches)
} push;

// In characterLists, after the large shadows' list: the slots of the compacting passes
// (slot_allocation.glsl, for resolve_cull.comp and resolve_bones.comp). Per character, where its
// joint spheres and its bones go among those of its workgroup's characters; then per workgroup,
// its characters' totals, which the allocation pass turns into where they start. A character's
// joints and bones land in character order, whatever order the writers run in, so ties between
// bodies (equal depths in a draw, equal distances in the visibility buffer, which keeps the
// lower instance) fall the same way every run.
uint characterSlotsStart() { return (kLargeShadowList + 1u) * push.characterCount + kLargeShadowFirst; }
uint groupSlotsStart() { return characterSlotsStart() + 2u * push.characterCount; }

#endif
