// libFuzzer entry point for scene files: any text must either be refused with an error that
// names the file, or give a scene whose crowd spawns (or is refused) and then steps without
// ever holding a non-finite position, heading or frame. Stepping is the point: a waypoint of
// 1e39 passed the old reader and hung the simulation at -O3; this finds that kind of input.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene_file.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/bvh_parser.h"

#ifndef THRONG_FUZZ_SCENE_PATH
#error "THRONG_FUZZ_SCENE_PATH must name a (virtual) scene file beside the project's clips"
#endif

namespace {

// Clips by path, baked once: most inputs name the same one or two.
const throng::motion::BakedClip* clipAt(const std::string& path) {
    static std::map<std::string, std::optional<throng::motion::BakedClip>> cache;
    auto found = cache.find(path);
    if (found == cache.end()) {
        std::optional<throng::motion::BakedClip> clip;
        if (cache.size() < 16)
            if (auto raw = throng::motion::loadBvhFile(path))
                if (auto baked = throng::motion::bake(raw.value())) clip = std::move(baked.value());
        found = cache.emplace(path, std::move(clip)).first;
    }
    return found->second ? &*found->second : nullptr;
}

void checkFinite(const throng::crowd::Crowd& crowd, std::span<const throng::motion::BakedClip> clips) {
    std::vector<throng::crowd::CharacterState> packed(static_cast<std::size_t>(crowd.size()));
    crowd.pack(packed);
    for (const throng::crowd::CharacterState& c : packed) {
        const int frames = clips[c.clip].frameCount;
        if (!std::isfinite(c.groundFrame.x) || !std::isfinite(c.groundFrame.z) || !std::isfinite(c.groundFrame.w)) std::abort();
        if (!(c.frame >= 0.0F && c.frame <= static_cast<float>(frames))) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto scene = throng::app::parseScene(text, THRONG_FUZZ_SCENE_PATH);
    if (!scene) {
        if (scene.error().location.file.empty() || scene.error().message.empty()) std::abort();  // errors name the file
        return 0;
    }
    std::vector<throng::motion::BakedClip> clips;
    // Clips bake with default options: the reader has checked the overrides, and the bake's
    // own tests cover them; the cache stays one clip per file.
    for (const throng::app::ClipSpec& spec : scene.value().clips) {
        const throng::motion::BakedClip* clip = clipAt(spec.path);
        if (clip == nullptr) return 0;
        clips.push_back(*clip);
    }
    throng::crowd::CrowdSetup setup = scene.value().setup;
    // Groups' locomotion sets, as prepareCrowdScene makes them: a refusal names the file too.
    auto sets = throng::app::makeSceneLocomotionSets(scene.value(), clips);
    if (!sets) {
        if (sets.error().location.file.empty() || sets.error().message.empty()) std::abort();
        return 0;
    }
    setup.locomotion = std::move(sets.value());
    setup.threads = 1;
    for (throng::crowd::GroupSpec& group : setup.groups) group.count = std::min(group.count, 40);  // keep each input fast
    auto crowd = throng::crowd::Crowd::spawn(clips, setup);
    if (!crowd) return 0;
    for (const double step : {1.0 / 30.0, 1.0 / 30.0, 0.5, 3.0, 1.0 / 30.0}) {
        crowd.value().step(clips, step);
        checkFinite(crowd.value(), clips);
    }
    return 0;
}
