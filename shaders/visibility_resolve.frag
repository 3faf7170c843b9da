#version 450
// The visibility path's resolve: where the splat left a sphere, shade it as impostor.frag
// does (the same ray, normal and lighting) at the depth the splat kept; elsewhere keep what
// is there (the ground).
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"
#include "sphere_cast.glsl"
#include "visibility.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    const uint64_t key = visibility[uint(gl_FragCoord.y) * uint(scene.viewport.x) + uint(gl_FragCoord.x)];
    if (key == kNothingVisible) discard;
    const InstanceGpu instance = instances[uint(key & 0xffffffffUL)];
    const vec4 sphere = instance.positionRadius;
    // The splat found this pixel's ray on the sphere; rounding may put this cast a hair
    // outside it, so it takes the rim there rather than miss.
    SphereHit ray;
    if (!castSphere(gl_FragCoord.xy, sphere, ray)) ray.t = dot(sphere.xyz - scene.cameraPosition.xyz, ray.direction);
    const vec3 hit = scene.cameraPosition.xyz + ray.t * ray.direction;
    gl_FragDepth = uintBitsToFloat(uint(key >> 32));
    outColor = vec4(shade(instance.color.rgb, (hit - sphere.xyz) / sphere.w, hit, 48.0, 0.35), 1.0);
}
