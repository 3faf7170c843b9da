// Cross-fade between levels of detail (--body auto), so a character crossing a threshold
// dissolves from one body into the next instead of popping: while it fades both levels are
// drawn, each keeping the pixels the other leaves out, by a 4x4 ordered dither. A fade f >= 0
// keeps the pixels whose dither value is below f (the level fading in as f rises to 1); f < 0
// keeps those at or above -f (the level fading out). 1 keeps all.
//
// The fade runs over frames, not over distance: a character's fade is the share of its last
// kLevelFadeFrames frames in which it was tall enough for the nearer level, so one that crosses
// a threshold dissolves into the next level over that many frames, and only the few crossing
// at any moment are drawn at two levels (a band of distance a quarter of the threshold wide,
// as the fade once was, drew every character in it at both, and a still image showed them half
// dissolved). The planning pass keeps each character's last frames as bits (the LevelFades
// buffer); a still, or a frame of another crowd, starts them all at its own level. The fade is
// a function of those frames alone, so a video rendered in parts, each part drawing the
// kLevelFadeFrames frames before its first (render_video.cpp), matches one rendered whole.
#ifndef THRONG_LOD_FADE_GLSL
#define THRONG_LOD_FADE_GLSL

#include "binding_numbers.h"

const uint kLevelFadeFrames = THRONG_LEVEL_FADE_FRAMES;  // bits a level's history keeps
const uint kLevelFadeBits = (1u << kLevelFadeFrames) - 1u;

// A level's history (its last kLevelFadeFrames frames, a bit each, the newest lowest) moved on
// by a frame in which the character was `tall` pixels tall against `threshold` (0 or less:
// always at the nearer level); with no previous frame, every bit is this frame's.
uint levelHistory(uint history, float tall, float threshold, bool continues) {
    const bool nearer = threshold <= 0.0 || tall >= threshold;
    if (!continues) return nearer ? kLevelFadeBits : 0u;
    return ((history << 1) & kLevelFadeBits) | (nearer ? 1u : 0u);
}

// The fade of the nearer level in: the share of the history's frames it was tall enough for it.
float levelFade(uint history) { return float(bitCount(history & kLevelFadeBits)) / float(kLevelFadeFrames); }

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
