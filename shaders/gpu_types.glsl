// GPU-shared structs, declared once here and mirrored in C++ with static_asserts on size and
// offsets (engine/render/src/gpu_types.h and engine/crowd CharacterState). std430 layout.

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
};

// One character, written by the CPU every frame.
struct CharacterGpu {
    vec4 groundFrame;  // xyz: position (y = 0), w: yaw in radians
    uint clip;
    float frame;       // fractional frame position
    float scale;
    uint color;        // RGBA8, R in the low byte, linear
};

// One joint of one character, written by the compute pass, read by the sphere pass.
struct InstanceGpu {
    vec4 positionRadius;  // world position (metres) and sphere radius; radius 0 draws nothing
    vec4 orientation;     // world orientation of the joint, quaternion (x, y, z, w)
    vec4 color;           // linear RGB, a = 1
};

layout(set = 0, binding = 5, std140) uniform SceneUniforms {
    mat4 viewProjection;
    vec4 cameraPosition;  // xyz
    vec4 lightDirection;  // xyz: unit vector toward the key light
    vec4 lightColor;      // rgb
    vec4 skyColor;        // rgb: hemisphere ambient from above
    vec4 bounceColor;     // rgb: hemisphere ambient from below
    vec4 groundParams;    // x: half extent (m), y: checker size (m), z: fog start (m), w: fog end (m)
    vec4 fogColor;        // rgb
    mat4 inverseViewProjection;
    vec4 viewport;        // x: width, y: height (pixels), z: focal length in pixels (vertical), w: largest point size
} scene;

// Push constants shared by every pipeline (one layout for all paths).
layout(push_constant) uniform Push {
    uint characterCount;
    uint jointsPerCharacter;   // k: the largest joint count of any clip
    float cullRadius;          // bounding-sphere radius of a character, metres (fast path)
    float cullHeight;          // height of that sphere's centre above the ground, metres
    vec4 frustum[6];           // world-space planes, inside where dot(xyz, p) + w >= 0 (fast path)
    float lodPixels;           // characters shorter than this on screen skip detail joints; 0: never
} push;
