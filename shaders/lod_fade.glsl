// Cross-fade between levels of detail (--body auto), so a character crossing a threshold
// dissolves from one body into the next instead of popping: in a band just above each
// threshold both levels are drawn, each keeping the pixels the other leaves out, by a 4x4
// ordered dither. A fade f >= 0 keeps the pixels whose dither value is below f (the level fading
// in as f rises to 1); f < 0 keeps those at or above -f (the level fading out). 1 keeps all.
#ifndef THRONG_LOD_FADE_GLSL
#define THRONG_LOD_FADE_GLSL

// The band above a threshold where two levels cross-fade, as a fraction of the threshold.
const float kFadeBand = 0.25;

// How far a character `tall` pixels tall is through the band above `threshold`: 0 at the
// threshold, 1 past the band.
float fadeThrough(float tall, float threshold) {
    return threshold > 0.0 ? clamp((tall - threshold) / (kFadeBand * threshold), 0.0, 1.0) : 1.0;
}

bool keptByFade(float fade, vec2 fragCoord) {
    const uvec2 p = uvec2(fragCoord) & 3u;
    // Bayer's 4x4 matrix, row by row.
    const uint bayer[16] = uint[16](0u, 8u, 2u, 10u, 12u, 4u, 14u, 6u, 3u, 11u, 1u, 9u, 15u, 7u, 13u, 5u);
    const float threshold = (float(bayer[p.y * 4u + p.x]) + 0.5) / 16.0;
    return fade >= 0.0 ? threshold < fade : threshold >= -fade;
}

#endif
