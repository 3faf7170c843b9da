// Joint sampling, the one GLSL definition (mirrored in C++ by crowd::sampleJointWorld in
// engine/crowd/include/throng/crowd/character_state.h): where a clip's poses sit in the
// palette, the two baked frames around a fractional frame position (clamped into the clip),
// nlerp of rotations on the short arc and lerp of translations between them, the same mixing
// of a speed blend's second clip and a transition's outgoing clip, the character's scale, a
// foot's twist about its ankle, and its ground frame (yaw about +Y, then position) to world.
//
// The order of the floating-point operations is part of the contract: every path that uses
// these functions (and the CPU mirror) gets the same bits, and the golden images depend on it.
#ifndef THRONG_POSE_GLSL
#define THRONG_POSE_GLSL

#include "bindings.glsl"

// Quaternion product a * b, (x, y, z, w): rotates by b first, then by a.
vec4 quatMultiply(vec4 a, vec4 b) {
    return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}

// Rotation about +Y by `yaw` radians as a quaternion (x, y, z, w), as core/math.h's yawQuat.
vec4 yawQuaternion(float yaw) {
    return vec4(0.0, sin(0.5 * yaw), 0.0, cos(0.5 * yaw));
}

// The baked pose of `joint` at whole frame `frame` of `clip`: the only place that indexes the
// palette (frame-major: frameCount x jointCount entries from clip.firstPose).
PoseGpu poseAt(ClipGpu clip, uint frame, uint joint) {
    return poses[clip.firstPose + frame * clip.jointCount + joint];
}

// The joint's sphere radius in metres at scale 1.
float jointRadiusAt(ClipGpu clip, uint joint) {
    return jointRadius[clip.firstJoint + joint];
}

// Whether a distant character may leave the joint out (level of detail).
bool isDetailJoint(ClipGpu clip, uint joint) {
    return (jointInfo[clip.firstJoint + joint] & 1u) != 0u;
}

// The character's foot twist for the joint: the twist of the leg whose foot it is in, else 0.
float footTwistOf(CharacterGpu character, ClipGpu clip, uint joint) {
    const uint leg = (jointInfo[clip.firstJoint + joint] >> 8) & 3u;
    return leg == 0u ? 0.0 : (leg == 1u ? character.footTwist.x : character.footTwist.y);
}

// The two baked frames around a frame position of a clip, clamped into [0, frameCount - 1],
// and how far it is from the first toward the second (0..1).
struct FrameBlend {
    uint first;
    uint second;
    float t;
};

FrameBlend frameBlend(float framePosition, ClipGpu clip) {
    const float frame = clamp(framePosition, 0.0, float(clip.frameCount - 1));
    const uint f0 = uint(floor(frame));
    return FrameBlend(f0, min(f0 + 1, clip.frameCount - 1), frame - float(f0));
}

// One clip's baked position of a joint at a frame position, in the ground frame, unscaled:
// lerp between the two frames around it.
vec3 sampleClipTranslation(ClipGpu clip, float framePosition, uint joint) {
    const FrameBlend f = frameBlend(framePosition, clip);
    return mix(poseAt(clip, f.first, joint).translation.xyz, poseAt(clip, f.second, joint).translation.xyz, f.t);
}

// Mixes rotation b into a by t: nlerp on the short arc (close rotations: matches slerp closely).
vec4 nlerpShort(vec4 a, vec4 b, float t) {
    return normalize(mix(a, dot(a, b) < 0.0 ? -b : b, t));
}

// One clip's baked orientation of a joint at a frame position: nlerp between the two frames.
vec4 sampleClipRotation(ClipGpu clip, float framePosition, uint joint) {
    const FrameBlend f = frameBlend(framePosition, clip);
    return nlerpShort(poseAt(clip, f.first, joint).rotation, poseAt(clip, f.second, joint).rotation, f.t);
}

