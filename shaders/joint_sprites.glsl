// The fast path's joint spheres for one visible character, written by a culling compute pass
// (resolve_cull.comp, and resolve_bones.comp for characters too small for bones) where
// slot_allocation.glsl allots them, in character order: one instance per joint kept, in order.
// Needs THRONG_COMPUTE_WRITES.
#ifndef THRONG_JOINT_SPRITES_GLSL
#define THRONG_JOINT_SPRITES_GLSL

#include "bindings.glsl"
#include "pose.glsl"

// The joints a character draws as spheres: a coarse one's come from its clip's list of those
// kept (palette.cpp): a CPU device runs each iteration of a loop for every lane, masked, so
// skipping the detail joints inside a loop over all of them still paid to sample each.
uint keptJoints(ClipGpu clip, bool coarse) { return coarse ? clip.coarseJointCount : clip.jointCount; }

// Writes character m's joint spheres from instance `slot` on (keptJoints of them). coarse:
// leave out the detail joints (level of detail); withOwners: also record the (character,
// joint) of each instance (only where the owners buffer is sized for them); fade:
// lod_fade.glsl's, 1 when the spheres are the only level drawn (then they are counted).
void writeJointSprites(uint m, CharacterGpu character, ClipGpu clip, bool coarse, bool withOwners, float fade, uint slot) {
    const uint kept = keptJoints(clip, coarse);
    if (fade < 1.0) {
        // fading out under a nearer level, which counts the character
    } else if (coarse) {
        atomicAdd(draw.coarseCharacters, 1u);
    } else {
        atomicAdd(draw.fullCharacters, 1u);
    }
    const vec4 color = vec4(unpackUnorm4x8(character.color).rgb, fade);
    const CharacterPose pose = characterPose(character, clip);
    const Ankles ankles = characterAnkles(pose);
    for (uint k = 0; k < kept; ++k) {
        const uint j = coarse ? jointInfo[clip.firstCoarseJoint + k] : k;
        // Spheres need no orientation; the fast path samples the position only.
        const vec3 world = poseToWorld(pose, jointTranslation(pose, ankles, j));
        instances[slot] = InstanceGpu(vec4(world, jointRadiusAt(clip, j) * character.scale), vec4(0.0, 0.0, 0.0, 1.0), color);
        if (withOwners) instanceOwners[slot] = uvec2(m, j);  // character, joint
        ++slot;
    }
}

#endif
