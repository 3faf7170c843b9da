#version 450
// Bone bodies: each bone is one quad (a 4-vertex strip per instance) just big enough to cover
// its tapered capsule on screen; bone.frag ray-casts the exact shape.
//
// The quad lies on the plane facing the eye (normal n, from the eye to the bone's middle) at
// the capsule's nearest possible distance along n, D - R, where R bounds the capsule about its
// middle. Every point of the capsule is at least that far along n, so it projects onto the
// plane no further from the quad's centre than its offset across n (scaled by (D - R) / t <= 1):
// the rectangle around the bone's axis projected across n, widened by the largest radius,
// covers it. And on every pixel's ray the quad comes first, so bone.frag's depth only grows
// (depth_greater keeps early depth rejection).
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 0) flat out vec4 boneStart;   // world xyz, radius
layout(location = 1) flat out vec4 boneEnd;     // world xyz, radius
layout(location = 2) flat out vec4 boneFlatten; // unit axis, thickness over width
layout(location = 3) flat out vec4 albedo;  // rgb, and the level-of-detail fade (lod_fade.glsl)

void main() {
    const BoneInstanceGpu bone = boneInstances[gl_InstanceIndex];
    boneStart = bone.start;
    boneEnd = bone.end;
    boneFlatten = bone.flatten;
    albedo = bone.color;
    const vec3 middle = 0.5 * (bone.start.xyz + bone.end.xyz);
    const vec3 axis = bone.end.xyz - bone.start.xyz;
    const float widest = max(bone.start.w, bone.end.w);
    const vec3 eye = scene.cameraPosition.xyz;
    const float distanceToMiddle = length(middle - eye);
    const float nearest = distanceToMiddle - (0.5 * length(axis) + widest);
    if (widest <= 0.0 || nearest <= 1e-3) {  // nothing to draw, or the eye inside its bound
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    const vec3 n = (middle - eye) / distanceToMiddle;
    const vec3 projected = axis - dot(axis, n) * n;
    const float along = length(projected);
    const vec3 e1 = along > 1e-6 ? projected / along : normalize(cross(n, abs(n.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    const vec3 e2 = cross(n, e1);
    // A pixel more on every side: bone.frag keeps only pixels whose centre's ray hits the
    // capsule (the rim's coverage is taken inside the silhouette), and a pixel whose centre is
    // inside the bare quad has all its samples inside this one (they lie within 0.71 px of it).
    // More only adds fragments that discard: most of a small bone's quad.
    const float pad = nearest / scene.viewport.z;
    const vec2 corner = vec2(float(gl_VertexIndex & 1), float(gl_VertexIndex >> 1)) * 2.0 - 1.0;
    const vec3 world = eye + n * nearest + corner.x * (0.5 * along + widest + pad) * e1 + corner.y * (widest + pad) * e2;
    gl_Position = scene.viewProjection * vec4(world, 1.0);
}
