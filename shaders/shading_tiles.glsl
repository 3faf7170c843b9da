// The visibility path's shading tiles: the frame cut into kShadingTile-pixel squares, so that
// its shading draws only the squares that need it, each with the shader it needs. lavapipe
// runs every branch of a shader for every pixel, so one full-screen pass paid for a body's
// shading on the sky and the empty ground too; now the splats mark each square a body may
// touch, with what kind of body, and classify_tiles.comp lists the squares a bone may show in,
// those only joint spheres may, and the unmarked ones that see the ground. The shading draws
// the first list with the whole shader, the second with the joints' part alone (it reads
// neither bones nor their arithmetic: visibility_resolve.glsl's THRONG_RESOLVE_JOINTS_ONLY),
// the ground's with the ground's alone (THRONG_RESOLVE_GROUND_ONLY), and leaves the sky squares
// as they were cleared. The pixels come out as the one pass made them.
// The contact shadows mark their squares too (kShadowMark): the ground squares no shadow
// touches are listed apart and shaded without reading the shadows (THRONG_RESOLVE_NO_SHADOWS),
// a per-pixel read they are spared (it was about a sixth of the ground's shading when lavapipe
// made it lane by lane from a storage buffer; it is a texel fetch now). Of those, the
// squares every pixel of which sees the ground are listed apart again and shaded "opaque"
// (THRONG_RESOLVE_OPAQUE): no pixel discarded. Only then does lavapipe write a pixel's colour
// straight out; for any other shader it reads the pixels back, decodes their sRGB, merges and
// encodes them again. So are the body and joint squares that stand wholly on the ground: every
// pixel there is a body's or the ground's. The shading has no depth test and writes no depth
// (skinned bodies test against the visibility buffer and the ground plane instead,
// skin_shading.glsl), so a skinned body near a square does not keep it from being opaque.
//
// A still camera keeps the ground (keepsLastFrame). Where the frame is drawn over the
// slot's last one with the same scene (offscreen frames: a benchmark, a video's still shots),
// a square that saw only the unshadowed ground then and does now holds its pixels already: it
// is not listed again. Each square's state after the frame (kSquareSky, kSquareGround or
// kSquareOther) is kept for the next; a square that held something else and may show sky is
// first painted the sky's colour (the sky list), since the shading leaves sky pixels as they
// were. Skinned bodies, drawn over the shading, list their screen bounds (skinBoxes) so that the
// squares under them count as something else.
//
// The buffer: eight indirect draws (the body squares, the ground squares no shadow touches, the
// joint squares, the ground squares a shadow may darken, the opaque ground, body and joint
// squares, then the squares to paint with the sky), whether the frame keeps the last one, the
// skinned bodies' bounds, then per square its mark (kJointMark | kBoneMark | kShadowMark: what
// may show there; 0: only the ground), the eight lists in that order, each a square's index,
// and last each square's state, which the per-frame clear leaves alone. The draws' firstVertex
// (the list times 6) tells visibility_tiles.vert which list.
#ifndef THRONG_SHADING_TILES_GLSL
#define THRONG_SHADING_TILES_GLSL

#include "bindings.glsl"

const int kShadingTile = THRONG_SHADING_TILE_PIXELS;  // pixels a side (binding_numbers.h, C++ reads it too)

const uint kSkinBoxes = THRONG_SKIN_BOXES;  // binding_numbers.h

struct TileDrawGpu {
    uint vertexCount, instanceCount, firstVertex, firstInstance;
};

#ifdef THRONG_COMPUTE_WRITES
layout(set = 0, binding = THRONG_BINDING_SHADING_TILES, std430) buffer ShadingTiles {
#else
layout(set = 0, binding = THRONG_BINDING_SHADING_TILES, std430) readonly buffer ShadingTiles {
#endif
    TileDrawGpu tileDraws[THRONG_SHADING_TILE_LISTS];  // a list's draw, at the list's index (below)
    uint keepsLastFrame;  // 1: the colour attachment holds this slot's last frame, of the same scene
    uint skinBoxCount;    // skinned bodies' bounds listed (past kSkinBoxes: every square is under one)
    uint unboundedSkin;   // 1: a skinned body too near the eye to bound (every square is under it)
    uint keptSquares;     // squares whose ground the frame kept from the last (not drawn again)
    ivec4 skinBoxes[kSkinBoxes];  // first and last pixel, inclusive
    uint tileData[];
};

// A square's mark: a joint sphere or a bone may show there, or a contact shadow.
const uint kJointMark = 1u, kBoneMark = 2u, kShadowMark = 4u;

// Squares across and down the frame (the last of each may be cut short).
uvec2 tileGrid() { return (uvec2(scene.viewport.xy) + uint(kShadingTile - 1)) / uint(kShadingTile); }

// The lists, in the draws' order (a draw's firstVertex / 6), and where each starts in tileData:
// after the marks, a frame's worth of squares each.
const uint kBodyTileList = 0u, kGroundTileList = 1u, kJointTileList = 2u, kShadowedGroundTileList = 3u, kOpaqueGroundTileList = 4u,
           kOpaqueBodyTileList = 5u, kOpaqueJointTileList = 6u, kSkyTileList = 7u, kTileLists = THRONG_SHADING_TILE_LISTS;
// A square's state after a frame, at tileListStart(kTileLists): what its pixels hold.
const uint kSquareOther = 0u, kSquareSky = 1u, kSquareGround = 2u;
uint tileListStart(uint list) {
    const uvec2 grid = tileGrid();
    return grid.x * grid.y * (1u + list);
}

#ifdef THRONG_COMPUTE_WRITES
// Marks every square the pixels lo..hi (inclusive, inside the frame) touch with `mark`: a body
// of that kind (or a shadow) may show there. Every splatted pixel lies in its splat's bound,
// so none goes unmarked. `across`: tileGrid().x, which a splat reads once (splat_frame.glsl).
void markBodyTiles(ivec2 lo, ivec2 hi, uint mark, uint across) {
    if (any(greaterThan(lo, hi))) return;
    const ivec2 first = lo / kShadingTile, last = hi / kShadingTile;
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) atomicOr(tileData[uint(y) * across + uint(x)], mark);
}

// Lists a skinned body's screen bound, pixels lo..hi (inclusive), or, with `bounded` false,
// says that one could not be bounded: no square keeps its pixels past this frame.
void listSkinBox(ivec2 lo, ivec2 hi, bool bounded) {
    if (!bounded) {
        atomicOr(unboundedSkin, 1u);
        return;
    }
    const uint at = atomicAdd(skinBoxCount, 1u);
    if (at >= kSkinBoxes) return;
    // Atomic stores, as the splats' other writes here: the splats run unordered among themselves.
    atomicExchange(skinBoxes[at].x, lo.x);
    atomicExchange(skinBoxes[at].y, lo.y);
    atomicExchange(skinBoxes[at].z, hi.x);
    atomicExchange(skinBoxes[at].w, hi.y);
}
#endif

#endif
