#version 450
// The visibility path's shading (visibility_resolve.glsl) of the squares a body may touch, joint spheres alone:
// nothing is drawn after it, so it writes no depth.
#extension GL_GOOGLE_include_directive : require
#include "visibility_resolve.glsl"
