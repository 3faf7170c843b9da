#version 450
// Bone bodies: the pixels of a bone's quad, ray-cast against its tapered capsule
// (bone_cast.glsl) for an exact silhouette, normal and depth.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"
#include "lod_fade.glsl"
#include "bone_cast.glsl"
#include "sphere_cast.glsl"

layout(location = 0) flat in vec4 boneStart;
layout(location = 1) flat in vec4 boneEnd;
layout(location = 2) flat in vec4 boneFlatten;
layout(location = 3) flat in vec4 albedo;  // rgb, fade
layout(location = 0) out vec4 outColor;
layout(depth_greater) out float gl_FragDepth;

void main() {
    if (!keptByFade(albedo.a, gl_FragCoord.xy)) discard;
    const vec3 eye = scene.cameraPosition.xyz;
    const vec3 direction = pixelRay(gl_FragCoord.xy);
    const BoneHit bone = castBone(eye, direction, boneStart, boneEnd, boneFlatten);
    if (bone.t == kMiss) discard;
    const vec3 hit = eye + bone.t * direction;
    const vec4 clip = scene.viewProjection * vec4(hit, 1.0);
    gl_FragDepth = clip.z / clip.w;
    // Alpha-to-coverage smooths the silhouette over about a pixel: how far the ray passes
    // inside the capsule, in pixels.
    const float rim = bone.inside * scene.viewport.z / max(bone.t, 1e-3);
    outColor = vec4(shade(albedo.rgb, unflatten(bone.normal, boneFlatten), hit, 16.0, 0.12), clamp(rim + 0.5, 0.0, 1.0));
}
