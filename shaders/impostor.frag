#version 450
// Ray-casts the joint's sphere through this pixel: exact silhouette, normal and depth.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"
#include "lod_fade.glsl"
#include "sphere_cast.glsl"

layout(location = 0) flat in vec4 sphere;
layout(location = 1) flat in vec4 albedo;  // rgb, fade
layout(location = 0) out vec4 outColor;
layout(depth_greater) out float gl_FragDepth;

void main() {
    if (!keptByFade(albedo.a, gl_FragCoord.xy)) discard;
    SphereHit ray;
    if (!castSphere(gl_FragCoord.xy, sphere, ray)) discard;
    const vec3 hit = scene.cameraPosition.xyz + ray.t * ray.direction;
    const vec4 clip = scene.viewProjection * vec4(hit, 1.0);
    gl_FragDepth = clip.z / clip.w;
    // Alpha-to-coverage smooths the silhouette over about one pixel: the ray's distance from
    // the rim, in pixels at this depth.
    const float pixelsPerMetre = scene.viewport.z / max(ray.t, 1e-3);
    const float rim = (sphere.w - sqrt(ray.missSq)) * pixelsPerMetre;
    outColor = vec4(shade(albedo.rgb, (hit - sphere.xyz) / sphere.w, hit, 48.0, 0.35), clamp(rim + 0.5, 0.0, 1.0));
}
