#version 450
// The visibility path's shading tiles (shading_tiles.glsl), once the splats have marked them:
// one invocation per square lists it for the whole shading (a bone may show there), for the
// joints' (only joint spheres may), for the ground's (no body, and some of its rays come down
// to the ground plane: apart, those a contact shadow may darken, and those whose every pixel
// sees the ground), or for none (the sky, as cleared). Over the slot's last frame of the same
// scene, it leaves out the ground squares that hold their shading already and lists the squares
// to paint with the sky first (shading_tiles.glsl).
#extension GL_GOOGLE_include_directive : require
#define THRONG_COMPUTE_WRITES
#include "bindings.glsl"
#include "shading_tiles.glsl"

layout(local_size_x = 64) in;

// Whether the ray through pixel `pixel` (frame coordinates) heads down. A near-plane point is
// affine in the pixel's coordinates, so the height of (point - eye) is too: over a square it
// is least at a corner, and a square none of whose corners' rays head down has none that do.
bool headsDown(vec2 pixel) {
    const vec4 near = scene.inverseViewProjectionAtEye * vec4(pixel / scene.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
    return near.y / near.w < 0.0;
}

// Whether the ray through pixel `pixel` meets the ground plane in front of the eye, well inside
// the ground's square (a thousandth of its size to spare, for the shading's rounding). The
// ground's square is convex and the frame's points map onto the plane projectively, so a
// square of the frame whose four corners do this has every pixel on the ground.
bool wellOnGround(vec2 pixel) {
    const vec4 near = scene.inverseViewProjectionAtEye * vec4(pixel / scene.viewport.xy * 2.0 - 1.0, 0.0, 1.0);
    const vec3 eye = scene.cameraPosition.xyz, direction = near.xyz / near.w;
    if (!(direction.y < 0.0 && eye.y > 0.0)) return false;
    const vec2 point = eye.xz - eye.y / direction.y * direction.xz;
    return all(lessThanEqual(abs(point), vec2(0.999 * scene.groundParams.x)));
}

// Whether any skinned body drawn this frame may cover pixels lo..hi (inclusive).
bool underSkin(ivec2 lo, ivec2 hi) {
    const uint listed = skinBoxCount;
    if (unboundedSkin != 0u || listed > kSkinBoxes) return true;
    for (uint i = 0u; i < listed; ++i) {
        const ivec4 box = skinBoxes[i];
        if (all(lessThanEqual(box.xy, hi)) && all(lessThanEqual(lo, box.zw))) return true;
    }
    return false;
}

const uint kNoList = 0xffffffffu;

// Adds square `tile` to list `list`, its draw counting one more.
void listTile(uint list, uint tile) { tileData[tileListStart(list) + atomicAdd(tileDraws[list].instanceCount, 1u)] = tile; }

void main() {
    const uvec2 grid = tileGrid();
    const uint count = grid.x * grid.y, tile = gl_GlobalInvocationID.x;
    if (tile >= count) return;
    const uint mark = tileData[tile];
    const vec2 lo = vec2(uvec2(tile % grid.x, tile / grid.x) * uint(kShadingTile));
    const vec2 hi = min(lo + float(kShadingTile), scene.viewport.xy);
    // Shaded opaque: every pixel a body's or the ground's.
    const bool opaque = wellOnGround(lo) && wellOnGround(vec2(hi.x, lo.y)) && wellOnGround(vec2(lo.x, hi.y)) && wellOnGround(hi);
    uint list = kNoList, state = kSquareOther;
    if ((mark & kBoneMark) != 0u) {
        list = opaque ? kOpaqueBodyTileList : kBodyTileList;
    } else if ((mark & kJointMark) != 0u) {
        list = opaque ? kOpaqueJointTileList : kJointTileList;
    } else if (!(scene.cameraPosition.y > 0.0) || !(headsDown(lo) || headsDown(vec2(hi.x, lo.y)) || headsDown(vec2(lo.x, hi.y)) || headsDown(hi))) {
        // The sky alone (groundAlong, visibility_resolve.glsl, finds no ground from an eye at or below it).
        state = kSquareSky;
    } else if ((mark & kShadowMark) != 0u) {
        list = kShadowedGroundTileList;
    } else {
        list = opaque ? kOpaqueGroundTileList : kGroundTileList;
        state = kSquareGround;
    }
    const uint stateAt = tileListStart(kTileLists) + tile;
    if (keepsLastFrame != 0u) {
        const uint before = tileData[stateAt];
        // The same scene's unshadowed ground is there already.
        if (state == kSquareGround && before == kSquareGround) {
            list = kNoList;
            atomicAdd(keptSquares, 1u);
        }
        // The shading leaves sky pixels as they are: where the square held more than sky and
        // ground and may show sky, paint it with the sky first.
        else if (!opaque && (before == kSquareOther || (state == kSquareSky && before != kSquareSky)))
            listTile(kSkyTileList, tile);
    }
    if (list != kNoList) listTile(list, tile);
    // Skinned bodies are drawn over the shading: their squares hold more than it drew.
    tileData[stateAt] = underSkin(ivec2(lo), ivec2(hi) - 1) ? kSquareOther : state;
}
