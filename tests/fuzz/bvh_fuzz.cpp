// libFuzzer entry point: any byte string must either parse and bake, or be refused with
// an error that has a location. Crashes, hangs, sanitizer reports and non-finite baked
// values are the bugs it looks for.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto raw = throng::motion::parseBvh(text, "fuzz.bvh");
    if (!raw) {
        if (raw.error().location.line < 1) std::abort();  // every parse error must say where
        return 0;
    }
    // Baking is linear in frames x joints, but not free; keep each input fast.
    if (static_cast<long long>(raw.value().frameCount) * raw.value().jointCount() > 100000) return 0;
    auto clip = throng::motion::bake(raw.value());
    if (!clip) return 0;
    for (const throng::motion::JointPose& pose : clip.value().poses)
        if (!std::isfinite(pose.translation.x) || !std::isfinite(pose.rotation.w)) std::abort();
    return 0;
}
