// A joint's sphere ray-cast through a pixel: shared by the point sprites (impostor.frag) and
// the visibility path's splat and resolve, so both draw the same exact spheres.
#ifndef THRONG_SPHERE_CAST_GLSL
#define THRONG_SPHERE_CAST_GLSL

#include "bindings.glsl"

struct SphereHit {
    vec3 direction;  // unit, from the eye through the pixel
    float t;         // distance along it to the sphere's front
    float missSq;    // squared distance of the ray from the centre
};

// The ray from the eye to the near plane's point at `ndc`, not normalised.
vec3 rayToNearPlane(vec2 ndc) {
    const vec4 nearPoint = scene.inverseViewProjectionAtEye * vec4(ndc, 0.0, 1.0);
    return nearPoint.xyz / nearPoint.w;
}

// The unit direction from the eye through the pixel centre `pixel` (framebuffer coordinates,
// as gl_FragCoord.xy).
vec3 pixelRay(vec2 pixel) { return normalize(rayToNearPlane(pixel / scene.viewport.xy * 2.0 - 1.0)); }

// The ray from the eye along unit `direction` against sphere (world centre, radius): false
// when it misses.
bool castSphereAlong(vec3 direction, vec4 sphere, out SphereHit hit) {
    hit.direction = direction;
    const vec3 fromCentre = scene.cameraPosition.xyz - sphere.xyz;
    const float b = dot(fromCentre, hit.direction);
    hit.missSq = dot(fromCentre, fromCentre) - b * b;
    const float radiusSq = sphere.w * sphere.w;
    if (hit.missSq > radiusSq) return false;
    hit.t = -b - sqrt(radiusSq - hit.missSq);
    return true;
}

// The ray through the pixel centre `pixel` against sphere: false when it misses.
bool castSphere(vec2 pixel, vec4 sphere, out SphereHit hit) { return castSphereAlong(pixelRay(pixel), sphere, hit); }

#endif
