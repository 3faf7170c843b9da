#version 450
// The fast path's compute passes: one invocation per character. A character whose bounding
// sphere is outside the view frustum writes nothing; a visible one writes its joints where
// slot_allocation.glsl allots them, in character order, so the draw touches only what can be
// seen and draws the same way every run. Joints of one character stay together and in order.
// Distant characters keep only their major joints (level of detail).
// The passes (specialisation constant 1): count the joints each character keeps, allot them
// (one workgroup), write them.
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes instances, the draw arguments and the instance owners
#include "bindings.glsl"
#include "culling.glsl"
#include "joint_sprites.glsl"
#include "slot_allocation.glsl"

layout(local_size_x = kAllocationGroup) in;

const uint kCount = 0u, kAllocate = 1u, kWrite = 2u;
layout(constant_id = 1) const uint kPass = kCount;

// Whether character m is in view and, if so, whether it keeps only its major joints: a
// character drawn only a few dozen pixels tall keeps those; the small ones would overlap them
// within a pixel or two anyway.
bool visibleAt(CharacterGpu character, out bool coarse) {
    const vec3 centre = characterCentre(character);
    coarse = false;
    if (!insideFrustum(centre, push.cullRadius * character.scale)) return false;
    coarse = pixelsTall(character, centre) < push.lodPixels;
    return true;
}

// Counts character m's joints (none when culled) and records the decision for the writer.
void count(uint m) {
    uint kept = 0u, decision = 0u;
    if (m < push.characterCount) {
        const CharacterGpu character = characters[m];
        bool coarse;
        if (visibleAt(character, coarse)) {
            kept = keptJoints(clips[character.clip], coarse);
            decision = kSlotWrites | (coarse ? kSlotCoarse : 0u);
        }
    }
    countOff(uvec2(kept, 0u), decision);
}

void main() {
    const uint m = gl_GlobalInvocationID.x;
    if (kPass == kCount) {
        count(m);
        return;
    }
    if (kPass == kAllocate) {
        allocateSlots();
        return;
    }
    if (m >= push.characterCount) return;
    const uint decision = slotDecision(m);
    if ((decision & kSlotWrites) == 0u) return;
    const CharacterGpu character = characters[m];
    writeJointSprites(m, character, clips[character.clip], (decision & kSlotCoarse) != 0u, true, 1.0, slotsOf(m).x);
}
