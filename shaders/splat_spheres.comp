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
#include "splat_frame.glsl"
#include "visibility.glsl"

layout(local_size_x = kSplatGroupSize) in;

void splatJoint(uint id, SplatFrame frame) {
    const InstanceGpu instance = instances[id];
    const vec4 sphere = instance.positionRadius;
    vec2 centre;
    float radius;
    if (sphere.w <= 0.0 || !screenCircle(frame, sphere, centre, radius)) return;  // nothing, or too close to bound safely
    // No larger than the fast path's largest point (a huge sphere is clipped alike). Only
    // pixels whose centres fall inside are cast.
    radius = min(radius, 0.5 * frame.viewport.w - 1.0);
    const ivec2 size = ivec2(frame.viewport.xy);
    const ivec2 lo = max(ivec2(ceil(centre - radius - 0.5)), ivec2(0));
    const ivec2 hi = min(ivec2(floor(centre + radius - 0.5)), size - 1);
    markBodyTiles(lo, hi, kJointMark, frame.tilesAcross);  // the shading shades bodies only in marked squares
    const bool fades = instance.color.a < 1.0;  // most joints keep every pixel (lod_fade.glsl)
    // castSphere's ray, stepped across the pixels.
    const PixelRays rays = pixelRaysFrom(frame, lo);
    const vec3 eye = frame.eye, fromCentre = eye - sphere.xyz;
    const float centreSq = dot(fromCentre, fromCentre), radiusSq = sphere.w * sphere.w;
    for (int y = lo.y; y <= hi.y; ++y) {
        const vec4 row = rays.first + rays.stepY * float(y - lo.y);
        for (int x = lo.x; x <= hi.x; ++x) {
            const vec4 near = row + rays.stepX * float(x - lo.x);  // not accumulated: no drift across a wide sphere
            const vec3 direction = normalize(near.xyz / near.w);  // the near point's offset from the eye
            const float b = dot(fromCentre, direction);
            const float missSq = centreSq - b * b;
            if (missSq > radiusSq) continue;
            const vec2 pixel = vec2(x, y) + 0.5;
            if (fades && !keptByFade(instance.color.a, pixel)) continue;
            atomicMin(visibility[pixelSlot(uvec2(x, y), uint(size.x))], visibilityKey(-b - sqrt(radiusSq - missSq), id, frame.epoch));
        }
    }
}

void main() {
    // Dispatched indirectly with the workgroups the culling pass asked for (draw.jointSplatGroups),
    // looping only past the most a dispatch may have.
    const SplatFrame frame = splatFrame();
    const uint count = draw.vertexCount;
    for (uint id = gl_GlobalInvocationID.x; id < count; id += gl_NumWorkGroups.x * kSplatGroupSize) splatJoint(id, frame);
}
