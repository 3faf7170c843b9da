#version 450
// The visibility path's shading (visibility_resolve.glsl) for bone bodies, for the squares no
// body touches (shading_tiles.glsl): the ground alone, under the contact shadows.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_BODIES
#define THRONG_RESOLVE_GROUND_ONLY
#include "visibility_resolve.glsl"
