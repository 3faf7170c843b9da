// The visibility path's shading of one pixel, for its full-screen pass
// (visibility_resolve.frag and visibility_resolve_bodies.frag) or its compute shading
// (visibility_shade.comp): each pixel's ray meets the nearest of the joint
// the splat kept there (shaded as impostor.frag shades it) and the ground (shaded as
// ground.frag shades it, so the path draws no ground pass of its own); where it meets
// neither, the sky's clear colour stays. One pass instead of two: on a CPU rasteriser a
// full-screen pass costs as much as thousands of joints. It draws with one sample
// (render::samplesFor): rims are smoothed here, the ground is filtered by its footprint.
#ifndef THRONG_VISIBILITY_RESOLVE_GLSL
#define THRONG_VISIBILITY_RESOLVE_GLSL

#include "bindings.glsl"
#include "bone_cast.glsl"
#include "ground_shading.glsl"
#include "lighting.glsl"
#include "sphere_cast.glsl"
#include "visibility.glsl"

// The depth buffer's value at a world point, for what is drawn after this pass (bodies near
// enough to be skinned, contact shadows) to be tested against. Only the bodies' form
// (visibility_resolve_bodies.frag, THRONG_RESOLVE_BODIES) shades bones and writes depth: the
// joint-sphere form draws nothing after it, and on lavapipe the depth write and the bones'
// code cost it a third of its frame.
float depthAt(vec3 point) {
    const vec4 clip = scene.viewProjection * vec4(point, 1.0);
    return clip.z / clip.w;
}

// A body's surface at this pixel: its distance along the ray, its colour and how much of the
// pixel it covers.
struct Surface {
    float t;
    vec3 colour;
    float coverage;
};

// The joint sphere the splat kept. The splat found this pixel's ray on it; rounding may put
// this cast a hair outside, so it takes the rim there rather than miss.
Surface jointSurface(uint index, vec3 direction) {
    const InstanceGpu instance = instances[index];
    const vec4 sphere = instance.positionRadius;
    SphereHit hit;
    if (!castSphereAlong(direction, sphere, hit)) {
        hit.t = dot(sphere.xyz - scene.cameraPosition.xyz, hit.direction);
        hit.missSq = sphere.w * sphere.w;
    }
    const vec3 point = scene.cameraPosition.xyz + hit.t * hit.direction;
    // The rim's coverage, as impostor.frag's alpha-to-coverage takes it: the ray's distance
    // inside the outline in pixels, plus half a pixel.
    const float rim = (sphere.w - sqrt(hit.missSq)) * scene.viewport.z / max(hit.t, 1e-3);
    return Surface(hit.t, shade(instance.color.rgb, (point - sphere.xyz) / sphere.w, point, 48.0, 0.35), clamp(rim + 0.5, 0.0, 1.0));
}

#ifdef THRONG_RESOLVE_BODIES
// The bone the splat kept, shaded as bone.frag shades it.
Surface boneSurface(uint index, vec3 direction) {
    const BoneInstanceGpu bone = boneInstances[index];
    const vec3 eye = scene.cameraPosition.xyz;
    BoneHit hit = castBone(eye, direction, bone.start, bone.end, bone.flatten);
    if (hit.t == kMiss) {  // rounding, as for a joint: the nearest the axis comes
        hit.t = dot(0.5 * (bone.start.xyz + bone.end.xyz) - eye, direction);
        hit.normal = -direction;
        hit.inside = 0.0;
    }
    const vec3 point = eye + hit.t * direction;
    const float rim = hit.inside * scene.viewport.z / max(hit.t, 1e-3);
    return Surface(hit.t, shade(bone.color.rgb, unflatten(hit.normal, bone.flatten), point, 16.0, 0.12), clamp(rim + 0.5, 0.0, 1.0));
}
#endif

// Where this pixel's ray meets the ground plane (y = 0) within the ground's square; its
// footprint, in checker squares, is the caller's to give (fwidth in a fragment shader, the
// neighbouring pixels' rays in compute).
struct GroundHit {
    float t;       // along the ray; -1 when the ray never comes down to the plane
    vec3 point;
    bool onGround;
};

GroundHit groundAlong(vec3 direction) {
    const vec3 eye = scene.cameraPosition.xyz;
    GroundHit ground;
    ground.t = direction.y < 0.0 ? -eye.y / direction.y : -1.0;
    ground.point = eye + max(ground.t, 0.0) * direction;
    ground.onGround = ground.t > 0.0 && all(lessThanEqual(abs(ground.point.xz), vec2(scene.groundParams.x)));
    return ground;
}

// The pixel's colour (linear) and the depth buffer's value there; false where neither a body
// nor the ground is (the sky's clear colour stays).
bool shadeVisibilityPixel(uint pixelIndex, vec3 direction, GroundHit ground, vec2 footprint, out vec3 colour, out float depth) {
    const vec3 eye = scene.cameraPosition.xyz;
    const uint64_t key = visibility[pixelIndex];
    if (key != kNothingVisible) {
        const uint index = uint(key & 0xffffffffUL);
#ifdef THRONG_RESOLVE_BODIES
        const Surface body = (index & kBoneKey) != 0u ? boneSurface(index & ~kBoneKey, direction) : jointSurface(index, direction);
#else
        const Surface body = jointSurface(index, direction);
#endif
        if (!ground.onGround || body.t < ground.t) {
            // A rim pixel mixes in what lies behind the body (the ground or the sky; another
            // body there is taken for the ground, a faint halo where two cross), so
            // silhouettes are smooth without multisampling. Only rim pixels shade the ground
            // (a CPU rasteriser skips a branch no pixel of a block takes).
            colour = body.colour;
            if (body.coverage < 1.0)
                colour = mix(ground.onGround ? groundColor(ground.point, footprint) : scene.fogColor.rgb, colour, body.coverage);
            depth = depthAt(eye + body.t * direction);
            return true;
        }
    }
    colour = ground.onGround ? groundColor(ground.point, footprint) : scene.fogColor.rgb;
    depth = ground.onGround ? depthAt(ground.point) : 1.0;
    return ground.onGround;
}

#ifndef THRONG_SHADE_IN_COMPUTE
layout(location = 0) out vec4 outColor;

void main() {
    // The ground along this pixel's ray, for every pixel, so that its footprint's derivatives
    // are taken in uniform control flow.
    const vec3 direction = pixelRay(gl_FragCoord.xy);
    const GroundHit ground = groundAlong(direction);
    const vec2 footprint = fwidth(ground.point.xz / scene.groundParams.y);
    vec3 colour;
    float depth;
    if (!shadeVisibilityPixel(uint(gl_FragCoord.y) * uint(scene.viewport.x) + uint(gl_FragCoord.x), direction, ground, footprint, colour, depth))
        discard;
    outColor = vec4(colour, 1.0);
#ifdef THRONG_RESOLVE_BODIES
    gl_FragDepth = depth;
#endif
}
#endif

#endif
