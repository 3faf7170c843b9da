// Skinned bodies' fragment shading (skin.frag, skin_over_splat.frag): smooth-shaded like the
// other bodies (lighting.glsl), slightly soft cloth.
//
// With THRONG_SKIN_OVER_SPLAT (the visibility path), drawn after a shading pass that writes no
// depth: a fragment is hidden where the body the splat kept at its pixel is nearer along the
// pixel's ray (both are distances from the eye), or where it lies under the ground plane within
// the ground's square (the ray met the ground first). Skinned bodies still hide each other by
// the depth buffer, which only they write.
#ifndef THRONG_SKIN_SHADING_GLSL
#define THRONG_SKIN_SHADING_GLSL

#include "bindings.glsl"
#include "lighting.glsl"
#include "lod_fade.glsl"
#ifdef THRONG_SKIN_OVER_SPLAT
#include "ground_shading.glsl"
#include "visibility.glsl"
#endif

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec3 albedo;
layout(location = 3) flat in float fade;
layout(location = 0) out vec4 outColor;

#ifdef THRONG_SKIN_OVER_SPLAT
// Whether the splat's body or the ground hides this fragment.
bool hiddenBySplat() {
    const vec3 eye = scene.cameraPosition.xyz;
    const KeptKey key = keptKeyAt(pixelSlot(uvec2(gl_FragCoord.xy), uint(scene.viewport.x)), scene.visibilityEpoch);
    if (key.present && key.distance < distance(worldPosition, eye)) return true;
    // Under the plane, where the ray from the eye crossed it within the ground's square: the
    // ground the shading drew there is nearer.
    return worldPosition.y < 0.0 && groundAlong(worldPosition - eye).onGround;
}
#endif

void main() {
    if (!keptByFade(fade, gl_FragCoord.xy)) discard;
#ifdef THRONG_SKIN_OVER_SPLAT
    if (hiddenBySplat()) discard;
#endif
    outColor = vec4(shade(albedo, normalize(worldNormal), worldPosition, 16.0, 0.12), 1.0);
}

#endif
