#version 450
// The visibility path's splat: one invocation per visible joint sphere (as the fast path's
// culling pass compacted them). For each pixel its screen bound covers, the sphere is ray-cast
// through the pixel's centre, as impostor.frag does, and the hit's distance and the instance are
// kept in the visibility buffer by a 64-bit atomicMin: no rasteriser set-up per sphere, which
// on a CPU rasteriser costs more than the few pixels a distant joint covers.
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES
#include "bindings.glsl"
#include "lod_fade.glsl"
#include "shading_tiles.glsl"
#include "visibility.glsl"

layout(local_size_x = kSplatGroupSize) in;

void splatJoint(uint id) {
    const InstanceGpu instance = instances[id];
    const vec4 sphere = instance.positionRadius;
    const vec4 clip = scene.viewProjection * vec4(sphere.xyz, 1.0);
    if (sphere.w <= 0.0 || clip.w <= sphere.w * 1.5) return;  // nothing, or too close to bound safely
    const vec2 centre = (clip.xy / clip.w * 0.5 + 0.5) * scene.viewport.xy;
    // The sphere's screen radius is at most r f / (w - r) on the axis; off the axis its
    // outline stretches away from the centre by up to 1 / cos^2 of the angle off the axis
    // (the ratio of distance to depth, squared). No larger than the fast path's largest point
    // (a huge sphere is clipped alike). Only pixels whose centres fall inside are cast.
    const float offAxis = length(sphere.xyz - scene.cameraPosition.xyz) / clip.w;
    const float radius = min(sphere.w * scene.viewport.z / (clip.w - sphere.w) * offAxis * offAxis + 0.25, 0.5 * scene.viewport.w - 1.0);
    const ivec2 size = ivec2(scene.viewport.xy);
    const ivec2 lo = max(ivec2(ceil(centre - radius - 0.5)), ivec2(0));
    const ivec2 hi = min(ivec2(floor(centre + radius - 0.5)), size - 1);
    markBodyTiles(lo, hi, kJointMark);  // the shading shades bodies only in marked squares
    const bool fades = instance.color.a < 1.0;  // most joints keep every pixel (lod_fade.glsl)
    // castSphere's ray, stepped across the pixels: a pixel's near-plane point is affine in its
    // coordinates before the perspective divide, so each step adds a column of the inverse.
    const vec3 eye = scene.cameraPosition.xyz;
    const vec4 stepX = scene.inverseViewProjection[0] * (2.0 / scene.viewport.x);
    const vec4 stepY = scene.inverseViewProjection[1] * (2.0 / scene.viewport.y);
    const vec2 firstNdc = (vec2(lo) + 0.5) / scene.viewport.xy * 2.0 - 1.0;
    const vec4 first = scene.inverseViewProjection * vec4(firstNdc, 0.0, 1.0);
    const vec3 fromCentre = eye - sphere.xyz;
    const float centreSq = dot(fromCentre, fromCentre), radiusSq = sphere.w * sphere.w;
    for (int y = lo.y; y <= hi.y; ++y) {
        const vec4 row = first + stepY * float(y - lo.y);
        for (int x = lo.x; x <= hi.x; ++x) {
            const vec4 near = row + stepX * float(x - lo.x);  // not accumulated: no drift across a wide sphere
            const vec3 direction = normalize(near.xyz / near.w - eye);
            const float b = dot(fromCentre, direction);
            const float missSq = centreSq - b * b;
            if (missSq > radiusSq) continue;
            const vec2 pixel = vec2(x, y) + 0.5;
            if (fades && !keptByFade(instance.color.a, pixel)) continue;
            atomicMin(visibility[uint(y) * uint(size.x) + uint(x)], visibilityKey(-b - sqrt(radiusSq - missSq), id));
        }
    }
}

void main() {
    // Dispatched indirectly with the workgroups the culling pass asked for (draw.jointSplatGroups),
    // looping only past the most a dispatch may have.
    for (uint id = gl_GlobalInvocationID.x; id < draw.vertexCount; id += gl_NumWorkGroups.x * kSplatGroupSize) splatJoint(id);
}
