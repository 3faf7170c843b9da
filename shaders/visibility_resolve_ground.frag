#version 450
// The visibility path's shading (visibility_resolve.glsl), joint spheres alone, for the squares
// no body touches (shading_tiles.glsl): the ground alone.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_GROUND_ONLY
#include "visibility_resolve.glsl"