// Whether the character's other clip `other` may mix into `clip` with weight `weight`: a weight
// of exactly 0 reads nothing (so a lone clip's bits are the clip's), and a clip of another
// skeleton never mixes.
bool mixes(ClipGpu clip, uint other, float weight) {
    return weight != 0.0 && other < uint(clips.length()) && clips[other].jointCount == clip.jointCount;
}

// The joint's baked position in the character's ground frame (in place), scaled: its clip,
// blended toward blendClip, then crossfaded toward fromClip, each by lerp.
vec3 sampleBakedTranslation(CharacterGpu character, ClipGpu clip, uint joint) {
    vec3 t = sampleClipTranslation(clip, character.frame, joint);
    if (mixes(clip, character.blendClip, character.blend))
        t = mix(t, sampleClipTranslation(clips[character.blendClip], character.blendFrame, joint), character.blend);
    if (mixes(clip, character.fromClip, character.fromWeight))
        t = mix(t, sampleClipTranslation(clips[character.fromClip], character.fromFrame, joint), character.fromWeight);
    return t * character.scale;
}

// The joint's baked orientation in the ground frame: its clip, blended, then crossfaded, each
// by nlerp on the short arc.
vec4 sampleBakedRotation(CharacterGpu character, ClipGpu clip, uint joint) {
    vec4 q = sampleClipRotation(clip, character.frame, joint);
    if (mixes(clip, character.blendClip, character.blend))
        q = nlerpShort(q, sampleClipRotation(clips[character.blendClip], character.blendFrame, joint), character.blend);
    if (mixes(clip, character.fromClip, character.fromWeight))
        q = nlerpShort(q, sampleClipRotation(clips[character.fromClip], character.fromFrame, joint), character.fromWeight);
    return q;
}

// The joint's position in the character's ground frame: baked, and for a foot joint with a
// twist, turned about its leg's ankle by it (x' = c x + s z, z' = -s x + c z, as the yaw). A
// twist of exactly 0 leaves the baked position's bits alone.
vec3 sampleJointTranslation(CharacterGpu character, ClipGpu clip, uint joint) {
    const vec3 baked = sampleBakedTranslation(character, clip, joint);
    const float twist = footTwistOf(character, clip, joint);
    if (twist == 0.0) return baked;
    const vec3 ankle = sampleBakedTranslation(character, clip, jointInfo[clip.firstJoint + joint] >> 10);
    const vec3 offset = baked - ankle;
    const float c = cos(twist), s = sin(twist);
    return ankle + vec3(c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z);
}

// The joint's orientation in the character's ground frame: baked (sampleBakedRotation), then a
// foot joint's twist about +Y.
vec4 sampleJointRotation(CharacterGpu character, ClipGpu clip, uint joint) {
    const vec4 baked = sampleBakedRotation(character, clip, joint);
    const float twist = footTwistOf(character, clip, joint);
    return twist == 0.0 ? baked : quatMultiply(yawQuaternion(twist), baked);
}

// One joint of one character in its ground frame (in place): orientation and scaled position.
struct JointSample {
    vec4 rotation;     // quaternion (x, y, z, w)
    vec3 translation;  // metres, already scaled by the character's scale
};

JointSample sampleJoint(CharacterGpu character, ClipGpu clip, uint joint) {
    return JointSample(sampleJointRotation(character, clip, joint), sampleJointTranslation(character, clip, joint));
}

// A point in the character's ground frame to world: rotation about +Y by the yaw, then the
// ground frame's position. x' = c x + s z, z' = -s x + c z (matches core/math.h).
vec3 groundToWorld(CharacterGpu character, vec3 local) {
    const float c = cos(character.groundFrame.w), s = sin(character.groundFrame.w);
    return character.groundFrame.xyz + vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
}

// An orientation in the character's ground frame to world.
vec4 groundToWorldRotation(CharacterGpu character, vec4 local) {
    return quatMultiply(yawQuaternion(character.groundFrame.w), local);
}

#endif
