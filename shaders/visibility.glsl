// The visibility path's buffer: per pixel, the frame's epoch (top 4 bits), the nearest body's
// distance along the pixel's unit ray from the eye (the next 28, the float's bits less the
// exponents below kNearestDistance, which order as positive floats do) and its joint or bone
// (low 32), so one 64-bit atomicMin keeps the nearest, and the lower instance where two tie:
// the same image however the splats interleave. The shading takes the hit point back from the
// distance instead of casting again.
//
// The epoch counts down from frame to frame (SceneUniforms::visibilityEpoch), so a key the
// buffer kept from an earlier frame loses to any of this frame's and reads as nothing: the
// buffer is filled (all ones: nothing there) only when the count starts again, one frame in
// THRONG_VISIBILITY_EPOCHS. On lavapipe the fill of every frame (7 MB at 1280 x 720, on one CPU
// thread while the others waited) cost a 2000-character frame about 0.25 ms.
#ifndef THRONG_VISIBILITY_GLSL
#define THRONG_VISIBILITY_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "binding_numbers.h"

// Where a pixel's key and shadow lie in their buffers: in 4 x 4-pixel blocks, one after another
// along the frame's rows of blocks, each block's pixels row by row (the frame padded to whole
// blocks: CrowdRenderer::visibilityBufferPixels). A cache line then holds a 4 x 2 block of keys,
// the 8 pixels lavapipe shades as one vector, or a 4 x 4 block of shadows, where along the
// frame's rows those 8 pixels' keys lay on two lines and their shadows on two. The shading
// waits on those reads' cache misses (most in the VM's slow spells): about 0.2 ms less of it at
// 2000 characters, the same bytes.
const uint kPixelBlock = THRONG_PIXEL_BLOCK;  // pixels a side (binding_numbers.h, C++ reads it too)
uint pixelSlot(uvec2 pixel, uint width) {
    const uint blocksAcross = (width + kPixelBlock - 1u) / kPixelBlock;
    const uvec2 block = pixel / kPixelBlock, within = pixel % kPixelBlock;
    return (block.y * blocksAcross + block.x) * (kPixelBlock * kPixelBlock) + within.y * kPixelBlock + within.x;
}

#ifdef THRONG_COMPUTE_WRITES
layout(set = 0, binding = THRONG_BINDING_VISIBILITY, std430) buffer Visibility { uint64_t visibility[]; };
#else
// The shading reads the buffer through a texel view of it (R32G32_UINT: the key's low word,
// then its high one): lavapipe fetches a texel buffer's texels for all lanes as one gather,
// where it loads a storage buffer's values lane by lane, each behind a branch. With the
// shadows' view below, that took about 0.4 ms off the 2000-character frame's shading.
layout(set = 0, binding = THRONG_BINDING_VISIBILITY_TEXELS) uniform usamplerBuffer visibilityTexels;
#endif

const uint64_t kNothingVisible = 0xffffffffffffffffUL;  // its epoch, 15, is none of the frames' (THRONG_VISIBILITY_EPOCHS)
// Distances are kept from kNearestDistance to kFarthestDistance metres (nearer and farther ones
// are clamped: no body is drawn within 4 mm of the eye, and the ground ends long before 8000 km),
// which leaves the float's 23 bits of mantissa and 5 of exponent: 28 bits.
const float kNearestDistance = 1.0 / 256.0, kFarthestDistance = 8388608.0;
const uint kNearestDistanceBits = 0x3b800000u;  // floatBitsToUint(kNearestDistance)

