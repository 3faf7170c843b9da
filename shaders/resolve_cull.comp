#version 450
// The fast path's compute pass: one invocation per character. A character whose bounding
// sphere is outside the view frustum writes nothing; a visible one reserves room for its
// joints with one atomic add on the indirect draw's vertex count and writes them there, so the
// draw touches only what can be seen. Joints of one character stay together and in order.
// Distant characters keep only their major joints (level of detail).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES  // writes instances, the draw arguments and the instance owners
#include "bindings.glsl"
#include "culling.glsl"
#include "joint_sprites.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint m = gl_GlobalInvocationID.x;
    if (m >= push.characterCount) return;
    const CharacterGpu character = characters[m];
    const ClipGpu clip = clips[character.clip];
    const vec3 centre = characterCentre(character);
    if (!insideFrustum(centre, push.cullRadius * character.scale)) return;
    // Level of detail: a character drawn only a few dozen pixels tall keeps its major joints;
    // the small ones would overlap them within a pixel or two anyway.
    const bool coarse = pixelsTall(character, centre) < push.lodPixels;
    writeJointSprites(m, character, clip, coarse, true, 1.0);
}
