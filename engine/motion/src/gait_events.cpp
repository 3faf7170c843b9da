// Gait events: where each foot strikes the ground and lifts off over the loop, and which leg is
// the body's left. A gait phase is timed from them (0 at the left foot's strike), which is what
// clips blended at different speeds are aligned by.
#include <algorithm>

#include "bake_steps.h"

namespace throng::motion::bake_steps {

GaitEvents findGaitEvents(const PoseTable& poses, const Anatomy& anatomy, const PlantedFeet& planted, LoopRange loop) {
    GaitEvents out;
    const int length = loop.length();
    if (!anatomy.biped() || length < 4) return out;
    for (std::size_t l = 0; l < 2; ++l) {
        const std::vector<char>& ankle = planted.ankle[l];
        const std::vector<char>& toe = planted.toe[l];
        if (ankle.size() != static_cast<std::size_t>(length) || (!toe.empty() && toe.size() != ankle.size())) continue;
        // Down while the heel or the toe is planted: a toe that lands first strikes, and the
        // toe's push-off after heel-off is still the same contact.
        const auto down = [&](int k) {
            const auto slot = static_cast<std::size_t>(k % length);
            return ankle[slot] != 0 || (!toe.empty() && toe[slot] != 0);
        };
        const auto runs = cyclicRuns(length, down);
        if (!runs) continue;  // a foot that never lifts never strikes
        for (const auto& [first, last] : *runs)
            out.contacts[l].push_back({loop.first + first % length, loop.first + (last + 1) % length});
        std::sort(out.contacts[l].begin(), out.contacts[l].end(),
                  [](const FootContact& a, const FootContact& b) { return a.strike < b.strike; });
    }
    // The ground frame faces +Z with the body's left towards +X: the left leg's hip is the one
    // further along +X on average over the loop (names are not trusted: exporters differ).
    double side = 0.0;
    for (int f = loop.first; f < loop.last; ++f)
        side += poses.pos(f, anatomy.legs[0].hip).x - poses.pos(f, anatomy.legs[1].hip).x;
    out.leftLeg = side > 0 ? 0 : 1;
    return out;
}

}  // namespace throng::motion::bake_steps
