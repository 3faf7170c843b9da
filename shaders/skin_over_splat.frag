#version 450
// Skinned bodies on the visibility path, tested against its splat and the ground plane
// (skin_shading.glsl), as its shading writes no depth.
#extension GL_GOOGLE_include_directive : require
#define THRONG_SKIN_OVER_SPLAT
#include "skin_shading.glsl"
