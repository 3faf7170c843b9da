#version 450
// Bone bodies (--body bones, skin, auto): a planning pass, one invocation per character, culls
// it against the view frustum, lists it for the writers its size on screen needs and counts
// off the joints and bones it asks for; one workgroup allots them in character order
// (slot_allocation.glsl); then each writer takes its list: bones as tapered capsules for
// bone.vert/bone.frag (or the splat) to ray-cast; joint spheres for characters shorter on
// screen than push.bonePixels; skinning transforms for those taller than push.skinPixels. The
// joints come from the same palette sampling as every other path (pose.glsl); the look
// (clothing colours, a slimmer or broader build) is drawn per character from its index, so it
// never flickers.
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes bone instances and the draw arguments
#include "bindings.glsl"
#include "culling.glsl"
#include "joint_sprites.glsl"
#include "character_look.glsl"
#include "lod_fade.glsl"
#include "slot_allocation.glsl"

layout(local_size_x = kAllocationGroup) in;

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
    const CharacterPose pose = characterPose(character, clip);
    const Ankles ankles = characterAnkles(pose);
    for (uint j = 0; j < clip.jointCount; ++j) {
        const vec4 rotation = poseToWorldRotation(pose, jointRotation(pose, j));
        const vec3 position = poseToWorld(pose, jointTranslation(pose, ankles, j));
        const PoseGpu bind = bindPoses[clip.firstJoint + j];
        const vec4 skinning = quatMultiply(rotation, vec4(-bind.rotation.xyz, bind.rotation.w));
        skinJoints[first + j] = PoseGpu(skinning, vec4(position - rotateByQuaternion(skinning, character.scale * bind.translation.xyz), character.scale));
    }
    const uint slot = atomicAdd(skinDraws[clip.skeleton].instanceCount, 1u);
    skinCharacters[skinDraws[clip.skeleton].firstInstance + slot] = uvec2(m, floatBitsToUint(fade));
    atomicAdd(draw.skinCharacters, 1u);
}

