#version 450
// Skinned bodies: smooth-shaded like the other bodies (lighting.glsl), slightly soft cloth.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"
#include "lighting.glsl"
#include "lod_fade.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec3 albedo;
layout(location = 3) flat in float fade;
layout(location = 0) out vec4 outColor;

void main() {
    if (!keptByFade(fade, gl_FragCoord.xy)) discard;
    outColor = vec4(shade(albedo, normalize(worldNormal), worldPosition, 16.0, 0.12), 1.0);
}
