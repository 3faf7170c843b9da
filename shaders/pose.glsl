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

// Whether two of the palette's clips share a skeleton, so that a character may mix a second
// clip into its own (a speed blend or a transition, mixes() below). A palette of one clip per
// skeleton (the paper's crowd) specialises it false: a CPU device runs a branch's loads for
// every lane, masked, whether any lane takes it or not, and the mixing's six palette reads a
// joint cost the writers of a 2000-character frame about 0.4 ms. The host decides
// (render_path_impl.h's clipsMayMix).
layout(constant_id = 2) const bool kClipsMayMix = true;

// Quaternion product a * b, (x, y, z, w): rotates by b first, then by a.
vec4 quatMultiply(vec4 a, vec4 b) {
    return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}

// Rotation about +Y by `yaw` radians as a quaternion (x, y, z, w), as core/math.h's yawQuat.
vec4 yawQuaternion(float yaw) {
    return vec4(0.0, sin(0.5 * yaw), 0.0, cos(0.5 * yaw));
}

// The joint's sphere radius in metres at scale 1.
float jointRadiusAt(ClipGpu clip, uint joint) {
    return jointRadius[clip.firstJoint + joint];
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

// Mixes rotation b into a by t: nlerp on the short arc (close rotations: matches slerp closely).
vec4 nlerpShort(vec4 a, vec4 b, float t) {
    return normalize(mix(a, dot(a, b) < 0.0 ? -b : b, t));
}

// Whether the character's other clip `other` may mix into `clip` with weight `weight`: a weight
// of exactly 0 reads nothing (so a lone clip's bits are the clip's), and a clip of another
// skeleton never mixes.
bool mixes(ClipGpu clip, uint other, float weight) {
    return kClipsMayMix && weight != 0.0 && other < uint(clips.length()) && clips[other].jointCount == clip.jointCount;
}

// One clip's two baked frames around a frame position, as palette indices of their joint 0, and
// how far from the first toward the second: the only place that indexes the palette
// (frame-major: frameCount x jointCount entries from clip.firstPose).
struct ClipFrames {
    uint first;
    uint second;
    float t;
};

ClipFrames clipFrames(ClipGpu clip, float framePosition) {
    const FrameBlend f = frameBlend(framePosition, clip);
    return ClipFrames(clip.firstPose + f.first * clip.jointCount, clip.firstPose + f.second * clip.jointCount, f.t);
}

// What sampling a character's joints needs that is the same for every joint: its clips' frames
// and weights, its scale, its feet's twists and its ground frame, each worked out once. A
// writer that loops over a character's joints makes one and samples each joint from it; on a
// CPU device every step of a shader runs for every lane, so working these out again per joint
// (the clip records, frames, sines and cosines) cost more than reading the poses. A shader that
// samples one joint makes one too: what it leaves unread is never computed.
struct CharacterPose {
    ClipFrames own, blended, from;
    bool blends, crossfades;
    float blend, fromWeight, scale;
    uint firstJoint;            // the clip's, for jointInfo
    uvec2 ankleJoints;          // the clip's legs' ankles, about which the feet twist
    vec2 footTwist;             // per leg, radians
    vec2 twistCos, twistSin;    // of footTwist
    vec4 leftTwist, rightTwist; // footTwist as rotations about +Y
    vec4 groundFrame;
    float yawCos, yawSin;       // of groundFrame.w
    vec4 yaw;                   // groundFrame.w as a rotation about +Y
};

CharacterPose characterPose(CharacterGpu character, ClipGpu clip) {
    CharacterPose pose;
    pose.own = clipFrames(clip, character.frame);
    pose.blends = mixes(clip, character.blendClip, character.blend);
    pose.blended = pose.blends ? clipFrames(clips[character.blendClip], character.blendFrame) : pose.own;
    pose.crossfades = mixes(clip, character.fromClip, character.fromWeight);
    pose.from = pose.crossfades ? clipFrames(clips[character.fromClip], character.fromFrame) : pose.own;
    pose.blend = character.blend;
    pose.fromWeight = character.fromWeight;
    pose.scale = character.scale;
    pose.firstJoint = clip.firstJoint;
    pose.ankleJoints = uvec2(clip.leftAnkle, clip.rightAnkle);
    pose.footTwist = character.footTwist;
    pose.twistCos = vec2(cos(character.footTwist.x), cos(character.footTwist.y));
    pose.twistSin = vec2(sin(character.footTwist.x), sin(character.footTwist.y));
    pose.leftTwist = yawQuaternion(character.footTwist.x);
    pose.rightTwist = yawQuaternion(character.footTwist.y);
    pose.groundFrame = character.groundFrame;
    pose.yawCos = cos(character.groundFrame.w);
    pose.yawSin = sin(character.groundFrame.w);
    pose.yaw = yawQuaternion(character.groundFrame.w);
    return pose;
}

// One clip's baked position of a joint, in the ground frame, unscaled: lerp between the two frames.
vec3 framesTranslation(ClipFrames frames, uint joint) {
    return mix(poses[frames.first + joint].translation.xyz, poses[frames.second + joint].translation.xyz, frames.t);
}

// One clip's baked orientation of a joint: nlerp between the two frames.
vec4 framesRotation(ClipFrames frames, uint joint) {
    return nlerpShort(poses[frames.first + joint].rotation, poses[frames.second + joint].rotation, frames.t);
}

// The joint's baked position in the character's ground frame (in place), scaled: its clip,
// blended toward blendClip, then crossfaded toward fromClip, each by lerp.
vec3 bakedTranslation(CharacterPose pose, uint joint) {
    vec3 t = framesTranslation(pose.own, joint);
    if (kClipsMayMix && pose.blends) t = mix(t, framesTranslation(pose.blended, joint), pose.blend);
    if (kClipsMayMix && pose.crossfades) t = mix(t, framesTranslation(pose.from, joint), pose.fromWeight);
    return t * pose.scale;
}

// The joint's baked orientation in the ground frame: its clip, blended, then crossfaded, each
// by nlerp on the short arc.
vec4 bakedRotation(CharacterPose pose, uint joint) {
    vec4 q = framesRotation(pose.own, joint);
    if (kClipsMayMix && pose.blends) q = nlerpShort(q, framesRotation(pose.blended, joint), pose.blend);
    if (kClipsMayMix && pose.crossfades) q = nlerpShort(q, framesRotation(pose.from, joint), pose.fromWeight);
    return q;
}

// The leg whose foot the joint is in (1 or 2; 0 for none) and its foot's twist (0 for none).
uint footLegOf(CharacterPose pose, uint joint, out float twist) {
    const uint leg = (jointInfo[pose.firstJoint + joint] >> 8) & 3u;
    twist = leg == 0u ? 0.0 : (leg == 1u ? pose.footTwist.x : pose.footTwist.y);
    return leg;
}

// A foot joint's baked position turned about its leg's ankle by the foot's twist
// (x' = c x + s z, z' = -s x + c z, as the yaw).
vec3 twistAboutAnkle(CharacterPose pose, vec3 baked, vec3 ankle, uint leg) {
    const vec3 offset = baked - ankle;
    const float c = leg == 1u ? pose.twistCos.x : pose.twistCos.y, s = leg == 1u ? pose.twistSin.x : pose.twistSin.y;
    return ankle + vec3(c * offset.x + s * offset.z, offset.y, -s * offset.x + c * offset.z);
}

// The joint's position in the character's ground frame: baked, and for a foot joint with a
// twist, turned about its leg's ankle by it. A twist of exactly 0 leaves the baked
// position's bits alone. Samples the joint's ankle itself: for one joint alone.
vec3 jointTranslation(CharacterPose pose, uint joint) {
    const vec3 baked = bakedTranslation(pose, joint);
    float twist;
    const uint leg = footLegOf(pose, joint, twist);
    if (twist == 0.0) return baked;
    return twistAboutAnkle(pose, baked, bakedTranslation(pose, leg == 1u ? pose.ankleJoints.x : pose.ankleJoints.y), leg);
}

// Both legs' ankles in the ground frame, sampled once for a writer that loops over a
// character's joints (on a CPU device every joint paid for its ankle's sampling, feet or not).
struct Ankles {
    vec3 left, right;
};

Ankles characterAnkles(CharacterPose pose) {
    return Ankles(bakedTranslation(pose, pose.ankleJoints.x), bakedTranslation(pose, pose.ankleJoints.y));
}

// jointTranslation, with the ankles sampled once (the same bits).
vec3 jointTranslation(CharacterPose pose, Ankles ankles, uint joint) {
    const vec3 baked = bakedTranslation(pose, joint);
    float twist;
    const uint leg = footLegOf(pose, joint, twist);
    if (twist == 0.0) return baked;
    return twistAboutAnkle(pose, baked, leg == 1u ? ankles.left : ankles.right, leg);
}

// The joint's orientation in the character's ground frame: baked, then a foot joint's twist about +Y.
vec4 jointRotation(CharacterPose pose, uint joint) {
    const vec4 baked = bakedRotation(pose, joint);
    float twist;
    const uint leg = footLegOf(pose, joint, twist);
    return twist == 0.0 ? baked : quatMultiply(leg == 1u ? pose.leftTwist : pose.rightTwist, baked);
}

// A point in the character's ground frame to world: rotation about +Y by the yaw, then the
// ground frame's position. x' = c x + s z, z' = -s x + c z (matches core/math.h).
vec3 poseToWorld(CharacterPose pose, vec3 local) {
    const float c = pose.yawCos, s = pose.yawSin;
    return pose.groundFrame.xyz + vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
}

// An orientation in the character's ground frame to world.
vec4 poseToWorldRotation(CharacterPose pose, vec4 local) {
    return quatMultiply(pose.yaw, local);
}

#endif
