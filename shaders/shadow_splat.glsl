// The visibility path's contact shadows (bone bodies), splatted: each character's shadow is an
// ellipse on the ground (contact_shadow.vert's: about a body's width across and a stride long,
// turned with the character, just above the ground), and each shadow texel (2 x 2 pixels,
// visibility.glsl's shadowSlot) whose centre's ray meets the ground inside it adds how much
// light the shadow takes there to the texel's total. The shading darkens the ground by what
// all the shadows over a pixel take together: the product of what each lets through, as
// blending them one over another would give, in any order (the sum is of integers).
// splat_shadows.comp casts a character's shadow in one invocation; a shadow too large for
// that, splat_large_shadows.comp casts with a whole workgroup.
#ifndef THRONG_SHADOW_SPLAT_GLSL
#define THRONG_SHADOW_SPLAT_GLSL

#include "bindings.glsl"
#include "shading_tiles.glsl"
#include "splat_frame.glsl"
#include "visibility.glsl"

const float kShadowHeight = 0.004;  // contact_shadow.vert's

// One character's shadow: its ellipse and the texels of its screen bound.
struct Shadow {
    vec3 centre, sideways, forward;  // on the ground; the ellipse's half axes
    vec2 inverseAxes;                // 1 / their squared lengths
    ivec2 lo, hi;                    // the bound in texels, inclusive, inside the frame (empty: lo > hi somewhere)
    PixelRays rays;                  // through texel lo's centre, and per texel
};

// Character m's shadow; false when there is none to cast (not in the crowd yet, or the
// ground seen from below).
bool shadowOf(uint m, SplatFrame frame, float cullHeight, out Shadow shadow) {
    const CharacterGpu character = characters[m];
    const float extent = cullHeight * character.scale;  // about half the character's height
    const float yaw = character.groundFrame.w;
    shadow.sideways = vec3(cos(yaw), 0.0, -sin(yaw)) * (0.36 * extent);
    shadow.forward = vec3(sin(yaw), 0.0, cos(yaw)) * (0.5 * extent);
    shadow.centre = vec3(character.groundFrame.x, kShadowHeight, character.groundFrame.z);
    shadow.inverseAxes = vec2(1.0 / dot(shadow.sideways, shadow.sideways), 1.0 / dot(shadow.forward, shadow.forward));
    // The screen bound of the quad around the ellipse, clipped to what lies in front of the eye
    // (each corner in front, and where an edge crosses the plane just in front of it).
    vec4 corners[4];
    for (int corner = 0; corner < 4; ++corner) {
        const vec2 at = vec2(corner == 1 || corner == 2 ? 1.0 : -1.0, corner >= 2 ? 1.0 : -1.0);  // round the quad
        corners[corner] = frame.viewProjection * vec4(shadow.centre + at.x * shadow.sideways + at.y * shadow.forward, 1.0);
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
    // NDC to pixels, within the screen (a bound far outside it stays finite); then the texels
    // whose centres it holds (texel t's at pixel coordinates kShadowTexel t + 1, the corner its
    // pixels share).
    low = clamp((low * 0.5 + 0.5) * frame.viewport.xy, vec2(-1.0), frame.viewport.xy + 1.0);
    high = clamp((high * 0.5 + 0.5) * frame.viewport.xy, vec2(-1.0), frame.viewport.xy + 1.0);
    const float texel = float(kShadowTexel);
    shadow.lo = max(ivec2(ceil((low - 1.0) / texel)), ivec2(0));
    shadow.hi = min(ivec2(floor((high - 1.0) / texel)), ivec2(shadowTexelGrid(frame.viewport.xy)) - 1);
    shadow.rays = raysFrom(frame, vec2(shadow.lo) * texel + 1.0, texel);
    // Not in the crowd yet (a track that has not started), or the ground seen from below.
    return character.scale > 0.0 && frame.eye.y > kShadowHeight;
}

// The pixels whose shading reads texels of the shadow's bound: each texel's own 2 x 2, and a
// pixel to either side (shadowSumAt's bilinear reach), within the frame. Empty where the bound is.
void shadowPixelBound(Shadow shadow, SplatFrame frame, out ivec2 lo, out ivec2 hi) {
    lo = max(shadow.lo * int(kShadowTexel) - 1, ivec2(0));
    hi = min(shadow.hi * int(kShadowTexel) + int(kShadowTexel), ivec2(frame.viewport.xy) - 1);
    if (any(greaterThan(shadow.lo, shadow.hi))) hi = lo - 1;
}

// Adds the shadow at texel lo + offset of its bound.
void shadowTexel(Shadow shadow, ivec2 offset, SplatFrame frame) {
    const vec4 near = shadow.rays.first + shadow.rays.stepY * float(offset.y) + shadow.rays.stepX * float(offset.x);
    const vec3 eye = frame.eye;
    const vec3 direction = near.xyz / near.w;  // the near point's offset from the eye
    if (direction.y >= 0.0) return;
    const vec3 onGround = eye + direction * ((kShadowHeight - eye.y) / direction.y);
    const vec3 toPoint = onGround - shadow.centre;
    const float r = length(vec2(dot(toPoint, shadow.sideways), dot(toPoint, shadow.forward)) * shadow.inverseAxes);
    if (r >= 1.0) return;
    // contact_shadow.frag's opacity, into the fog with the ground under it.
    const float fog = smoothstep(frame.fog.x, frame.fog.y, distance(onGround, eye));
    const float opacity = 0.6 * (1.0 - smoothstep(0.3, 1.0, r)) * (1.0 - fog);
    const uvec2 texel = uvec2(shadow.lo + offset);
    atomicAdd(shadows[shadowSlot(texel, shadowRowPitch(frame.viewport.xy))], uint(-log2(1.0 - opacity) * kShadowScale + 0.5));
}

#endif
