#version 450
// Skinned bodies over the raster paths' depth (skin_shading.glsl).
#extension GL_GOOGLE_include_directive : require
#include "skin_shading.glsl"
