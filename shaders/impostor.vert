#version 450
// Fast path: each joint is one point sprite just big enough to cover its sphere on screen;
// the fragment shader ray-casts the exact sphere. One vertex per joint instead of a mesh.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 0) flat out vec4 sphere;  // world centre, radius
layout(location = 1) flat out vec4 albedo;  // rgb, and the level-of-detail fade (lod_fade.glsl)

void main() {
    const InstanceGpu instance = instances[gl_VertexIndex];
    sphere = instance.positionRadius;
    albedo = instance.color;
    const vec3 centre = sphere.xyz;
    const float radius = sphere.w;
    const vec4 clip = scene.viewProjection * vec4(centre, 1.0);
    if (radius <= 0.0 || clip.w <= radius * 1.5) {  // nothing to draw, or too close to bound safely
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        gl_PointSize = 1.0;
        return;
    }
    // A sphere at view depth w covers about 2 r f / (w - r) pixels; off-axis perspective
    // stretches it a little, so pad by 15% and two pixels.
    gl_PointSize = min(2.0 * radius * scene.viewport.z / (clip.w - radius) * 1.15 + 2.0, scene.viewport.w);
    // The sprite sits at the depth of the sphere's nearest point, so every depth the fragment
    // shader writes is greater: with depth_greater the rasteriser may still reject early.
    const vec3 towardEye = normalize(scene.cameraPosition.xyz - centre);
    const vec4 front = scene.viewProjection * vec4(centre + towardEye * radius, 1.0);
    gl_Position = vec4(clip.xy / clip.w * front.w, front.z, front.w);
}
