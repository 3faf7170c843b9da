#version 450
// Ray-casts the joint's sphere through this pixel: exact silhouette, normal and depth.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"
#include "lod_fade.glsl"

layout(location = 0) flat in vec4 sphere;
layout(location = 1) flat in vec4 albedo;  // rgb, fade
layout(location = 0) out vec4 outColor;
layout(depth_greater) out float gl_FragDepth;

void main() {
    if (!keptByFade(albedo.a, gl_FragCoord.xy)) discard;
    const vec2 ndc = gl_FragCoord.xy / scene.viewport.xy * 2.0 - 1.0;
    const vec4 nearPoint = scene.inverseViewProjection * vec4(ndc, 0.0, 1.0);
    const vec3 eye = scene.cameraPosition.xyz;
    const vec3 direction = normalize(nearPoint.xyz / nearPoint.w - eye);
    const vec3 fromCentre = eye - sphere.xyz;
    const float b = dot(fromCentre, direction);
    const float missSq = dot(fromCentre, fromCentre) - b * b;  // squared distance of the ray from the centre
    const float radiusSq = sphere.w * sphere.w;
    if (missSq > radiusSq) discard;
    const float t = -b - sqrt(radiusSq - missSq);
    const vec3 hit = eye + t * direction;
    const vec4 clip = scene.viewProjection * vec4(hit, 1.0);
    gl_FragDepth = clip.z / clip.w;
    // Alpha-to-coverage smooths the silhouette over about one pixel: the ray's distance from
    // the rim, in pixels at this depth.
    const float pixelsPerMetre = scene.viewport.z / max(t, 1e-3);
    const float rim = (sphere.w - sqrt(missSq)) * pixelsPerMetre;
    outColor = vec4(shade(albedo.rgb, (hit - sphere.xyz) / sphere.w, hit, 48.0, 0.35), clamp(rim + 0.5, 0.0, 1.0));
}
