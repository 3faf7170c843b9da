// The visibility path's shading of one pixel, for its shading pass (visibility_resolve.frag and
// visibility_resolve_bodies.frag, drawn over the squares of shading_tiles.glsl that a body may
// touch; with THRONG_RESOLVE_GROUND_ONLY, the _ground forms, over those that only see the
// ground (with THRONG_RESOLVE_NO_SHADOWS too, _bodies_ground_unshadowed, over those no contact
// shadow touches either: it reads none; with THRONG_RESOLVE_OPAQUE, _ground_opaque, over those
// of them whose every pixel sees the ground: it discards none, as the _opaque forms of the
// others); with THRONG_RESOLVE_JOINTS_ONLY,
// visibility_resolve_bodies_joints.frag, over those only joint spheres touch, which reads no
// bone): each pixel's ray meets the
// nearest of the body the splat kept there (shaded as impostor.frag and bone.frag shade
// joints and bones) and the ground (shaded as ground.frag shades it, so the path draws no
// ground pass of its own); where it meets neither, the sky's clear colour stays. One pass
// instead of two: on a CPU rasteriser a pass over the frame costs as much as thousands of joints.
// It draws with one sample (render::samplesFor): rims are smoothed here, the ground is
// filtered by its footprint.
//
// lavapipe runs both sides of every branch for every pixel (its shaders keep an execution mask
// rather than jump), so this pass does everything once, for every pixel: no second ray cast
// (the splat's distance gives the hit point), one capsule normal for joints and bones alike (a
// joint is a capsule whose ends coincide), one body shading and one ground shading (darkened by
// the splatted contact shadows in the bodies' form).
#ifndef THRONG_VISIBILITY_RESOLVE_GLSL
#define THRONG_VISIBILITY_RESOLVE_GLSL

#include "bindings.glsl"
// The scene as visibility_tiles.vert hands it on, flat, read in place of the uniform buffer.
layout(location = 1) flat in SceneData tileScene;
#define scene tileScene
#include "bone_cast.glsl"
#include "ground_shading.glsl"
#include "lighting.glsl"
#include "sphere_cast.glsl"
#include "visibility.glsl"

// The body the splat kept at a pixel, as a capsule (bone_cast.glsl's; a joint's ends coincide).
struct Body {
    vec4 start, end, flatten;
    vec3 albedo;
    float shininess, specular;
};

layout(set = 0, binding = THRONG_BINDING_INSTANCE_TEXELS) uniform samplerBuffer instanceTexels;
layout(set = 0, binding = THRONG_BINDING_BONE_INSTANCE_TEXELS) uniform samplerBuffer boneInstanceTexels;

Body keptBody(uint index) {
#if defined(THRONG_RESOLVE_BODIES) && !defined(THRONG_RESOLVE_JOINTS_ONLY)
    if ((index & kBoneKey) != 0u) {
        const int at = 4 * int(index & ~kBoneKey);
        return Body(texelFetch(boneInstanceTexels, at), texelFetch(boneInstanceTexels, at + 1), texelFetch(boneInstanceTexels, at + 2),
                    texelFetch(boneInstanceTexels, at + 3).rgb, 16.0, 0.12);  // bone.frag's
    }
#endif
    const int at = 3 * int(index);
    const vec4 positionRadius = texelFetch(instanceTexels, at);
    return Body(positionRadius, positionRadius, vec4(0.0, 0.0, 0.0, 1.0), texelFetch(instanceTexels, at + 2).rgb, 48.0, 0.35);  // impostor.frag's
}

// What the shading reads of a pixel from the splats' buffers: the body kept there and the
// contact shadows' sum. Read first, before the ray's and the ground's arithmetic: lavapipe lays
// a shader's instructions out in the order they are written, and a pixel's shading is too long
// for the CPU to reach ahead to the next pixels' reads, so a read made where it is used waits
// out its cache miss, while one made first overlaps it with that arithmetic (shading about 0.3-0.6 ms
// less at 2000 characters, the same bytes).
struct PixelReads {
    KeptKey key;  // none in the squares no body touches (not read there)
    float shadow;  // the contact shadows' sum in log2 of what they let through (visibility.glsl); 0 in the forms that read none
};

PixelReads readPixel(uvec2 pixel) {
#ifdef THRONG_RESOLVE_GROUND_ONLY
    const KeptKey key = KeptKey(false, 0.0, 0u);  // a square no body touches (shading_tiles.glsl)
#else
    const KeptKey key = keptKeyAt(pixelSlot(pixel, uint(scene.viewport.x)), scene.visibilityEpoch);
#endif
#if defined(THRONG_RESOLVE_BODIES) && !defined(THRONG_RESOLVE_NO_SHADOWS)
    return PixelReads(key, shadowSumAt(pixel, scene.viewport.xy));
#else
    return PixelReads(key, 0.0);
#endif
}

