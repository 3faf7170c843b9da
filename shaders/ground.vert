#version 450
// A ground quad on y = 0, generated from the vertex index (no vertex buffer).
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 0) out vec3 worldPosition;

void main() {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, 1), vec2(1, -1), vec2(-1, -1), vec2(-1, 1), vec2(1, 1));
    const vec2 corner = corners[gl_VertexIndex] * scene.groundParams.x;
    worldPosition = vec3(corner.x, 0.0, corner.y);
    gl_Position = scene.viewProjection * vec4(worldPosition, 1.0);
}
