// Order-preserving allocation of the compacted joint spheres and bones (resolve_cull.comp,
// resolve_bones.comp). Reserving each character's room with an atomic add put characters'
// joints and bones in whatever order the invocations ran, and where two bodies tie (at equal
// depth where two characters touch, in the fast path's draws; at equal distance in the
// visibility buffer, which keeps the lower instance) the image could change from run to run:
// in the fast path's bones, about one run in ten at 300 characters. Now a counting pass has each
// workgroup count off, in character order, the joints and bones its characters ask for; one
// workgroup turns the workgroups' totals into where each workgroup's start (allocateSlots); and
// a writer puts a character's at its workgroup's start plus its place. The slots live in
// characterLists (bindings.glsl's characterSlotsStart). Needs THRONG_COMPUTE_WRITES.
#ifndef THRONG_SLOT_ALLOCATION_GLSL
#define THRONG_SLOT_ALLOCATION_GLSL

#include "bindings.glsl"

// The workgroup size of the passes that include this (binding_numbers.h, C++'s kPlanWorkgroup).
const uint kAllocationGroup = THRONG_ALLOCATION_GROUP;

// A character's joints' slot word also keeps what the counting pass decided, so that the
// writer, which runs in another pipeline, writes exactly what was counted (recomputed there, a
// frustum or size test rounded the other way would spill into the next character's slots):
// kSlotWrites, it has joints to write; kSlotCoarse, only its major ones. Its place is below.
const uint kSlotWrites = 1u << 30, kSlotCoarse = 1u << 31, kSlotPlace = kSlotWrites - 1u;
shared uvec2 counted[kAllocationGroup];
shared uvec2 countedTotal;

// Where character m's joint spheres (x) and bones (y) start among all written, once
// allocateSlots has run.
uvec2 slotsOf(uint m) {
    const uint at = characterSlotsStart() + 2u * m, start = groupSlotsStart() + 2u * (m / kAllocationGroup);
    return uvec2(characterLists[start], characterLists[start + 1u]) + uvec2(characterLists[at] & kSlotPlace, characterLists[at + 1u]);
}

// What the counting pass decided for character m's joints (kSlotWrites, kSlotCoarse).
uint slotDecision(uint m) { return characterLists[characterSlotsStart() + 2u * m] & ~kSlotPlace; }

// Counting off a workgroup's uvec2 counts (one per invocation, in counted[]) in invocation
// order: each becomes the sum of those before it; returns the total. Called by every invocation
// (barriers); the first does the sums, which on a CPU device costs less than a scan's steps.
uvec2 countOffInOrder() {
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        uvec2 total = uvec2(0u);
        for (uint i = 0u; i < kAllocationGroup; ++i) {
            const uvec2 asked = counted[i];
            counted[i] = total;
            total += asked;
        }
        countedTotal = total;
    }
    barrier();
    return countedTotal;
}

// The counting pass's part, for every invocation of a workgroup (gl_GlobalInvocationID.x is
// the character; `asked` is 0 past the last): records where its joints and bones go among its
// workgroup's, with `decision` (kSlotWrites, kSlotCoarse), and the workgroup's totals.
void countOff(uvec2 asked, uint decision) {
    const uint m = gl_GlobalInvocationID.x;
    counted[gl_LocalInvocationIndex] = asked;
    const uvec2 total = countOffInOrder();
    if (gl_LocalInvocationIndex == 0u) {
        const uint start = groupSlotsStart() + 2u * gl_WorkGroupID.x;
        characterLists[start] = total.x;
        characterLists[start + 1u] = total.y;
    }
    if (m < push.characterCount) {
        const uvec2 place = counted[gl_LocalInvocationIndex];
        characterLists[characterSlotsStart() + 2u * m] = place.x | decision;
        characterLists[characterSlotsStart() + 2u * m + 1u] = place.y;
    }
}

// The allocation pass, one workgroup: each invocation sums a run of the counting workgroups'
// totals, the runs are counted off in order, then each run's workgroups get where they start.
// The totals of all become the draws' counts and the splats' dispatches.
void allocateSlots() {
    const uint local = gl_LocalInvocationIndex;
    const uint groups = (push.characterCount + kAllocationGroup - 1u) / kAllocationGroup;
    const uint run = (groups + kAllocationGroup - 1u) / kAllocationGroup;
    const uint first = min(local * run, groups), last = min(first + run, groups);
    uvec2 sum = uvec2(0u);
    for (uint g = first; g < last; ++g) sum += uvec2(characterLists[groupSlotsStart() + 2u * g], characterLists[groupSlotsStart() + 2u * g + 1u]);
    counted[local] = sum;
    const uvec2 total = countOffInOrder();
    if (local == 0u) {
        draw.vertexCount = total.x;
        draw.jointSplatGroups = splatGroupsFor(total.x);  // the visibility path's splats
        draw.boneInstanceCount = total.y;
        draw.boneSplatGroups = splatGroupsFor(total.y);
    }
    uvec2 start = counted[local];
    for (uint g = first; g < last; ++g) {
        const uint at = groupSlotsStart() + 2u * g;
        const uvec2 workgroup = uvec2(characterLists[at], characterLists[at + 1u]);
        characterLists[at] = start.x;
        characterLists[at + 1u] = start.y;
        start += workgroup;
    }
}

#endif
