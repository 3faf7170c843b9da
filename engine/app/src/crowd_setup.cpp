#include "crowd_setup.h"

#include <cmath>

#include "bvh_commands.h"
#include "throng/motion/bvh_parser.h"

namespace throng::app {
namespace {
constexpr double kSimulationStep = 1.0 / 30.0;      // seconds
constexpr float kSquareMetresPerCharacter = 2.56F;  // the paper-like default density
}  // namespace

Result<SceneDescription> describeCrowd(const CrowdOptions& options) {
    SceneDescription description;
    if (options.scene) {
        auto scene = loadScene(*options.scene);
        if (!scene) return scene.error();
        description = std::move(scene.value());
    } else {
        description.clipPaths = options.clips.empty() ? std::vector<std::string>{defaultClipPath()} : options.clips;
        const float side = std::sqrt(static_cast<float>(options.characters) * kSquareMetresPerCharacter);
        const glm::vec2 area = options.area.value_or(glm::vec2(side, side));
        description.setup.groups.push_back({.count = options.characters, .clips = {}, .region = {glm::vec2(0.0F), area},
                                            .mode = options.mode, .speedRange = {1.0F, 1.0F}, .heading = 0.0F});
        description.setup.area = {glm::vec2(0.0F), area};
    }
    if (options.seed) description.setup.seed = *options.seed;
    description.setup.threads = options.threads;
    return description;
}

Result<std::vector<motion::BakedClip>> loadClips(const std::vector<std::string>& paths) {
    std::vector<motion::BakedClip> clips;
    for (const std::string& path : paths) {
        auto raw = motion::loadBvhFile(path);
        if (!raw) return raw.error();
        auto clip = motion::bake(raw.value());
        if (!clip) return clip.error();
        clips.push_back(std::move(clip.value()));
    }
    return clips;
}

void advance(crowd::Crowd& crowd, std::span<const motion::BakedClip> clips, double seconds) {
    const auto steps = static_cast<long long>(std::floor(seconds / kSimulationStep + 1e-9));
    for (long long s = 0; s < steps; ++s) crowd.step(clips, kSimulationStep);
    const double remainder = seconds - static_cast<double>(steps) * kSimulationStep;
    if (remainder > 1e-9) crowd.step(clips, remainder);
}

CrowdView frameView(std::span<const crowd::CharacterState> characters, std::span<const motion::BakedClip> clips, float aspect,
                    const std::optional<CameraSpec>& given) {
    CrowdView view;
    std::vector<glm::vec3> grounds;
    for (const crowd::CharacterState& c : characters) {
        grounds.emplace_back(c.groundFrame.x, 0.0F, c.groundFrame.z);
        view.reach = std::max({view.reach, std::abs(c.groundFrame.x), std::abs(c.groundFrame.z)});
    }
    for (const motion::BakedClip& clip : clips) view.height = std::max(view.height, static_cast<float>(clip.height));
    view.camera = render::frameCrowd(grounds, view.height, aspect);
    if (given) {
        view.camera.eye = given->eye;
        view.camera.target = given->target;
        view.camera.verticalFovDegrees = given->verticalFovDegrees;
        view.camera.nearPlane = 0.05F;
        view.camera.farPlane = glm::length(given->eye - given->target) + 2.0F * view.reach + 200.0F;
    }
    return view;
}

}  // namespace throng::app
