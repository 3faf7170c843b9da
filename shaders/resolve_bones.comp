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
#include "character_look.glsl"
#include "lod_fade.glsl"

layout(local_size_x = 64) in;

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

// A skinned character: each joint's skinning transform, its world pose times the inverse of
// its bind pose, for skin.vert to blend; and the character joins its skeleton's draw.
void writeSkinJoints(uint m, CharacterGpu character, ClipGpu clip, float fade) {
    const uint first = m * push.jointsPerCharacter;
    for (uint j = 0; j < clip.jointCount; ++j) {
        const vec4 rotation = groundToWorldRotation(character, sampleJointRotation(character, clip, j));
        const vec3 position = groundToWorld(character, sampleJointTranslation(character, clip, j));
        const PoseGpu bind = bindPoses[clip.firstJoint + j];
        const vec4 skinning = quatMultiply(rotation, vec4(-bind.rotation.xyz, bind.rotation.w));
        skinJoints[first + j] = PoseGpu(skinning, vec4(position - rotateByQuaternion(skinning, character.scale * bind.translation.xyz), character.scale));
    }
    const uint slot = atomicAdd(skinDraws[clip.skeleton].instanceCount, 1u);
    skinCharacters[skinDraws[clip.skeleton].firstInstance + slot] = uvec2(m, floatBitsToUint(fade));
    atomicAdd(draw.skinCharacters, 1u);
}

// A character's bones as tapered capsules for bone.vert/bone.frag, with lod_fade.glsl's fade;
// counted unless it is fading out under its skinned mesh. Returns where they start.
uint writeBones(uint m, CharacterGpu character, ClipGpu clip, float fade, bool counted) {
    uint slot = atomicAdd(draw.boneInstanceCount, clip.boneCount);
    atomicMax(draw.boneSplatGroups, splatGroupsFor(slot + clip.boneCount));  // the visibility path's splat
    const uint first = slot;
    if (counted) atomicAdd(draw.boneCharacters, 1u);
    const float girth = character.scale * buildOf(push.firstCharacter + m);
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
        // Soles flatten toward the ground's normal, palms across the body, the trunk front to back.
        const uint flattening = (bone.look >> 8) & 3u;
        const vec3 flatAxis = flattening == 1u ? across(vec3(0.0, 1.0, 0.0), unitAxis)
                            : flattening == 2u ? across(sideways, unitAxis)
                            : flattening == 3u ? across(vec3(sin(yaw), 0.0, cos(yaw)), unitAxis) : vec3(0.0);
        const float thickness = dot(flatAxis, flatAxis) > 0.5 ? bone.thickness : 1.0;
        boneInstances[slot] = BoneInstanceGpu(vec4(start, bone.radiusStart * girth), vec4(end, bone.radiusEnd * girth),
                                              vec4(flatAxis, thickness), vec4(partColor(bone.look & 3u, push.firstCharacter + m, shirt), fade));
        ++slot;
    }
    return first;
}

void main() {
    const uint m = gl_GlobalInvocationID.x;
    if (m >= push.characterCount) return;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const vec3 centre = characterCentre(character);
    if (!insideFrustum(centre, push.cullRadius * character.scale)) {
        bodyLevels[m] = BodyLevelGpu(0u, 0.0, 0u, 0u);
        return;
    }
    // --body auto: joint spheres below push.bonePixels, bones above, a skinned mesh from
    // push.skinPixels; just above each threshold the two levels cross-fade.
    const float tall = pixelsTall(character, centre);
    const bool coarse = tall < push.lodPixels;
    if (tall < push.bonePixels) {
        writeJointSprites(m, character, clip, coarse, false, 1.0);
        bodyLevels[m] = BodyLevelGpu(1u, tall, 0u, 0u);
        return;
    }
    const float bonesIn = fadeThrough(tall, push.bonePixels);
    if (bonesIn < 1.0) writeJointSprites(m, character, clip, coarse, false, -bonesIn);
    if (tall >= push.skinPixels) {
        const float skinIn = fadeThrough(tall, push.skinPixels);
        writeSkinJoints(m, character, clip, skinIn);
        const bool fading = skinIn < 1.0;
        const uint first = fading ? writeBones(m, character, clip, -skinIn, false) : 0u;
        bodyLevels[m] = BodyLevelGpu(3u, tall, first, fading ? clip.boneCount : 0u);
        return;
    }
    bodyLevels[m] = BodyLevelGpu(2u, tall, writeBones(m, character, clip, bonesIn, true), clip.boneCount);
}
