#version 450
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec3 albedo;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(shade(albedo, worldNormal, worldPosition, 48.0, 0.35), 1.0);
}
