#version 450
// Instanced joint spheres: each instance is one joint, placed by the compute pass.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 0) in vec3 unitPosition;  // unit-sphere vertex, which is also its normal

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 albedo;

void main() {
    const InstanceGpu instance = instances[gl_InstanceIndex];
    worldPosition = instance.positionRadius.xyz + unitPosition * instance.positionRadius.w;
    worldNormal = unitPosition;
    albedo = instance.color.rgb;
    // A zero radius collapses the sphere to a point: no fragments, nothing drawn.
    gl_Position = scene.viewProjection * vec4(worldPosition, 1.0);
}
