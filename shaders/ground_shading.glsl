// The ground's shading, shared by the ground pass (ground.frag) and the visibility path's
// shading pass, which shades the ground where no joint is: paving of the two-tone checker
// of 2 m squares, each laid as 4 x 4 slabs of 0.5 m with faint joints between them and a
// slight tone of its own. Every pattern is filtered by its screen-space footprint, so none
// aliases: far away the joints fade into an even tone and the slabs' tones into their mean,
// and the detail stays quieter than the crowd on it.
#ifndef THRONG_GROUND_SHADING_GLSL
#define THRONG_GROUND_SHADING_GLSL

#include "bindings.glsl"
#include "lighting.glsl"

const float kSlabsPerSquare = 4.0;
const float kJointWidth = 0.05;   // of a slab: 2.5 cm
const float kJointDarkening = 0.14;
const float kSlabToneSpread = 0.05;

// The mean over [x - w/2, x + w/2] of a pulse train that is 1 on [n - kJointWidth/2,
// n + kJointWidth/2] for every integer n: the integral of the train, differenced.
vec2 filteredJoints(vec2 x, vec2 w) {
    const vec2 shifted = x + 0.5 * kJointWidth;
    const vec2 lo = shifted - 0.5 * w, hi = shifted + 0.5 * w;
    const vec2 integralLo = floor(lo) * kJointWidth + min(fract(lo), vec2(kJointWidth));
    const vec2 integralHi = floor(hi) * kJointWidth + min(fract(hi), vec2(kJointWidth));
    return (integralHi - integralLo) / w;
}

// A slab's own tone in [-1, 1), from its integer coordinates.
float slabTone(vec2 slab) {
    uvec2 q = uvec2(ivec2(slab) + ivec2(32768));
    uint h = q.x * 0x8da6b343u ^ q.y * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return float(h >> 8) * (2.0 / 16777216.0) - 1.0;
}

// The lit, fogged colour of the ground at `worldPosition` (on y = 0), where a pixel covers
// `width` checker squares along x and z (the fwidth of worldPosition.xz / checker size).
vec3 groundAlbedo(vec3 worldPosition, vec2 width) {
    const vec2 cell = worldPosition.xz / scene.groundParams.y;
    width = max(width, vec2(1e-4));
    // Integral of a square wave over the pixel footprint: the box-filtered checker.
    const vec2 i = (2.0 * (abs(fract((cell - 0.5 * width) * 0.5) - 0.5) - abs(fract((cell + 0.5 * width) * 0.5) - 0.5))) / width;
    const float checker = 0.5 - 0.5 * i.x * i.y;
    vec3 albedo = mix(vec3(0.34, 0.35, 0.33), vec3(0.28, 0.29, 0.28), checker);

    const vec2 slab = cell * kSlabsPerSquare, slabWidth = width * kSlabsPerSquare;
    // A slab's tone shows only while a pixel covers less than about one slab.
    const float toneVisible = 1.0 - smoothstep(0.3, 1.0, max(slabWidth.x, slabWidth.y));
    albedo *= 1.0 + kSlabToneSpread * toneVisible * slabTone(floor(slab));
    const vec2 joints = filteredJoints(slab, max(slabWidth, vec2(1e-4)));
    const float joint = joints.x + joints.y - joints.x * joints.y;  // either direction's joint
    albedo *= 1.0 - kJointDarkening * joint;
    return albedo;
}

vec3 groundColor(vec3 worldPosition, vec2 width) { return shade(groundAlbedo(worldPosition, width), vec3(0.0, 1.0, 0.0), worldPosition, 16.0, 0.05); }

// groundColor seen along `view` from `distanceToEye`.
vec3 groundColorSeen(vec3 worldPosition, vec2 width, View view, float distanceToEye) {
    return shadeSeen(groundAlbedo(worldPosition, width), vec3(0.0, 1.0, 0.0), view, distanceToEye, 16.0, 0.05);
}

// Where the ray from the eye along `direction` meets the ground plane (y = 0) within the
// ground's square: the visibility path's shading takes a pixel's ground from it, and its skinned
// bodies their test against the ground (skin_shading.glsl). `direction` need not be a unit
// vector: t is in its lengths.
struct GroundHit {
    float t;       // along the ray; -1 when the ray never comes down to the plane
    vec3 point;
    bool onGround;
};

GroundHit groundAlong(vec3 direction) {
    const vec3 eye = scene.cameraPosition.xyz;
    GroundHit ground;
    ground.t = direction.y < 0.0 ? -eye.y / direction.y : -1.0;
    ground.point = eye + max(ground.t, 0.0) * direction;
    ground.onGround = ground.t > 0.0 && all(lessThanEqual(abs(ground.point.xz), vec2(scene.groundParams.x)));
    return ground;
}

#endif
