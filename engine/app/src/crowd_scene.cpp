#include "crowd_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <tuple>

#include "throng/core/log.h"
#include "throng/core/supported_range.h"
#include "throng/render/crowd_renderer.h"
#include "throng/motion/bvh_parser.h"

namespace throng::app {
namespace {

constexpr double kSimulationStep = 1.0 / 30.0;      // seconds
constexpr float kSquareMetresPerCharacter = 2.56F;  // the paper-like default density

// A track faster than any sprinter most likely has its positions in another unit than the one
// read (a file in centimetres without a unit line reads as metres, 100 times too fast). It is
// followed as read; the warning says why a crowd may run.
void warnOfSuperhumanSpeed(const std::string& path, const crowd::Trajectories& trajectories) {
    constexpr double kFastestHuman = 12.5;  // m/s, a sprinter's top speed
    double fastest = 0.0, at = 0.0;
    std::int64_t who = 0;
    for (const crowd::Track& track : trajectories.tracks)
        for (std::size_t k = 1; k < track.samples.size(); ++k) {
            const crowd::TrackSample &a = track.samples[k - 1], &b = track.samples[k];
            const double speed = glm::length(b.position - a.position) / (b.time - a.time);
            if (speed > fastest) std::tie(fastest, at, who) = std::tuple(speed, a.time, track.id);
        }
    if (!(fastest > kFastestHuman)) return;
    char line[256];
    std::snprintf(line, sizeof line, "trajectories %s: id %lld moves at %.3g m/s at %.2f s, faster than people run: "
                  "if the positions are not in metres, give --trajectory-units cm or mm",
                  path.c_str(), static_cast<long long>(who), fastest, at);
    log::warning(line);
}

// One character per track of --trajectories, posed by --locomotion or the project's own set.
Result<bool> followTrajectories(const CrowdOptions& options, SceneDescription& description) {
    auto read = crowd::readTrajectories(*options.trajectories, options.trajectoryReading);
    if (!read) return read.error();
    auto trajectories = std::make_shared<const crowd::Trajectories>(std::move(read.value()));
    char summary[160];
    const std::size_t people = trajectories->tracks.size();
    std::snprintf(summary, sizeof summary, ": %zu %s, %zu samples over %.2f s", people, people == 1 ? "person" : "people",
                  trajectories->rows, trajectories->duration);
    log::report("trajectories " + *options.trajectories + ": " + trajectories->format + summary);
    warnOfSuperhumanSpeed(*options.trajectories, *trajectories);
    description.clips = options.locomotion.empty() ? defaultLocomotionSet() : options.locomotion;
    glm::dvec2 lo(range::kMaxCoordinate), hi(-range::kMaxCoordinate);
    for (const crowd::Track& track : trajectories->tracks)
        for (const crowd::TrackSample& sample : track.samples) {
            lo = glm::min(lo, sample.position);
            hi = glm::max(hi, sample.position);
        }
    // The tracks' bounds, for the ground's size (the region places nobody: tracks do).
    const crowd::Region bounds{glm::vec2((lo + hi) * 0.5), glm::max(glm::vec2(hi - lo), glm::vec2(1.0F))};
    description.setup.groups.push_back({.count = static_cast<int>(trajectories->tracks.size()), .clips = {}, .region = bounds,
                                        .mode = crowd::Mode::Follow, .speedRange = {1.0F, 1.0F}, .heading = 0.0F,
                                        .locomotion = 0U, .groundSpeed = kDefaultGroundSpeed});
    description.setup.groups.back().name = "the tracks of --trajectories " + *options.trajectories;
    description.locomotionMembers.emplace_back();
    for (std::uint32_t c = 0; c < description.clips.size(); ++c) description.locomotionMembers.back().push_back(c);
    description.setup.area = bounds;
    description.setup.trajectories = std::move(trajectories);
    for (const ClipSpec& clip : description.clips) description.clipNames.push_back(std::filesystem::path(clip.path).stem().string());
    return true;
}

// What errors call the crowd the command line asks for: by the options that shape it, as the
// user gave them ("--area 1x1"), not as "group 0" of a scene they never wrote.
std::string commandLineCrowdName(const CrowdOptions& options) {
    if (!options.area) return "the command line's crowd";
    char text[80];
    std::snprintf(text, sizeof text, "--area %gx%g", static_cast<double>(options.area->x), static_cast<double>(options.area->y));
    return text;
}

// The crowd from --scene, or from --bvh/--characters/--mode/--area; --seed and --threads applied.
Result<SceneDescription> describeCrowd(const CrowdOptions& options) {
    SceneDescription description;
    if (options.scene) {
        auto scene = loadScene(*options.scene);
        if (!scene) return scene.error();
        description = std::move(scene.value());
    } else if (options.trajectories) {
        auto followed = followTrajectories(options, description);
        if (!followed) return followed.error();
    } else {
        // No --bvh: a set blends, the given one or the project's own.
        const bool blends = options.clips.empty();
        description.clips = !blends ? options.clips : options.locomotion.empty() ? defaultLocomotionSet() : options.locomotion;
        const float side = std::sqrt(static_cast<float>(options.characters) * kSquareMetresPerCharacter);
        const glm::vec2 area = options.area.value_or(glm::vec2(side, side));
        description.setup.groups.push_back({.count = options.characters, .clips = {}, .region = {glm::vec2(0.0F), area},
                                            .mode = options.mode, .speedRange = {1.0F, 1.0F}, .heading = 0.0F,
                                            .locomotion = blends ? std::optional<std::uint32_t>(0) : std::nullopt,
                                            .groundSpeed = options.speed.value_or(kDefaultGroundSpeed)});
        description.setup.groups.back().name = commandLineCrowdName(options);
        if (blends) {
            description.locomotionMembers.emplace_back();
            for (std::uint32_t c = 0; c < description.clips.size(); ++c) description.locomotionMembers.back().push_back(c);
        }
        description.setup.area = {glm::vec2(0.0F), area};
        for (const ClipSpec& clip : description.clips) description.clipNames.push_back(std::filesystem::path(clip.path).stem().string());
    }
    if (options.seed) description.setup.seed = *options.seed;
    description.setup.threads = options.threads;
    return description;
}

// Steps in fixed 1/30 s steps and one remainder step, so a given time always simulates the same.
void advance(crowd::Crowd& crowd, std::span<const motion::BakedClip> clips, double seconds) {
    const long long steps = clampedFloor<long long>(seconds / kSimulationStep + 1e-9, 0, 1LL << 40);
    for (long long s = 0; s < steps; ++s) crowd.step(clips, kSimulationStep);
    const double remainder = seconds - static_cast<double>(steps) * kSimulationStep;
    if (remainder > 1e-9) crowd.step(clips, remainder);
}

}  // namespace

std::string defaultClipPath() {
    if (const char* dir = std::getenv("THRONG_ASSET_DIR"); dir != nullptr && *dir != '\0') return std::string(dir) + "/walk.bvh";
    // Beside the executable: share/throng in the build tree, ../share/throng when installed.
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return "walk.bvh";  // no /proc: the loader's error then names the file it looked for
    for (const std::filesystem::path& candidate : {exe.parent_path() / "share/throng/walk.bvh",
                                                   exe.parent_path().parent_path() / "share/throng/walk.bvh"})
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate.string();
    return (exe.parent_path().parent_path() / "share/throng/walk.bvh").string();
}

std::vector<ClipSpec> defaultLocomotionSet() {
    const std::filesystem::path walk = defaultClipPath();
    std::vector<ClipSpec> set;
    for (const char* name : {"idle.bvh", "slow_walk.bvh", "walk.bvh", "run.bvh"}) set.push_back({(walk.parent_path() / name).string(), {}});
    return set;
}

Result<std::vector<motion::BakedClip>> loadClips(const std::vector<ClipSpec>& specs) {
    std::vector<motion::BakedClip> clips;
    std::set<std::string> warned;  // a clip given twice warns once
    for (const ClipSpec& spec : specs) {
        const std::string& path = spec.path;
        auto raw = motion::loadBvhFile(path);
        if (!raw) return raw.error();
        auto clip = motion::bake(raw.value(), spec.bake);
        if (!clip) return clip.error();
        const motion::BakedClip& baked = clip.value();
        // Before the clip's info line, which THRONG_LOG=info users (and a test) read as
        // followed by the next clip's or the device's.
        for (const std::string& warning : baked.warnings)
            if (warned.insert(path + ": " + warning).second) log::warning(path + ": " + warning);
        log::info(path + ": " + std::to_string(baked.jointCount()) + " joints, " + std::to_string(baked.frameCount) + " frames, " +
                  std::to_string(baked.stature) + " m tall, loop " + std::to_string(baked.loop().first) + ".." +
                  std::to_string(baked.loop().last));
        clips.push_back(std::move(clip.value()));
    }
    return clips;
}

std::int64_t CrowdScene::plannedCharacters() const {
    std::int64_t total = 0;
    for (const crowd::GroupSpec& group : description.setup.groups) total += group.count;
    return total;
}

std::uint32_t CrowdScene::jointsPerCharacter() const {
    std::uint32_t joints = 0;
    for (const motion::BakedClip& clip : clipSpan()) joints = std::max(joints, static_cast<std::uint32_t>(clip.jointCount()));
    return joints;
}

void CrowdScene::step(double seconds) {
    crowd->step(clipSpan(), seconds);
    packedCacheCurrent = false;
}

Result<bool> CrowdScene::respawn(double seconds) {
    auto spawned = crowd::Crowd::spawn(clipSpan(), description.setup);
    if (!spawned) return spawned.error();
    crowd.emplace(std::move(spawned.value()));
    advance(*crowd, clipSpan(), seconds);
    packedCacheCurrent = false;
    return true;
}

std::span<const crowd::CharacterState> CrowdScene::packed() const {
    if (!packedCacheCurrent) {
        packedCache.resize(static_cast<std::size_t>(size()));
        if (crowd) crowd->pack(packedCache);
        packedCacheCurrent = true;
    }
    return packedCache;
}

crowd::CharacterState CrowdScene::character(int i) const {
    crowd::CharacterState state{};
    crowd->pack(static_cast<std::size_t>(i), std::span(&state, 1));
    return state;
}

render::CharacterSource CrowdScene::source(int highlighted, std::uint32_t highlight) const {
    return {static_cast<std::size_t>(size()), [this, highlighted, highlight](std::size_t first, std::span<crowd::CharacterState> out) {
                crowd->pack(first, out);
                if (highlighted >= 0 && static_cast<std::size_t>(highlighted) - first < out.size())
                    out[static_cast<std::size_t>(highlighted) - first].color = highlight;
            }};
}

Result<CrowdScene> prepareCrowdScene(const CrowdOptions& options, SharedClips clips) {
    auto description = describeCrowd(options);
    if (!description) return description.error();
    CrowdScene scene{std::move(description.value()), std::move(clips), std::nullopt, {}, false};
    if (!scene.clips) {
        auto loaded = loadClips(scene.description.clips);
        if (!loaded) return loaded.error();
        scene.clips = std::make_shared<const std::vector<motion::BakedClip>>(std::move(loaded.value()));
    }
    auto sets = makeSceneLocomotionSets(scene.description, scene.clipSpan());
    if (!sets) return sets.error();
    scene.description.setup.locomotion = std::move(sets.value());
    return scene;
}

Result<CrowdScene> loadCrowdScene(const CrowdOptions& options, SharedClips clips) {
    auto scene = prepareCrowdScene(options, std::move(clips));
    if (!scene) return scene.error();
    if (auto spawned = scene.value().respawn(options.time); !spawned) return spawned.error();
    return scene;
}

Result<CrowdScene> loadCrowdScene(const CrowdOptions& options) { return loadCrowdScene(options, nullptr); }

std::optional<Error> checkCrowdFits(const gpu::Context& context, const CrowdScene& scene, render::Body body, std::uint32_t slots) {
    // A crowd past one storage buffer is drawn in batches; what bounds it is the device's memory.
    const std::uint64_t perCharacter = render::CrowdRenderer::bytesPerCharacter(scene.clipSpan(), body) * std::max(slots, 1U);
    const std::uint64_t heap = context.largestDeviceHeap();
    const std::int64_t wanted = scene.plannedCharacters();
    if (wanted >= 0 && static_cast<std::uint64_t>(wanted) <= heap / perCharacter) return std::nullopt;
    return Error{Error::Kind::BadInput,
                 std::to_string(wanted) + " characters drawn as " + std::string(render::bodyName(body)) + " need about " +
                     std::to_string(static_cast<std::uint64_t>(std::max<std::int64_t>(wanted, 0)) * perCharacter >> 20) +
                     " MiB of GPU memory; this device has " + std::to_string(heap >> 20) + " MiB (at most " +
                     std::to_string(heap / perCharacter) + " characters)",
                 {}};
}

std::optional<CameraSpec> requestedCamera(const CrowdOptions& options, const CrowdScene& scene) {
    return options.camera ? options.camera : scene.description.camera;
}

float crowdReach(const CrowdScene& scene) {
    float reach = 0.0F;
    for (const crowd::CharacterState& c : scene.packed()) reach = std::max({reach, std::abs(c.groundFrame.x), std::abs(c.groundFrame.z)});
    return reach;
}

CrowdView frameView(const CrowdScene& scene, float aspect, const std::optional<CameraSpec>& given, DefaultView defaultView) {
    CrowdView view;
    std::vector<glm::vec3> grounds;
    for (const crowd::CharacterState& c : scene.packed()) grounds.emplace_back(c.groundFrame.x, 0.0F, c.groundFrame.z);
    view.reach = crowdReach(scene);
    for (const motion::BakedClip& clip : scene.clipSpan()) view.height = std::max(view.height, static_cast<float>(clip.stature));
    view.camera = defaultView == DefaultView::Street ? render::streetCamera(grounds, aspect) : render::frameCrowd(grounds, view.height, aspect);
    if (given) placeCamera(view.camera, *given, view);
    return view;
}

bool seesAnyCharacter(const CrowdScene& scene, const render::Camera& camera, float aspect, float stature) {
    const std::array<glm::vec4, 6> planes = render::frustumPlanes(camera.viewProjection(aspect));
    return std::ranges::any_of(scene.packed(), [&](const crowd::CharacterState& c) {
        const float radius = 0.5F * stature * c.scale;
        const glm::vec3 centre(c.groundFrame.x, radius, c.groundFrame.z);
        return c.scale > 0.0F && std::ranges::all_of(planes, [&](const glm::vec4& plane) { return glm::dot(glm::vec3(plane), centre) + plane.w >= -radius; });
    });
}

void placeCamera(render::Camera& camera, const CameraSpec& spec, const CrowdView& view) {
    camera.eye = spec.eye;
    camera.target = spec.target;
    camera.verticalFovDegrees = spec.verticalFovDegrees;
    // Nothing drawn is nearer than the eye's height above the tallest body, and its depth along
    // the view is at least that times cos(fov / 2) (a point at the frame's edge): the near plane
    // may come out to half that, so a view from 10^6 m up keeps the depth's and the clipper's
    // precision (a near plane of 5 cm against a far one of 10^7 m drew the ground as a notch).
    const float tallest = 1.5F * view.height;
    const float nearest = (spec.eye.y - tallest) * std::cos(glm::radians(0.5F * spec.verticalFovDegrees));
    camera.nearPlane = std::max(0.05F, 0.5F * nearest);
    // Past the target by the crowd's reach, and from high up past the ground below too.
    camera.farPlane = std::max(glm::length(spec.eye - spec.target), 2.0F * std::abs(spec.eye.y)) + 2.0F * view.reach + 200.0F;
}

}  // namespace throng::app
