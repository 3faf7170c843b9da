#version 450
// The contact shadow's falloff: darkest under the body, fading out to the ellipse's rim, and
// into the fog with the ground it lies on.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 0) in vec2 across;
layout(location = 1) in float fog;
layout(location = 0) out vec4 outColor;

void main() {
    const float r = length(across);
    if (r >= 1.0) discard;
    outColor = vec4(0.0, 0.0, 0.0, 0.6 * (1.0 - smoothstep(0.3, 1.0, r)) * (1.0 - fog));
}
