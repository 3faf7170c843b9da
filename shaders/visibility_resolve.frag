#version 450
// The visibility path's one full-screen pass: each pixel's ray meets the nearest of the joint
// the splat kept there (shaded as impostor.frag shades it) and the ground (shaded as
// ground.frag shades it, so the path draws no ground pass of its own); where it meets
// neither, the sky's clear colour stays. One pass instead of two: on a CPU rasteriser a
// full-screen pass costs as much as thousands of joints. It draws with one sample
// (render::samplesFor): rims are smoothed here, the ground is filtered by its footprint.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "ground_shading.glsl"
#include "lighting.glsl"
#include "sphere_cast.glsl"
#include "visibility.glsl"

layout(location = 0) out vec4 outColor;

void main() {
    // The ground plane (y = 0) along this pixel's ray, computed for every pixel so that its
    // footprint's derivatives are taken in uniform control flow.
    SphereHit ray;
    castSphere(gl_FragCoord.xy, vec4(0.0), ray);  // only its direction is wanted here
    const vec3 eye = scene.cameraPosition.xyz;
    const float groundT = ray.direction.y < 0.0 ? -eye.y / ray.direction.y : -1.0;
    const vec3 groundPoint = eye + max(groundT, 0.0) * ray.direction;
    const vec2 footprint = fwidth(groundPoint.xz / scene.groundParams.y);
    const bool onGround = groundT > 0.0 && all(lessThanEqual(abs(groundPoint.xz), vec2(scene.groundParams.x)));

    const uint64_t key = visibility[uint(gl_FragCoord.y) * uint(scene.viewport.x) + uint(gl_FragCoord.x)];
    if (key != kNothingVisible) {
        const InstanceGpu instance = instances[uint(key & 0xffffffffUL)];
        const vec4 sphere = instance.positionRadius;
        // The splat found this pixel's ray on the sphere; rounding may put this cast a hair
        // outside it, so it takes the rim there rather than miss.
        SphereHit hit;
        if (!castSphere(gl_FragCoord.xy, sphere, hit)) {
            hit.t = dot(sphere.xyz - eye, hit.direction);
            hit.missSq = sphere.w * sphere.w;
        }
        if (!onGround || hit.t < groundT) {
            const vec3 point = eye + hit.t * hit.direction;
            vec3 colour = shade(instance.color.rgb, (point - sphere.xyz) / sphere.w, point, 48.0, 0.35);
            // The rim's coverage, as impostor.frag's alpha-to-coverage takes it: the ray's
            // distance inside the outline in pixels, plus half a pixel. A rim pixel mixes in
            // what lies behind the joint (the ground or the sky; another joint there is taken
            // for the ground, a faint halo where two joints cross), so silhouettes are smooth
            // without multisampling. Only rim pixels shade the ground (a CPU rasteriser skips
            // a branch no pixel of a block takes).
            const float rim = (sphere.w - sqrt(hit.missSq)) * scene.viewport.z / max(hit.t, 1e-3);
            const float coverage = clamp(rim + 0.5, 0.0, 1.0);
            if (coverage < 1.0) colour = mix(onGround ? groundColor(groundPoint, footprint) : scene.fogColor.rgb, colour, coverage);
            outColor = vec4(colour, 1.0);
            return;
        }
    }
    if (!onGround) discard;
    outColor = vec4(groundColor(groundPoint, footprint), 1.0);
}
