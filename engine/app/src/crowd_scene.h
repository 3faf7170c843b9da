#pragma once
// The one crowd set-up that render, demo and bench share: describe the crowd from the options
// (or a scene file), load and bake its clips, spawn it, advance it to the asked time, pack it
// for the GPU, and frame it with a first camera.

#include <memory>
#include <optional>
#include <vector>

#include "scene_file.h"
#include "throng/app/cli.h"
#include "throng/render/camera.h"

namespace throng::app {

/// The project's own default clip: $THRONG_ASSET_DIR/walk.bvh, else walk.bvh in share/throng
/// beside the executable (build tree) or in ../share/throng (installed).
[[nodiscard]] std::string defaultClipPath();

/// Parses and bakes every clip; the first error stops it.
[[nodiscard]] Result<std::vector<motion::BakedClip>> loadClips(const std::vector<std::string>& paths);

using SharedClips = std::shared_ptr<const std::vector<motion::BakedClip>>;

/// A spawned crowd with its clips and this frame's packed characters.
struct CrowdScene {
    SceneDescription description;
    SharedClips clips;
    std::optional<crowd::Crowd> crowd;
    std::vector<crowd::CharacterState> packed;  ///< One per character, as of the last step.

    [[nodiscard]] std::span<const motion::BakedClip> clipSpan() const { return *clips; }
    [[nodiscard]] int size() const { return static_cast<int>(packed.size()); }
    /// Advances every character by `seconds` and packs them again.
    void step(double seconds);
    /// Spawns the crowd again from `description` (after a change to it) and advances it `seconds`.
    [[nodiscard]] Result<bool> respawn(double seconds);
};

/// The whole set-up from the command line's crowd options, advanced to options.time.
[[nodiscard]] Result<CrowdScene> loadCrowdScene(const CrowdOptions& options);
/// The same with clips already loaded (the benchmark loads them once for many crowds).
[[nodiscard]] Result<CrowdScene> loadCrowdScene(const CrowdOptions& options, SharedClips clips);

/// A first view: the given camera, or one that frames every character.
struct CrowdView {
    render::Camera camera;
    float reach = 0.0F;   ///< Largest |x| or |z| of any character (for the ground's size).
    float height = 0.0F;  ///< Tallest clip, metres.
};
/// The camera the user asked for: --camera, else the scene file's, else none.
[[nodiscard]] std::optional<CameraSpec> requestedCamera(const CrowdOptions& options, const CrowdScene& scene);
/// `given`, or (nullopt) a camera that frames every character.
[[nodiscard]] CrowdView frameView(const CrowdScene& scene, float aspect, const std::optional<CameraSpec>& given);

}  // namespace throng::app
