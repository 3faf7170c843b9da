#define THRONG_BINDING_POSES 0
#define THRONG_BINDING_CLIPS 1
#define THRONG_BINDING_JOINT_RADII 2
#define THRONG_BINDING_CHARACTERS 3
#define THRONG_BINDING_INSTANCES 4
#define THRONG_BINDING_SCENE_UNIFORMS 5
#define THRONG_BINDING_DRAW_ARGUMENTS 6
#define THRONG_BINDING_INSTANCE_OWNERS 7
#define THRONG_BINDING_JOINT_DETAIL 8
#define THRONG_BINDING_BONES 9
#define THRONG_BINDING_BONE_INSTANCES 10
#define THRONG_BINDING_BIND_POSES 11
#define THRONG_BINDING_SKIN_JOINTS 12
#define THRONG_BINDING_SKIN_CHARACTERS 13
#define THRONG_BINDING_SKIN_DRAWS 14
#define THRONG_BINDING_BODY_LEVELS 15
#define THRONG_BINDING_VISIBILITY 16
#define THRONG_BINDING_CHARACTER_LISTS 17
#define THRONG_BINDING_SHADOWS 18
#define THRONG_BINDING_SHADING_TILES 19
#define THRONG_BINDING_VISIBILITY_TEXELS 20
#define THRONG_BINDING_SHADOW_TEXELS 21
#define THRONG_BINDING_SKIN_JOINT_TEXELS 22
#define THRONG_BINDING_LEVEL_FADES 23
#define THRONG_BINDING_INSTANCE_TEXELS 24
#define THRONG_BINDING_BONE_INSTANCE_TEXELS 25
// Not a binding: pixels a side of the visibility path's shading squares (shading_tiles.glsl),
// here so that C++ sizes and dispatches them as the shaders cut them.
#define THRONG_SHADING_TILE_PIXELS 64
// Not a binding: pixels a side of the blocks the visibility path's per-pixel buffers hold the
// frame in (visibility.glsl's pixelSlot), here so that C++ pads the buffers to whole blocks.
#define THRONG_PIXEL_BLOCK 4
// Not a binding: pixels a side of the visibility path's contact-shadow texels (visibility.glsl's
// shadowSlot), here so that C++ sizes their buffer. The shading's bilinear read assumes 2.
#define THRONG_SHADOW_TEXEL 2
// Not a binding: how many lists of squares the visibility path's shading draws, each with its
// indirect draw (shading_tiles.glsl).
#define THRONG_SHADING_TILE_LISTS 8
// Not a binding: how many skinned bodies' screen bounds the visibility path's shading squares
// list (shading_tiles.glsl); past that, no square keeps its pixels to the next frame.
#define THRONG_SKIN_BOXES 64
// Not a binding: which per-character stretch of the character lists holds the visibility path's
// list of contact shadows too large to splat one invocation a shadow (after the body writers').
#define THRONG_LARGE_SHADOW_LIST 3
// Not a binding: the workgroup size of the passes that allot compacted joints and bones in
// character order (slot_allocation.glsl); C++ sizes their slots and dispatches them by it.
#define THRONG_ALLOCATION_GROUP 64
// Not a binding: the frames a bone body's cross-fade between levels takes (lod_fade.glsl); C++
// (render::kLevelFadeFrames) draws as many before a video part's first frame.
#define THRONG_LEVEL_FADE_FRAMES 8
// The visibility path's epochs (visibility.glsl): its buffer is filled one frame in as many. At
// most 15: four bits, the fifteenth value meaning none.
#define THRONG_VISIBILITY_EPOCHS 15
