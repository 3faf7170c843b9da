#pragma once
// The project's own clips (assets/: idle, slow walk, walk, run), for the unit tests that need
// a real locomotion set, read beside the default clip the build names (THRONG_DEFAULT_CLIP).

#include <filesystem>
#include <string>
#include <vector>

#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"

namespace unit_test {

/// The path of assets/`name`.
inline std::string asset(const std::string& name) {
    return (std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path() / name).string();
}

/// The clip at `path`, parsed and baked with the default options (throws on an error).
inline throng::motion::BakedClip bakeFile(const std::string& path) {
    return throng::motion::bake(throng::motion::loadBvhFile(path).orThrow()).orThrow();
}

/// The project's set by rising speed: 0 idle, 1 slow walk, 2 walk, 3 run; baked once per
/// test program, as every test reads the same clips.
inline const std::vector<throng::motion::BakedClip>& projectClips() {
    static const std::vector<throng::motion::BakedClip> clips{bakeFile(asset("idle.bvh")), bakeFile(asset("slow_walk.bvh")),
                                                              bakeFile(asset("walk.bvh")), bakeFile(asset("run.bvh"))};
    return clips;
}

}  // namespace unit_test
