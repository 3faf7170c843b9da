#pragma once
// The one crowd set-up that render, demo and bench share, in two steps: prepare (describe the
// crowd from the options or a scene file, load and bake its clips) and spawn (place every
// character, advance to the asked time, pack for the GPU). Between the two a caller can check
// the crowd's size against the device before any character exists, as `throng render` does.
// Then frame it with a first camera.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "scene_file.h"
#include "throng/app/cli.h"
#include "throng/gpu/context.h"
#include "throng/render/camera.h"
#include "throng/render/crowd_renderer.h"

namespace throng::app {

/// The project's own default clip: $THRONG_ASSET_DIR/walk.bvh, else walk.bvh in share/throng
/// beside the executable (build tree) or in ../share/throng (installed).
[[nodiscard]] std::string defaultClipPath();

/// Parses and bakes every clip with its own options; the first error stops it. Each clip's
/// bake warnings go to stderr once, "throng: warning: FILE: text" (THRONG_LOG filters them).
[[nodiscard]] Result<std::vector<motion::BakedClip>> loadClips(const std::vector<ClipSpec>& clips);

/// A set's desired ground speeds without --speed, m/s: strolling to brisk.
inline constexpr glm::vec2 kDefaultGroundSpeed{1.0F, 1.6F};

/// The project's own locomotion set: idle, slow walk, walk and run beside defaultClipPath().
[[nodiscard]] std::vector<ClipSpec> defaultLocomotionSet();

using SharedClips = std::shared_ptr<const std::vector<motion::BakedClip>>;

/// A spawned crowd with its clips and this frame's characters.
struct CrowdScene {
    SceneDescription description;
    SharedClips clips;
    std::optional<crowd::Crowd> crowd;

    [[nodiscard]] std::span<const motion::BakedClip> clipSpan() const { return *clips; }
    /// Characters spawned (0 before the first spawn).
    [[nodiscard]] int size() const { return crowd ? crowd->size() : 0; }
    /// k: the largest joint count of any clip (every character gets k instances).
    [[nodiscard]] std::uint32_t jointsPerCharacter() const;
    /// Characters the description asks for, spawned or not.
    [[nodiscard]] std::int64_t plannedCharacters() const;
    /// Advances every character by `seconds`.
    void step(double seconds);
    /// Spawns the crowd from `description` (again, after a change to it) and advances it `seconds`.
    [[nodiscard]] Result<bool> respawn(double seconds);

    /// Every character as of the last step, packed in host memory for readers on the CPU
    /// (dumps, a trajectory file): packed on the first call after a step. A frame that is only
    /// drawn never packs here; its renderer takes source().
    [[nodiscard]] std::span<const crowd::CharacterState> packed() const;
    /// One character as of the last step, without packing the rest.
    [[nodiscard]] crowd::CharacterState character(int i) const;
    /// The crowd for a renderer: packed straight into its memory on the crowd's threads.
    /// Character `highlighted` (if in the crowd) is written with colour `highlight` instead of its own.
    [[nodiscard]] render::CharacterSource source(int highlighted = -1, std::uint32_t highlight = 0) const;

    // The host copy behind packed(), and whether it is of the last step.
    mutable std::vector<crowd::CharacterState> packedCache;
    mutable bool packedCacheCurrent = false;
};

/// Step 1: the description and the baked clips (`clips`, when given, are used as they are:
/// the benchmark loads them once for many crowds). Nothing is spawned yet.
[[nodiscard]] Result<CrowdScene> prepareCrowdScene(const CrowdOptions& options, SharedClips clips = nullptr);
/// Both steps: prepared, then spawned and advanced to options.time.
[[nodiscard]] Result<CrowdScene> loadCrowdScene(const CrowdOptions& options);
/// The same with clips already loaded.
[[nodiscard]] Result<CrowdScene> loadCrowdScene(const CrowdOptions& options, SharedClips clips);

/// Refuses (BadInput) a planned crowd larger than the device's memory holds in `slots` frames
/// in flight, before anything is spawned: refused in a second, not after minutes of simulation.
[[nodiscard]] std::optional<Error> checkCrowdFits(const gpu::Context& context, const CrowdScene& scene, render::Body body,
                                                 std::uint32_t slots);

/// A first view: the given camera, or one that frames every character.
struct CrowdView {
    render::Camera camera;
    float reach = 0.0F;   ///< Largest |x| or |z| of any character (for the ground's size).
    float height = 0.0F;  ///< Tallest clip, metres.
};
/// Puts `camera` where `spec` says (eye, target, field of view), with near and far planes for
/// the crowd `view` frames (its reach from the origin, its tallest body).
void placeCamera(render::Camera& camera, const CameraSpec& spec, const CrowdView& view);
/// The camera the user asked for: --camera, else the scene file's, else none.
[[nodiscard]] std::optional<CameraSpec> requestedCamera(const CrowdOptions& options, const CrowdScene& scene);
/// `given`, or (nullopt) the default `view` of the crowd.
[[nodiscard]] CrowdView frameView(const CrowdScene& scene, float aspect, const std::optional<CameraSpec>& given,
                                  DefaultView view = DefaultView::Overview);
/// Largest |x| or |z| of any character's ground position (CrowdView::reach).
[[nodiscard]] float crowdReach(const CrowdScene& scene);
/// Whether any character of `scene` stands, at least in part, inside what `camera` sees at
/// `aspect` (each a sphere about its body, `stature` (CrowdView::height) times its scale tall).
[[nodiscard]] bool seesAnyCharacter(const CrowdScene& scene, const render::Camera& camera, float aspect, float stature);

}  // namespace throng::app