// A character's bones as tapered capsules for bone.vert/bone.frag, from bone instance `slot`
// on, with lod_fade.glsl's fade; counted unless it is fading out under its skinned mesh.
void writeBones(uint m, CharacterGpu character, ClipGpu clip, float fade, bool countsCharacter, uint slot) {
    if (countsCharacter) atomicAdd(draw.boneCharacters, 1u);
    const float girth = character.scale * buildOf(push.firstCharacter + m);
    const vec3 shirt = unpackUnorm4x8(character.color).rgb;
    const float yaw = character.groundFrame.w;
    const vec3 sideways = vec3(cos(yaw), 0.0, -sin(yaw));  // the character's +X in the world
    const CharacterPose pose = characterPose(character, clip);
    const Ankles ankles = characterAnkles(pose);
    for (uint b = 0; b < clip.boneCount; ++b) {
        const BoneGpu bone = bones[clip.firstBone + b];
        const vec3 start = poseToWorld(pose, jointTranslation(pose, ankles, bone.joint));
        vec3 end;
        if (bone.child != kBoneToEndSite) {
            end = poseToWorld(pose, jointTranslation(pose, ankles, bone.child));
        } else {
            const vec4 rotation = poseToWorldRotation(pose, jointRotation(pose, bone.joint));
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
}

// What one character draws this frame, from its place on screen: nothing (culled), joint
// spheres below push.bonePixels, bones above, a skinned mesh from push.skinPixels; a character
// that crosses a threshold cross-fades from one level into the next over a few frames
// (lod_fade.glsl; --body bones and --body skin set the thresholds so that one level is drawn).
struct Plan {
    bool visible;
    float tall;
    bool coarse;    // the joint spheres leave detail joints out
    float bonesIn;  // lod_fade.glsl's fade of bones in over joint spheres
    float skinIn;   // and of skin over bones
};

// The passes (specialisation constant 1), see below.
const uint kPlan = 0u, kWriterSprites = 1u, kWriterBones = 2u, kWriterSkin = 3u, kAllocate = 4u;
layout(constant_id = 1) const uint kPass = kPlan;

// Character m's plan. The planning pass moves its levels' histories on by this frame
// (lod_fade.glsl) and keeps them for the writers and the next frame: bones over joint spheres in
// the low half of its LevelFades word, skin over bones in the high.
Plan planFor(uint m, CharacterGpu character) {
    Plan plan;
    plan.tall = tallInView(character, plan.visible);
    plan.coarse = plan.tall < push.lodPixels;
    uint histories = levelFades[m];
    if (kPass == kPlan) {
        // A still, another crowd's frame, or out of view (where no fade would be seen): the level
        // its size asks for (out of view, by its distance: tallInView gives it no height).
        const bool continues = plan.visible && scene.cameraPosition.w > 0.0;
        const float tall = plan.visible ? plan.tall : pixelsTall(character, characterCentre(character));
        histories = levelHistory(histories & 0xffffu, tall, push.bonePixels, continues) |
                    (levelHistory(histories >> 16, tall, push.skinPixels, continues) << 16);
        levelFades[m] = histories;
    }
    plan.skinIn = levelFade(histories >> 16);
    // Skin fades in over whole bones: a character crossing both thresholds within a fade (a fast
    // zoom) is never drawn at three levels, joint spheres and bones keeping the same pixels.
    plan.bonesIn = plan.skinIn > 0.0 ? 1.0 : levelFade(histories & 0xffffu);
    return plan;
}

// The passes: the plan lists each visible character for the writers it needs; then one pass
// per writer takes its list. A CPU device runs every writer for a SIMD vector of characters if
// any of them needs it (its shaders keep an execution mask rather than branch), so one pass
// doing all three paid for bones and skin for almost every character; listed, each writer runs
// only for the characters that need it. The allocation pass (kAllocate, slot_allocation.glsl)
// runs between them.

// Lists character m for writer w (kWriter*), growing that writer's dispatch to match.
void list(uint m, uint w) {
    const uint at = atomicAdd(draw.listed[w - 1u], 1u);
    characterLists[(w - 1u) * push.characterCount + at] = m;
    atomicMax(draw.writerDispatch[3u * (w - 1u)], splatGroupsFor(at + 1u));
}

// Lists character m for the writers its plan needs; returns the joint spheres and bones it
// asks for, and whether its joint spheres are the coarse ones (slot_allocation.glsl's kSlotCoarse).
uvec2 planCharacter(uint m, out uint decision) {
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const Plan plan = planFor(m, character);
    decision = plan.coarse ? kSlotCoarse : 0u;
    if (!plan.visible || plan.bonesIn <= 0.0) {  // culled, or joint spheres alone
        bodyLevels[m] = BodyLevelGpu(plan.visible ? 1u : 0u, plan.tall, 0u, 0u);
        if (!plan.visible) return uvec2(0u);
        list(m, kWriterSprites);
        return uvec2(keptJoints(clip, plan.coarse), 0u);
    }
    uvec2 asked = uvec2(0u);
    if (plan.bonesIn < 1.0 || (plan.skinIn > 0.0 && plan.skinIn < 1.0)) atomicAdd(draw.fadingCharacters, 1u);
    if (plan.bonesIn < 1.0) {  // fading out under bones
        list(m, kWriterSprites);
        asked.x = keptJoints(clip, plan.coarse);
    }
    if (plan.skinIn > 0.0) list(m, kWriterSkin);
    if (plan.skinIn < 1.0) {  // alone, or fading out under skin
        list(m, kWriterBones);
        asked.y = clip.boneCount;
    }
    return asked;
}

void writeCharacter(uint m) {
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const Plan plan = planFor(m, character);
    if (kPass == kWriterSprites) {
        // Coarse or not as the plan counted its joints (slot_allocation.glsl's decision).
        writeJointSprites(m, character, clip, (slotDecision(m) & kSlotCoarse) != 0u, false, plan.bonesIn <= 0.0 ? 1.0 : -plan.bonesIn,
                          slotsOf(m).x);
    } else if (kPass == kWriterBones) {
        const bool underSkin = plan.skinIn > 0.0;
        const uint first = slotsOf(m).y;
        writeBones(m, character, clip, underSkin ? -plan.skinIn : plan.bonesIn, !underSkin, first);
        bodyLevels[m] = BodyLevelGpu(underSkin ? 3u : 2u, plan.tall, first, clip.boneCount);
    } else {
        writeSkinJoints(m, character, clip, plan.skinIn);
        if (plan.skinIn >= 1.0) bodyLevels[m] = BodyLevelGpu(3u, plan.tall, 0u, 0u);  // no bones under it
    }
}

void main() {
    if (kPass == kPlan) {
        const uint m = gl_GlobalInvocationID.x;
        uint decision = 0u;
        countOff(m < push.characterCount ? planCharacter(m, decision) : uvec2(0u), decision);
        return;
    }
    if (kPass == kAllocate) {
        allocateSlots();
        return;
    }
    // A writer: dispatched indirectly with the workgroups its list asked for.
    const uint w = kPass - 1u;
    for (uint i = gl_GlobalInvocationID.x; i < draw.listed[w]; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x)
        writeCharacter(characterLists[w * push.characterCount + i]);
}
