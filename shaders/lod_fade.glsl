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
    // Bayer's 4x4 matrix (rows 0 8 2 10, 12 4 14 6, 3 11 1 9, 15 7 13 5) from the bits of x ^ y
    // and y, bit-reversed and interleaved: a table indexed per pixel costs a CPU rasteriser a
    // load per lane, this a few integer operations.
    const uint v = p.x ^ p.y;
    const uint bayer = ((v & 1u) << 3) | ((p.y & 1u) << 2) | (v & 2u) | (p.y >> 1);
    const float threshold = (float(bayer) + 0.5) / 16.0;
    return fade >= 0.0 ? threshold < fade : threshold >= -fade;
}

#endif
