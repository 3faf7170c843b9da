#version 450
// The ground quad's pixels, shaded as ground_shading.glsl paves it.
#extension GL_GOOGLE_include_directive : require
#include "ground_shading.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(groundColor(worldPosition, fwidth(worldPosition.xz / scene.groundParams.y)), 1.0);
}
