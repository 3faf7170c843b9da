#version 450
// The visibility path's shading (visibility_resolve.glsl) for bone bodies, for the squares no
// body and no contact shadow touches (shading_tiles.glsl): the ground alone, and no shadow
// read.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_BODIES
#define THRONG_RESOLVE_GROUND_ONLY
#define THRONG_RESOLVE_NO_SHADOWS
#include "visibility_resolve.glsl"
