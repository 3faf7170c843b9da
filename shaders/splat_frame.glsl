// What the visibility path's splats (splat_spheres.comp, splat_bones.comp, and the contact
// shadows' in shadow_splat.glsl) read of the scene, read once at an invocation's start and
// handed to each body it casts: lavapipe loads a uniform's value lane by lane, behind a bounds
// check, and with the reads inside each cast the joint spheres' splat took about 1.5 ms more at
// 10,000 characters.
#ifndef THRONG_SPLAT_FRAME_GLSL
#define THRONG_SPLAT_FRAME_GLSL

#include "bindings.glsl"
#include "shading_tiles.glsl"

struct SplatFrame {
    mat4 viewProjection, inverseViewProjectionAtEye;
    vec4 viewport;  // scene.viewport: width, height, focal length and the largest point, in pixels
    vec3 eye;
    uint tilesAcross;  // shading squares across the frame (shading_tiles.glsl)
    vec2 fog;          // scene.groundParams.zw: where the fog starts and where it is whole, metres from the eye
    uint epoch;        // scene.visibilityEpoch: this frame's, in its visibility keys (visibility.glsl)
};

SplatFrame splatFrame() {
    return SplatFrame(scene.viewProjection, scene.inverseViewProjectionAtEye, scene.viewport, scene.cameraPosition.xyz, tileGrid().x,
                      scene.groundParams.zw, scene.visibilityEpoch);
}

// A sphere's (world centre, radius) screen circle: centre and a radius that bounds it, in
// pixels. False when the sphere is too close to the eye to bound safely. The sphere's screen
// radius is at most r f / (w - r) on the axis; off the axis its outline stretches away from the
// centre by up to 1 / cos^2 of the angle off the axis (the ratio of distance to depth, squared).
bool screenCircle(SplatFrame frame, vec4 sphere, out vec2 centre, out float radius) {
    const vec4 clip = frame.viewProjection * vec4(sphere.xyz, 1.0);
    if (clip.w <= sphere.w * 1.5) return false;
    centre = (clip.xy / clip.w * 0.5 + 0.5) * frame.viewport.xy;
    const float offAxis = length(sphere.xyz - frame.eye) / clip.w;
    radius = sphere.w * frame.viewport.z / (clip.w - sphere.w) * offAxis * offAxis + 0.25;
    return true;
}

// The ray through a bound's pixels, stepped: a pixel's near-plane point is affine in its
// coordinates before the perspective divide, so each step adds a column of the inverse.
struct PixelRays {
    vec4 first, stepX, stepY;  // the near-plane point's offset from the eye (homogeneous) at the bound's first sample, and per step across and down
};

// Rays through samples `spacing` pixels apart, the first at pixel coordinates `first`.
PixelRays raysFrom(SplatFrame frame, vec2 first, float spacing) {
    const vec2 firstNdc = first / frame.viewport.xy * 2.0 - 1.0;
    return PixelRays(frame.inverseViewProjectionAtEye * vec4(firstNdc, 0.0, 1.0),
                     frame.inverseViewProjectionAtEye[0] * (2.0 * spacing / frame.viewport.x),
                     frame.inverseViewProjectionAtEye[1] * (2.0 * spacing / frame.viewport.y));
}

// Through the centre of each pixel from the corner pixel `lo` on.
PixelRays pixelRaysFrom(SplatFrame frame, ivec2 lo) { return raysFrom(frame, vec2(lo) + 0.5, 1.0); }

#endif
