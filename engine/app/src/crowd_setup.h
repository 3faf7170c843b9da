#pragma once
// What `throng render` and `throng demo` share: turning crowd options into clips, a crowd and
// a first camera.

#include <optional>
#include <vector>

#include "scene_file.h"
#include "throng/app/cli.h"
#include "throng/render/camera.h"

namespace throng::app {

/// The crowd from --scene, or from --bvh/--characters/--mode/--area; --seed and --threads applied.
[[nodiscard]] Result<SceneDescription> describeCrowd(const CrowdOptions& options);

/// Parses and bakes every clip; the first error stops it.
[[nodiscard]] Result<std::vector<motion::BakedClip>> loadClips(const std::vector<std::string>& paths);

/// Steps the crowd through `seconds` in fixed 1/30 s steps and one remainder step.
void advance(crowd::Crowd& crowd, std::span<const motion::BakedClip> clips, double seconds);

/// A first view: the given camera, or one that frames every character.
struct CrowdView {
    render::Camera camera;
    float reach = 0.0F;   ///< Largest |x| or |z| of any character (for the ground's size).
    float height = 0.0F;  ///< Tallest clip, metres.
};
[[nodiscard]] CrowdView frameView(std::span<const crowd::CharacterState> characters, std::span<const motion::BakedClip> clips,
                                  float aspect, const std::optional<CameraSpec>& given);

}  // namespace throng::app
