#version 450
// The visibility path's splat for bone bodies: one invocation per visible bone (as
// resolve_bones.comp wrote them). Every pixel whose centre falls inside the screen bound of its
// two end spheres (the capsule is their convex hull) is ray-cast against the capsule, as
// bone.frag casts it, and the hit's distance and the bone (tagged kBoneKey) are kept in the
// visibility buffer by a 64-bit atomicMin, beside the joint spheres of splat_spheres.comp.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#define THRONG_SPLAT_ORDER
#define THRONG_COMPUTE_WRITES
#include "bindings.glsl"
#include "bone_cast.glsl"
#include "lod_fade.glsl"
#include "shading_tiles.glsl"
#include "splat_frame.glsl"
#include "visibility.glsl"

layout(local_size_x = kSplatGroupSize) in;

void splatBone(uint id, SplatFrame frame) {
    const BoneInstanceGpu bone = boneInstances[id];
    vec2 centreA, centreB;
    float radiusA, radiusB;
    if (max(bone.start.w, bone.end.w) <= 0.0 || !screenCircle(frame, bone.start, centreA, radiusA) ||
        !screenCircle(frame, bone.end, centreB, radiusB))
        return;
    const ivec2 size = ivec2(frame.viewport.xy);
    // No larger than the joint sprites' largest point either side (a bone filling the screen
    // is the raster paths' work; the auto body skins characters that near).
    const vec2 reach = vec2(0.5 * frame.viewport.w);
    const vec2 middle = 0.5 * (centreA + centreB);
    const vec2 low = max(min(centreA - radiusA, centreB - radiusB), middle - reach);
    const vec2 high = min(max(centreA + radiusA, centreB + radiusB), middle + reach);
    const ivec2 lo = max(ivec2(ceil(low - 0.5)), ivec2(0));
    const ivec2 hi = min(ivec2(floor(high - 0.5)), size - 1);
    markBodyTiles(lo, hi, kBoneMark, frame.tilesAcross);  // the shading shades bodies only in marked squares
    const bool fades = bone.color.a < 1.0;
    const vec3 eye = frame.eye;
    const PixelRays rays = pixelRaysFrom(frame, lo);
    for (int y = lo.y; y <= hi.y; ++y) {
        const vec4 row = rays.first + rays.stepY * float(y - lo.y);
        for (int x = lo.x; x <= hi.x; ++x) {
            if (fades && !keptByFade(bone.color.a, vec2(x, y) + 0.5)) continue;
            const vec4 near = row + rays.stepX * float(x - lo.x);
            const vec3 direction = normalize(near.xyz / near.w);  // the near point's offset from the eye
            const BoneHit hit = castBone(eye, direction, bone.start, bone.end, bone.flatten);
            if (hit.t == kMiss) continue;
            atomicMin(visibility[pixelSlot(uvec2(x, y), uint(size.x))], visibilityKey(hit.t, id | kBoneKey, frame.epoch));
        }
    }
}

void main() {
    // Dispatched indirectly with the workgroups the bones' writer asked for
    // (draw.boneSplatGroups), looping only past the most a dispatch may have. Every character
    // of a clip writes all its bones (the first clip's count stands for all).
    const SplatFrame frame = splatFrame();
    const uint count = draw.boneInstanceCount, perCharacter = clips[0].boneCount;
    for (uint id = gl_GlobalInvocationID.x; id < count; id += gl_NumWorkGroups.x * kSplatGroupSize)
        splatBone(lockstepOrder(id, count, perCharacter), frame);
}
