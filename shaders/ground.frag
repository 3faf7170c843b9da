#version 450
// A two-tone checkerboard, filtered by its screen-space footprint so it doesn't alias.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 outColor;

void main() {
    const vec2 cell = worldPosition.xz / scene.groundParams.y;
    const vec2 width = max(fwidth(cell), vec2(1e-4));
    // Integral of a square wave over the pixel footprint: the box-filtered checker.
    const vec2 i = (2.0 * (abs(fract((cell - 0.5 * width) * 0.5) - 0.5) - abs(fract((cell + 0.5 * width) * 0.5) - 0.5))) / width;
    const float checker = 0.5 - 0.5 * i.x * i.y;
    const vec3 albedo = mix(vec3(0.34, 0.35, 0.33), vec3(0.28, 0.29, 0.28), checker);
    outColor = vec4(shade(albedo, vec3(0.0, 1.0, 0.0), worldPosition, 16.0, 0.05), 1.0);
}