// The pixel's colour (linear); false where neither a body nor the ground is (the sky's clear
// colour stays). No depth: the skinned bodies drawn after this pass test against the
// visibility buffer and the ground plane themselves (skin_shading.glsl), so no square needs
// its pixels merged with a depth buffer's.
bool shadeVisibilityPixel(PixelReads reads, vec3 direction, GroundHit ground, vec2 footprint, out vec3 colour) {
    const vec3 eye = scene.cameraPosition.xyz;
    // A body in front of the ground (or where there is none).
    const KeptKey key = reads.key;
    const float t = key.distance;
    const bool body = key.present && (!ground.onGround || t < ground.t);
    const vec3 point = eye + t * direction;
    vec3 front = vec3(0.0);
    float coverage = 0.0;
    // The way to the eye and the highlight's halfway vector are the ray's, whichever surface it
    // meets: worked out once for the body and the ground instead of from each hit point (on
    // lavapipe that took about 0.4 ms off the 2000-character frame's shading, the same bytes).
    // The ray is a unit one where a body may show; the ground squares interpolate one of any length.
#ifdef THRONG_RESOLVE_GROUND_ONLY
    const float rayLength = length(direction);
    const View view = viewAlong(-direction / rayLength);
#else
    const float rayLength = 1.0;
    const View view = viewAlong(-direction);
#endif
    if (body) {
        const Body kept = keptBody(key.instance);
#if defined(THRONG_RESOLVE_BODIES) && !defined(THRONG_RESOLVE_JOINTS_ONLY)
        // The normal in the round capsule's space (the flattened one stretched back about its
        // middle), mapped forward as castBone's are.
        const vec3 middle = 0.5 * (kept.start.xyz + kept.end.xyz);
        float radius;
        const vec3 roundNormal = boneNormalAt(middle + unflatten(point - middle, kept.flatten), kept.start, kept.end, radius);
        const vec3 normal = unflatten(roundNormal, kept.flatten);
        const vec3 roundDirection = normalize(unflatten(direction, kept.flatten));
#else
        // Joints only: the sphere's own normal, none of the capsule's arithmetic.
        const float radius = kept.start.w;
        const vec3 roundNormal = normalize(point - kept.start.xyz), normal = roundNormal, roundDirection = direction;
#endif
        // A rim pixel mixes in what lies behind the body (the ground or the sky; another body
        // there is taken for the ground, a faint halo where two cross), so silhouettes are
        // smooth without multisampling. Its coverage, as the sprites' alpha-to-coverage takes
        // it: how far the ray passes inside the outline, in pixels, plus half a pixel; the ray
        // passes the touching sphere's centre at radius |n x d|.
        const float inside = radius * (1.0 - length(cross(roundNormal, roundDirection)));
        coverage = clamp(inside * scene.viewport.z / max(t, 1e-3) + 0.5, 0.0, 1.0);
#if defined(THRONG_RESOLVE_BODIES) && !defined(THRONG_RESOLVE_JOINTS_ONLY)
        front = shadeSeen(kept.albedo, normalize(normal), view, t, kept.shininess, kept.specular);  // unflattened: not a unit normal
#else
        front = shadeSeen(kept.albedo, normal, view, t, kept.shininess, kept.specular);  // the sphere's, unit already
#endif
    }
    // The ground last: on a CPU its colour would otherwise be held through all of the above
    // (every pixel runs both, and a SIMD register file is small).
    vec3 behind = ground.onGround ? groundColorSeen(ground.point, footprint, view, ground.t * rayLength) : scene.fogColor.rgb;
#if defined(THRONG_RESOLVE_BODIES) && !defined(THRONG_RESOLVE_NO_SHADOWS)
    // The contact shadows on the ground (splat_shadows.comp): what they let through together.
    if (ground.onGround) behind *= exp2(-reads.shadow);
#endif
    colour = mix(behind, front, coverage);
    return body || ground.onGround;
}

layout(location = 0) noperspective in vec3 groundRay;  // visibility_tiles.vert's
layout(location = 0) out vec4 outColor;

void main() {
    const PixelReads reads = readPixel(uvec2(gl_FragCoord.xy));
    // The ground along this pixel's ray, for every pixel, so that its footprint's derivatives
    // are taken in uniform control flow. A body's distance is along the unit ray the splat
    // cast, so the squares with bodies cast that one again (the interpolated ray is the same
    // up to rounding, but on a sphere a pixel wide that rounding moves its rim's shading); the
    // ground alone takes the interpolated ray as it is.
#ifdef THRONG_RESOLVE_GROUND_ONLY
    const vec3 direction = groundRay;
#else
    const vec3 direction = pixelRay(gl_FragCoord.xy);
#endif
    const GroundHit ground = groundAlong(direction);
    const vec2 footprint = fwidth(ground.point.xz / scene.groundParams.y);
    vec3 colour;
#ifdef THRONG_RESOLVE_OPAQUE
    // An opaque square's every pixel sees the ground (classify_tiles.comp): none is discarded.
    shadeVisibilityPixel(reads, direction, ground, footprint, colour);
#else
    if (!shadeVisibilityPixel(reads, direction, ground, footprint, colour)) discard;
#endif
    outColor = vec4(colour, 1.0);
}

#endif
