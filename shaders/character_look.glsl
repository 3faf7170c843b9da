// How a character looks, drawn from its index so it never flickers: the colours of its
// clothing and skin, and its build. Shared by the bone bodies and the skinned bodies.
#ifndef THRONG_CHARACTER_LOOK_GLSL
#define THRONG_CHARACTER_LOOK_GLSL

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

// Build: limbs and trunk 12% slimmer to 15% broader, lengths untouched (height already varies).
float buildOf(uint m) { return mix(0.88, 1.15, unitHash(m, 0u)); }

#endif
