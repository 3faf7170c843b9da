#version 450
// Skinned bodies: the skeleton's generated mesh, one instance per skinned character, each
// vertex blended from up to four joints' skinning transforms (resolved by resolve_bones.comp)
// by dual-quaternion skinning, which turns a vertex about a bending joint instead of pulling it
// toward the bone (no collapsing elbows or candy-wrapper twists). The character's build
// scales the body across its bones (along each vertex's girth vector) before skinning.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "character_look.glsl"

layout(location = 0) in vec3 bindPosition;
layout(location = 1) in vec3 bindNormal;
layout(location = 2) in vec3 girth;
layout(location = 3) in uint mainBone;
layout(location = 4) in uvec4 joints;
layout(location = 5) in vec4 weights;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 albedo;
layout(location = 3) flat out float fade;  // lod_fade.glsl's

// The skinning transforms, read through a texel view of skinJoints (two texels a joint: its
// rotation, then its translation): lavapipe fetches texels for all lanes as one gather, where it
// loads a storage buffer's values lane by lane, each behind a branch. 200 skinned walkers drew
// in about 131 ms instead of 154.
layout(set = 0, binding = THRONG_BINDING_SKIN_JOINT_TEXELS) uniform samplerBuffer skinJointTexels;
PoseGpu skinJointAt(uint i) { return PoseGpu(texelFetch(skinJointTexels, 2 * int(i)), texelFetch(skinJointTexels, 2 * int(i) + 1)); }
vec4 quatProduct(vec4 a, vec4 b) { return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz)); }
vec3 rotateVector(vec4 q, vec3 v) {
    const vec3 t = 2.0 * cross(q.xyz, v);
    return v + q.w * t + cross(q.xyz, t);
}

void main() {
    const uvec2 listed = skinCharacters[gl_InstanceIndex];
    const uint m = listed.x;
    const CharacterGpu character = characters[m];
    const uint first = m * push.jointsPerCharacter;
    // Blend the joints' dual quaternions (real r, dual 0.5 * t * r), each on r's side of the first.
    const PoseGpu lead = skinJointAt(first + joints.x);
    vec4 real = vec4(0.0), dual = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        if (weights[i] <= 0.0) continue;
        const PoseGpu joint = skinJointAt(first + joints[i]);
        const float w = dot(joint.rotation, lead.rotation) < 0.0 ? -weights[i] : weights[i];
        real += w * joint.rotation;
        dual += w * 0.5 * quatProduct(vec4(joint.translation.xyz, 0.0), joint.rotation);
    }
    const float norm = length(real);
    real /= norm;
    dual /= norm;
    const vec3 translation = 2.0 * quatProduct(dual, vec4(-real.xyz, real.w)).xyz;
    const float scale = lead.translation.w;
    const vec3 local = scale * (bindPosition + (buildOf(push.firstCharacter + m) - 1.0) * girth);
    worldPosition = rotateVector(real, local) + translation;
    worldNormal = rotateVector(real, bindNormal);
    const ClipGpu clip = clips[character.clip];
    albedo = partColor(bones[clip.firstBone + mainBone].look & 3u, push.firstCharacter + m, unpackUnorm4x8(character.color).rgb);
    fade = uintBitsToFloat(listed.y);
    gl_Position = scene.viewProjection * vec4(worldPosition, 1.0);
}
