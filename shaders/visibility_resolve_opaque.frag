#version 450
// visibility_resolve.frag (joint spheres alone) for the squares that stand wholly on the ground
// (shading_tiles.glsl): no pixel discarded, drawn with no depth test, so that lavapipe writes
// its colours straight out.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_OPAQUE
#include "visibility_resolve.glsl"
