#version 450
// The visibility path's shading (visibility_resolve.glsl) for bone bodies, for the squares
// only joint spheres touch (shading_tiles.glsl): the whole shading, the joints' exactly as
// there, but with no bone read (lavapipe would load both kinds for every pixel).
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_BODIES
#define THRONG_RESOLVE_JOINTS_ONLY
#include "visibility_resolve.glsl"
