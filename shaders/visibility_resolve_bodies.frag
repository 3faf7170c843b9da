#version 450
// The visibility path's shading (visibility_resolve.glsl) of the squares a body may touch, for bone bodies: it
// shades bones as well as joints (no depth: the skinned bodies drawn after it test themselves
// against the splat and the ground plane, skin_shading.glsl).
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_BODIES
#include "visibility_resolve.glsl"
