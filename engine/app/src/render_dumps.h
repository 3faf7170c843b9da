#pragma once
// What `throng render --dump-instances` and `--dump-bodies` write: the GPU's work read back
// as JSON, with each character's state as the compute pass read it, so tests can recompute
// it on the CPU (tests/gpu/check_instances.cpp).

#include <nlohmann/json.hpp>
#include <span>

#include "throng/crowd/character_state.h"
#include "throng/motion/baked_clip.h"
#include "throng/render/offscreen.h"

namespace throng::app {

using Json = nlohmann::ordered_json;

/// The clips as the dumps list them: source file, joint names, height.
[[nodiscard]] Json clipListJson(std::span<const motion::BakedClip> clips);

/// One character's state as the GPU read it: index, clip, frame, ground frame, scale, foot
/// twist, blend and transition.
[[nodiscard]] Json characterJson(std::size_t index, const crowd::CharacterState& character);

/// --dump-bodies (bones, skin, auto): per character the level it was drawn at ("culled",
/// "spheres", "bones", "skin"), its height on screen, and the bones drawn (at the bones level,
/// or fading out under the skin) with their joints, ends and radii.
[[nodiscard]] Json bodyDump(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> packed,
                            const render::OffscreenRenderer& offscreen);

}  // namespace throng::app
