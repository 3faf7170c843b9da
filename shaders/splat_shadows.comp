#version 450
// The visibility path's contact shadows (bone bodies): one invocation per character casts the
// ray of every pixel inside its shadow's screen bound onto the ground and, inside the shadow's
// ellipse (contact_shadow.vert's: about a body's width across and a stride long, turned with
// the character, just above the ground), adds how much light the shadow takes there to the
// pixel's total. The shading darkens the ground by what all the shadows over a pixel
// take together: the product of what each lets through, as blending them one over another
// would give, in any order (the sum is of integers). A rasterised quad per character costs a
// CPU rasteriser more set-up than the few pixels most shadows cover.
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES
#include "bindings.glsl"
#include "visibility.glsl"

layout(local_size_x = kSplatGroupSize) in;

const float kShadowHeight = 0.004;  // contact_shadow.vert's

// One character's shadow, as splatShadow measured it.
struct Shadow {
    vec3 centre, sideways, forward;  // on the ground; the ellipse's half axes
    vec2 inverseAxes;                // 1 / their squared lengths
};

// Adds the shadow at the pixel whose centre's near-plane point (before the divide) is `near`.
void shadowPixel(Shadow shadow, ivec2 pixel, vec4 near) {
    const vec3 eye = scene.cameraPosition.xyz;
    const vec3 direction = near.xyz / near.w - eye;
    if (direction.y >= 0.0) return;
    const vec3 onGround = eye + direction * ((kShadowHeight - eye.y) / direction.y);
    const vec3 offset = onGround - shadow.centre;
    const float r = length(vec2(dot(offset, shadow.sideways), dot(offset, shadow.forward)) * shadow.inverseAxes);
    if (r >= 1.0) return;
    // contact_shadow.frag's opacity, into the fog with the ground under it.
    const float fog = smoothstep(scene.groundParams.z, scene.groundParams.w, distance(onGround, eye));
    const float opacity = 0.6 * (1.0 - smoothstep(0.3, 1.0, r)) * (1.0 - fog);
    atomicAdd(shadows[uint(pixel.y) * uint(scene.viewport.x) + uint(pixel.x)], uint(-log2(1.0 - opacity) * kShadowScale + 0.5));
}

void splatShadow(uint m) {
    const CharacterGpu character = characters[m];
    if (character.scale <= 0.0) return;  // not in the crowd yet (a track that has not started)
    const float extent = push.cullHeight * character.scale;  // about half the character's height
    const float yaw = character.groundFrame.w;
    const vec3 sideways = vec3(cos(yaw), 0.0, -sin(yaw)) * (0.36 * extent), forward = vec3(sin(yaw), 0.0, cos(yaw)) * (0.5 * extent);
    const vec3 centre = vec3(character.groundFrame.x, kShadowHeight, character.groundFrame.z);
    // The screen bound of the quad around the ellipse, clipped to what lies in front of the eye
    // (each corner in front, and where an edge crosses the plane just in front of it).
    vec4 corners[4];
    for (int corner = 0; corner < 4; ++corner) {
        const vec2 at = vec2(corner == 1 || corner == 2 ? 1.0 : -1.0, corner >= 2 ? 1.0 : -1.0);  // round the quad
        corners[corner] = scene.viewProjection * vec4(centre + at.x * sideways + at.y * forward, 1.0);
    }
    const float nearest = 1e-3;
    vec2 low = vec2(1e30), high = vec2(-1e30);
    for (int corner = 0; corner < 4; ++corner) {
        const vec4 a = corners[corner], b = corners[(corner + 1) & 3];
        if (a.w > nearest) {
            low = min(low, a.xy / a.w);
            high = max(high, a.xy / a.w);
        }
        if ((a.w > nearest) != (b.w > nearest)) {
            const vec4 crossing = mix(a, b, (nearest - a.w) / (b.w - a.w));
            low = min(low, crossing.xy / nearest);
            high = max(high, crossing.xy / nearest);
        }
    }
    const ivec2 size = ivec2(scene.viewport.xy);
    // NDC to pixels, within the screen (a bound far outside it stays finite).
    low = clamp((low * 0.5 + 0.5) * scene.viewport.xy, vec2(-1.0), scene.viewport.xy + 1.0);
    high = clamp((high * 0.5 + 0.5) * scene.viewport.xy, vec2(-1.0), scene.viewport.xy + 1.0);
    const ivec2 lo = max(ivec2(ceil(low - 0.5)), ivec2(0));
    const ivec2 hi = min(ivec2(floor(high - 0.5)), size - 1);
    const vec3 eye = scene.cameraPosition.xyz;
    if (eye.y <= kShadowHeight) return;  // the ground seen from below: no shadow on it
    const vec4 stepX = scene.inverseViewProjection[0] * (2.0 / scene.viewport.x);
    const vec4 stepY = scene.inverseViewProjection[1] * (2.0 / scene.viewport.y);
    const vec4 first = scene.inverseViewProjection * vec4((vec2(lo) + 0.5) / scene.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
    const Shadow shadow = Shadow(centre, sideways, forward, vec2(1.0 / dot(sideways, sideways), 1.0 / dot(forward, forward)));
    // Four pixels a step: lavapipe stops a shader's loops after 65,535 iterations in all, which
    // one pixel a step would reach at a shadow of 65,535 pixels (a character a metre from a
    // low camera); four a step reach it at 262,140, past which the far rows go unshadowed.
    for (int y = lo.y; y <= hi.y; ++y) {
        const vec4 row = first + stepY * float(y - lo.y);
        for (int x = lo.x; x <= hi.x; x += 4) {
            shadowPixel(shadow, ivec2(x, y), row + stepX * float(x - lo.x));
            if (x + 1 <= hi.x) shadowPixel(shadow, ivec2(x + 1, y), row + stepX * float(x + 1 - lo.x));
            if (x + 2 <= hi.x) shadowPixel(shadow, ivec2(x + 2, y), row + stepX * float(x + 2 - lo.x));
            if (x + 3 <= hi.x) shadowPixel(shadow, ivec2(x + 3, y), row + stepX * float(x + 3 - lo.x));
        }
    }
}

void main() {
    // One invocation per character of the batch (culled ones find an empty or clipped bound).
    const uint m = gl_GlobalInvocationID.x;
    if (m < push.characterCount) splatShadow(m);
}
