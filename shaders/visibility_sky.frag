#version 450
// The visibility path's sky (shading_tiles.glsl): over the slot's last frame, the squares that
// held a body and may show sky are first painted the colour the frame is cleared to, which is
// the fog's (scene_look.cpp's skyClearColor). Every pixel written: the shading after it leaves
// the sky's pixels as they are.
#extension GL_GOOGLE_include_directive : require
#include "bindings.glsl"

layout(location = 1) flat in SceneData tileScene;  // visibility_tiles.vert's
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(tileScene.fogColor.rgb, 1.0); }