// Bone bodies' contact shadows (splat_shadows.comp): per texel, the light the shadows over it
// take, as the sum of -log2 of what each lets through, in 1/kShadowScale steps (0: none). A
// shadow takes at most 60% (1.32 in log2), so even 30,000 over one texel stay within 32 bits.
//
// A texel to each 2 x 2 pixels: the shadows are splatted at half the frame's resolution and the
// shading reads them back bilinearly. A contact shadow is a soft blot. At full resolution its
// sums (4 bytes a pixel, 3.7 MB at 1280 x 720) were most of what the shading lost when this
// VM's share of the CPU's cache shrank, and their splat cast four times the rays: on lavapipe
// a 2000-character frame took 0.3 ms longer in the VM's fast spells and 0.8 in its slow ones.
// The pictures stay within a level of the full-resolution shadows in a close-up; a far shadow
// only a pixel or two tall is spread over a pixel more. Read back by nearest texel instead, a
// shadow's soft edge showed its 2 x 2 steps.
//
// Texels lie row by row with a texel of zeros all round, so that a pixel's four texels are its
// own, the next or the last, and those a row down or up, none clamped at the frame's edges.
const uint kShadowTexel = THRONG_SHADOW_TEXEL;
const float kShadowScale = 65536.0;
uvec2 shadowTexelGrid(vec2 viewport) { return (uvec2(viewport) + kShadowTexel - 1u) / kShadowTexel; }
uint shadowRowPitch(vec2 viewport) { return shadowTexelGrid(viewport).x + 2u; }  // CrowdRenderer::shadowBufferTexels
uint shadowSlot(uvec2 texel, uint rowPitch) { return (texel.y + 1u) * rowPitch + texel.x + 1u; }
#ifdef THRONG_COMPUTE_WRITES
layout(set = 0, binding = THRONG_BINDING_SHADOWS, std430) buffer Shadows { uint shadows[]; };
#else
layout(set = 0, binding = THRONG_BINDING_SHADOW_TEXELS) uniform usamplerBuffer shadowTexels;  // R32_UINT, as visibilityTexels
// The shadows' sum at a pixel, in log2 of what they let through: bilinear between the four
// texels nearest its centre. A texel's centre is the corner its 2 x 2 pixels share, so a pixel
// lies a quarter texel from its own texel's centre each way, toward the neighbour on its side:
// weights 3/4 and 1/4 along each axis.
float shadowSumAt(uvec2 pixel, vec2 viewport) {
    const uint rowPitch = shadowRowPitch(viewport), own = shadowSlot(pixel / kShadowTexel, rowPitch);
    const uint beside = (pixel.x & 1u) != 0u ? own + 1u : own - 1u;
    const int down = (pixel.y & 1u) != 0u ? int(rowPitch) : -int(rowPitch);
    const float sum = 9.0 * float(texelFetch(shadowTexels, int(own)).x) +
                      3.0 * (float(texelFetch(shadowTexels, int(beside)).x) + float(texelFetch(shadowTexels, int(own) + down).x)) +
                      float(texelFetch(shadowTexels, int(beside) + down).x);
    return sum * (1.0 / (16.0 * kShadowScale));
}
#endif
// The key's instance names a bone (boneInstances) when this bit is set, else a joint sphere
// (instances).
const uint kBoneKey = 0x80000000u;

uint64_t visibilityKey(float distance, uint instance, uint epoch) {
    const uint kept = floatBitsToUint(clamp(distance, kNearestDistance, kFarthestDistance)) - kNearestDistanceBits;
    return (uint64_t((epoch << 28) | kept) << 32) | uint64_t(instance);
}
#ifndef THRONG_COMPUTE_WRITES
// The body the splat kept at a pixel, if any this frame (epoch `epoch`): its distance along the
// pixel's ray and its instance. Read as the key's two words, with no 64-bit arithmetic.
struct KeptKey {
    bool present;
    float distance;
    uint instance;
};
KeptKey keptKeyAt(uint pixel, uint epoch) {
    const uvec2 key = texelFetch(visibilityTexels, int(pixel)).xy;  // low word (the instance), then high
    return KeptKey(key.y >> 28 == epoch, uintBitsToFloat((key.y & 0x0fffffffu) + kNearestDistanceBits), key.x);
}
#endif

#ifdef THRONG_SPLAT_ORDER
// The splats' order of work: which of `count` bodies (joints or bones, written character after
// character, `perCharacter` each) invocation `id` casts. A subgroup's invocations run in
// lockstep on a CPU device, each of its pixel loops for as long as its largest body takes, so
// they take the same body of consecutive characters (the same bone of each of 8 characters
// on lavapipe: like sizes) rather than consecutive bodies of one character (a torso beside a
// finger). Any permutation casts the same pixels to the same atomic minima, so this only
// changes how long it takes: where characters write different counts the subgroups mix bodies
// again, and the rest past the last whole run goes in order, as does everything when
// perCharacter is 0 (a first clip with no bones, others with some).
uint lockstepOrder(uint id, uint count, uint perCharacter) {
    if (perCharacter == 0u) return id;
    const uint lanes = gl_SubgroupSize, run = lanes * perCharacter;
    if (id >= count / run * run) return id;
    return id - id % run + (id % lanes) * perCharacter + (id % run) / lanes;
}
#endif

#endif
