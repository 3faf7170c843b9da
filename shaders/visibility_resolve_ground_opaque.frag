#version 450
// The visibility path's shading (visibility_resolve.glsl) for the squares whose every pixel
// sees the ground and that no body or contact shadow touches (shading_tiles.glsl): the ground
// alone, every pixel written, so that lavapipe writes its colours straight out instead of
// merging them with what was there.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_GROUND_ONLY
#define THRONG_RESOLVE_OPAQUE
#include "visibility_resolve.glsl"
