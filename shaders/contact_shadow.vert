#version 450
// Contact shadows: a soft dark ellipse on the ground under every character (a 4-vertex strip
// per instance), so bodies stand on the floor instead of floating above it. About a body's
// width across and a stride long, turned with the character; just above the ground, drawn
// over it before the bodies, writing no depth.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 0) out vec2 across;  // -1..1 over the ellipse
layout(location = 1) out float fog;    // of the ground under it, 0..1

void main() {
    const CharacterGpu character = characters[gl_InstanceIndex];
    const vec2 corner = vec2(float(gl_VertexIndex & 1), float(gl_VertexIndex >> 1)) * 2.0 - 1.0;
    across = corner;
    const float size = push.cullHeight * character.scale;  // about half the character's height
    const float yaw = character.groundFrame.w;
    const vec3 forward = vec3(sin(yaw), 0.0, cos(yaw)), sideways = vec3(cos(yaw), 0.0, -sin(yaw));
    const vec3 world = vec3(character.groundFrame.x, 0.004, character.groundFrame.z) + sideways * (corner.x * 0.36 * size) +
                       forward * (corner.y * 0.5 * size);
    fog = smoothstep(scene.groundParams.z, scene.groundParams.w, distance(world, scene.cameraPosition.xyz));
    gl_Position = scene.viewProjection * vec4(world, 1.0);
}
