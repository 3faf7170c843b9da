#version 450
// The visibility path's shading (visibility_resolve.glsl) of the squares a body may touch, for bone bodies: it
// shades bones as well as joints, and writes each pixel's depth for the skinned bodies and
// contact shadows drawn after it.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_BODIES
#include "visibility_resolve.glsl"
