// Frustum culling and on-screen size for the compute passes that cull whole characters
// (resolve_cull.comp for joint spheres, resolve_bones.comp for bone bodies), and screen bounds
// for the visibility path's splats.
#ifndef THRONG_CULLING_GLSL
#define THRONG_CULLING_GLSL

#include "bindings.glsl"

// Whether a sphere (world centre, radius) touches the view frustum.
bool insideFrustum(vec3 centre, float radius) {
    for (int p = 0; p < 6; ++p)
        if (dot(push.frustum[p].xyz, centre) + push.frustum[p].w < -radius) return false;
    return true;
}

// The character's bounding sphere centre (world), from its ground frame and scale.
vec3 characterCentre(CharacterGpu character) {
    return character.groundFrame.xyz + vec3(0.0, push.cullHeight * character.scale, 0.0);
}

// About how many pixels tall the character is drawn.
float pixelsTall(CharacterGpu character, vec3 centre) {
    return 2.0 * push.cullHeight * character.scale * scene.viewport.z / max(distance(centre, scene.cameraPosition.xyz), 1e-3);
}

// Whether a character's bounding sphere touches the view and, if so, about how many pixels
// tall it is drawn (0 when it doesn't): the planning pass's measure (resolve_bones.comp).
float tallInView(CharacterGpu character, out bool visible) {
    const vec3 centre = characterCentre(character);
    visible = insideFrustum(centre, push.cullRadius * character.scale);
    return visible ? pixelsTall(character, centre) : 0.0;
}

#endif
