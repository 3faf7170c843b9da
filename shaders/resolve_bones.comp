#version 450
// Bone bodies (--body bones, auto): one invocation per character culls it against the view
// frustum and, when visible, writes its bones as tapered capsules for bone.vert/bone.frag to
// ray-cast, reserving room with one atomic add on the bone draw's instance count; with auto, a
// character shorter on screen than push.bonePixels writes joint spheres instead. The joints come
// from the same palette sampling as every other path (pose.glsl); the look (clothing colours,
// a slimmer or broader build) is drawn per character from its index, so it never flickers.
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes bone instances and the draw arguments
#include "bindings.glsl"
#include "culling.glsl"
#include "joint_sprites.glsl"

layout(local_size_x = 64) in;

// A well-mixed 32-bit hash (lowbias32), and from it a number in [0, 1).
uint mixBits(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float unitHash(uint character, uint salt) { return float(mixBits(character * 4u + salt) >> 8) * (1.0 / 16777216.0); }

// Linear RGB: the shirt is the character's own colour; trousers, skin and shoes come from
// small plausible palettes.
const vec3 kTrousers[5] = vec3[5](vec3(0.035, 0.05, 0.11), vec3(0.03, 0.03, 0.035), vec3(0.26, 0.2, 0.11),
                                  vec3(0.12, 0.12, 0.13), vec3(0.1, 0.06, 0.035));
const vec3 kSkin[5] = vec3[5](vec3(0.68, 0.45, 0.34), vec3(0.52, 0.31, 0.2), vec3(0.32, 0.18, 0.1),
                              vec3(0.15, 0.085, 0.05), vec3(0.76, 0.55, 0.44));
const vec3 kShoes[3] = vec3[3](vec3(0.025), vec3(0.55), vec3(0.09, 0.05, 0.03));

vec3 partColor(uint part, uint m, vec3 shirt) {
    if (part == 1u) return shirt;
    if (part == 2u) return kTrousers[min(uint(unitHash(m, 1u) * 5.0), 4u)];
    if (part == 3u) return kShoes[min(uint(unitHash(m, 2u) * 3.0), 2u)];
    return kSkin[min(uint(unitHash(m, 3u) * 5.0), 4u)];
}

// A rotation (x, y, z, w) applied to a vector.
vec3 rotateByQuaternion(vec4 q, vec3 v) {
    const vec3 t = 2.0 * cross(q.xyz, v);
    return v + q.w * t + cross(q.xyz, t);
}

// The unit part of `direction` across `axis` (unit), or 0 when they are parallel.
vec3 across(vec3 direction, vec3 axis) {
    const vec3 v = direction - dot(direction, axis) * axis;
    const float len = length(v);
    return len > 1e-4 ? v / len : vec3(0.0);
}

void main() {
    const uint m = gl_GlobalInvocationID.x;
    if (m >= push.characterCount) return;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const vec3 centre = characterCentre(character);
    if (!insideFrustum(centre, push.cullRadius * character.scale)) return;
    // --body auto: a character too small on screen for its bones to show draws joint spheres.
    const float tall = pixelsTall(character, centre);
    if (tall < push.bonePixels) {
        writeJointSprites(m, character, clip, tall < push.lodPixels, false);
        return;
    }
    uint slot = atomicAdd(draw.boneInstanceCount, clip.boneCount);
    atomicAdd(draw.boneCharacters, 1u);
    // Build: limbs and trunk 12% slimmer to 15% broader, lengths untouched (height already varies).
    const float girth = character.scale * mix(0.88, 1.15, unitHash(m, 0u));
    const vec3 shirt = unpackUnorm4x8(character.color).rgb;
    const float yaw = character.groundFrame.w;
    const vec3 sideways = vec3(cos(yaw), 0.0, -sin(yaw));  // the character's +X in the world
    for (uint b = 0; b < clip.boneCount; ++b) {
        const BoneGpu bone = bones[clip.firstBone + b];
        const vec3 start = groundToWorld(character, sampleJointTranslation(character, clip, bone.joint));
        vec3 end;
        if (bone.child != kBoneToEndSite) {
            end = groundToWorld(character, sampleJointTranslation(character, clip, bone.child));
        } else {
            const vec4 rotation = groundToWorldRotation(character, sampleJointRotation(character, clip, bone.joint));
            end = start + rotateByQuaternion(rotation, bone.tipOffset.xyz * character.scale);
        }
        const vec3 axis = end - start;
        const vec3 unitAxis = length(axis) > 1e-6 ? normalize(axis) : vec3(0.0, 1.0, 0.0);
        // Soles flatten toward the ground's normal, palms across the body.
        const uint flattening = (bone.look >> 8) & 3u;
        const vec3 flatAxis = flattening == 1u ? across(vec3(0.0, 1.0, 0.0), unitAxis)
                            : flattening == 2u ? across(sideways, unitAxis) : vec3(0.0);
        const float thickness = dot(flatAxis, flatAxis) > 0.5 ? bone.thickness : 1.0;
        boneInstances[slot] = BoneInstanceGpu(vec4(start, bone.radiusStart * girth), vec4(end, bone.radiusEnd * girth),
                                              vec4(flatAxis, thickness), vec4(partColor(bone.look & 3u, m, shirt), 1.0));
        ++slot;
    }
}
