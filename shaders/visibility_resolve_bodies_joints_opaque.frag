#version 450
// visibility_resolve_bodies_joints.frag for the squares that stand wholly on the ground
// (shading_tiles.glsl): no pixel discarded, so that lavapipe writes its colours straight out.
#extension GL_GOOGLE_include_directive : require
#define THRONG_RESOLVE_BODIES
#define THRONG_RESOLVE_JOINTS_ONLY
#define THRONG_RESOLVE_OPAQUE
#include "visibility_resolve.glsl"
