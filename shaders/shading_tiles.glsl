// The visibility path's shading tiles: the frame cut into kShadingTile-pixel squares, so that
// its shading draws only the squares that need it, each with the shader it needs. lavapipe
// runs every branch of a shader for every pixel, so one full-screen pass paid for a body's
// shading on the sky and the empty ground too; now the splats mark each square a body may
// touch, classify_tiles.comp lists the marked squares and the unmarked ones that see the
// ground, and the shading draws the first list with the whole shader, the second with the
// ground's alone (visibility_resolve.glsl's THRONG_RESOLVE_GROUND_ONLY), and leaves the sky
// squares as they were cleared. The pixels come out as the one pass made them.
//
// The buffer: two indirect draws (the body squares, then the ground squares), then per square
// its mark (0: no body), then the body squares' list, then the ground squares' list, each a
// square's index. The draws' firstVertex (0 and 6) tells visibility_tiles.vert which list.
#ifndef THRONG_SHADING_TILES_GLSL
#define THRONG_SHADING_TILES_GLSL

#include "bindings.glsl"

const int kShadingTile = THRONG_SHADING_TILE_PIXELS;  // pixels a side (binding_numbers.h, C++ reads it too)

struct TileDrawGpu {
    uint vertexCount, instanceCount, firstVertex, firstInstance;
};

#ifdef THRONG_COMPUTE_WRITES
layout(set = 0, binding = THRONG_BINDING_SHADING_TILES, std430) buffer ShadingTiles {
#else
layout(set = 0, binding = THRONG_BINDING_SHADING_TILES, std430) readonly buffer ShadingTiles {
#endif
    TileDrawGpu bodyTiles, groundTiles;
    uint tileData[];
};

// Squares across and down the frame (the last of each may be cut short).
uvec2 tileGrid() { return (uvec2(scene.viewport.xy) + uint(kShadingTile - 1)) / uint(kShadingTile); }

#ifdef THRONG_COMPUTE_WRITES
// Marks every square the pixels lo..hi (inclusive, inside the frame) touch: a body may show
// there. Every splatted pixel lies in its splat's bound, so no body pixel goes unmarked.
void markBodyTiles(ivec2 lo, ivec2 hi) {
    if (any(greaterThan(lo, hi))) return;
    const uint across = tileGrid().x;
    const ivec2 first = lo / kShadingTile, last = hi / kShadingTile;
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) tileData[uint(y) * across + uint(x)] = 1u;
}
#endif

#endif
