// GPU-shared structs, declared once here and mirrored in C++ with static_asserts on size and
// offsets (engine/render/include/throng/render/gpu_types.h, motion::JointPose for PoseGpu and
// crowd::CharacterState for CharacterGpu). std430 layout. The buffers, the scene uniforms and
// the push constants that use them are declared in bindings.glsl.

// One baked joint at one frame, relative to the character's ground frame (metres).
struct PoseGpu {
    vec4 rotation;     // quaternion (x, y, z, w)
    vec4 translation;  // xyz; w unused
};

// Where a clip's poses and joint radii start in the shared palette.
struct ClipGpu {
    uint firstPose;    // index of frame 0, joint 0 in the pose array
    uint jointCount;
    uint frameCount;
    uint firstJoint;   // index of joint 0 in the joint-radius array
    uint firstBone;    // index of the clip's first bone in the bone table (bone bodies)
    uint boneCount;
    uint skeleton;     // skinned bodies: the clip's skeleton, its mesh's index
    uint coarseJointCount;  // joints a distant character keeps (not detail joints)
    uint firstCoarseJoint;  // where their list starts in jointInfo, ascending
    uint leftAnkle, rightAnkle;  // the legs' ankle joints, about which a foot twists
    uint pad;
};

// One skeleton's indexed draw of its skinned mesh (VkDrawIndexedIndirectCommand); the compute
// pass counts instances, each an entry of the skinned-characters list from firstInstance.
struct SkinDrawGpu {
    uint indexCount;
    uint instanceCount;
    uint firstIndex;
    int vertexOffset;
    uint firstInstance;
};

// One bone of a clip's body (--body bones): a tapered capsule from a joint to its child joint,
// or to an End Site given as an offset in the joint's frame. Radii in metres at scale 1.
const uint kBoneToEndSite = 0xffffffffu;
struct BoneGpu {
    vec4 tipOffset;     // xyz: the End Site in the joint's frame (metres, scale 1), when child is kBoneToEndSite
    uint joint;         // where the bone starts
    uint child;         // the joint where it ends, or kBoneToEndSite
    float radiusStart;
    float radiusEnd;
    uint look;          // bits 0-1: clothing part (0 skin, 1 shirt, 2 trousers, 3 shoes); bits 8-9: flattening (0 none, 1 the sole's, 2 the palm's, 3 the trunk's, front to back)
    float thickness;    // flattened: thickness over width, 0..1 (1: round)
    float pad0;
    float pad1;
};

// One bone of one visible character, written by resolve_bones.comp, drawn by bone.vert/frag.
struct BoneInstanceGpu {
    vec4 start;    // world position of the bone's start, radius there (metres)
    vec4 end;      // world position of its end, radius there
    vec4 flatten;  // xyz: unit axis the bone is flattened along, w: thickness over width (1: round)
    vec4 color;    // linear RGB, a = 1
};

// One character, written by the CPU every frame. Its pose is `clip` at `frame`, blended toward
// `blendClip` at `blendFrame` by `blend`, then toward `fromClip` at `fromFrame` by `fromWeight`
// (pose.glsl's blendedPose); a weight of exactly 0 leaves its clip unread.
struct CharacterGpu {
    vec4 groundFrame;  // xyz: position (y = 0), w: yaw in radians
    uint clip;
    float frame;       // fractional frame position
    float scale;
    uint color;        // RGBA8, R in the low byte, linear
    vec2 footTwist;    // per leg, radians: the foot turned about its ankle (pose.glsl's jointTranslation)
    uint blendClip;    // speed blending: the second clip, at the same gait phase
    float blendFrame;
    float blend;       // weight of blendClip, 0..1
    uint fromClip;     // a transition's outgoing clip
    float fromFrame;
    float fromWeight;  // weight of fromClip, falling to 0 as the transition ends
};

// What resolve_bones.comp drew one character as: level 0 culled, 1 joint spheres, 2 bones,
// 3 skinned mesh (the nearer level while two cross-fade); bones from firstBone, boneCount of them.
struct BodyLevelGpu {
    uint level;
    float pixelsTall;
    uint firstBone;
    uint boneCount;
};

// One joint of one character, written by the compute pass, read by the sphere pass.
struct InstanceGpu {
    vec4 positionRadius;  // world position (metres) and sphere radius; radius 0 draws nothing
    vec4 orientation;     // world orientation of the joint, quaternion (x, y, z, w)
    vec4 color;           // linear RGB, a = 1
};
