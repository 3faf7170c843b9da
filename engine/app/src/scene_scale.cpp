// Scaling a scene's crowd to another size, group by group (scene_file.h: scaleScene).
#include <algorithm>
#include <cmath>
#include <numeric>

#include "scene_file.h"

namespace throng::app {

std::optional<Error> scaleScene(SceneDescription& scene, std::int64_t total) {
    std::vector<crowd::GroupSpec>& groups = scene.setup.groups;
    const auto groupCount = static_cast<std::int64_t>(groups.size());
    if (groups.empty() || total < groupCount || total > kMaxCharacters)
        return Error{Error::Kind::BadInput,
                     "can't scale " + std::to_string(groupCount) + " group(s) to " + std::to_string(total) +
                         " characters: each group needs one, and a crowd has at most " + std::to_string(kMaxCharacters),
                     {scene.source, 0, 0}};
    std::int64_t planned = 0;
    for (const crowd::GroupSpec& group : groups) planned += group.count;
    // Integer shares, so the scene's own total comes back exactly: floor(count * total /
    // planned) each, then one more to the largest remainders (ties to the earlier group).
    std::vector<std::int64_t> counts(groups.size()), remainders(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::int64_t share = static_cast<std::int64_t>(groups[g].count) * total;
        counts[g] = std::max<std::int64_t>(share / planned, 1);  // a group of none couldn't spawn
        remainders[g] = share % planned;
    }
    std::vector<std::size_t> order(groups.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainders[a] > remainders[b]; });
    std::int64_t given = std::accumulate(counts.begin(), counts.end(), std::int64_t{0});
    for (std::size_t k = 0; given < total; k = (k + 1) % order.size(), ++given) ++counts[order[k]];
    // Groups raised to one can leave too many: the largest groups give them back.
    while (given > total) {
        --*std::max_element(counts.begin(), counts.end());
        --given;
    }
    for (std::size_t g = 0; g < groups.size(); ++g) {
        crowd::GroupSpec& group = groups[g];
        group.region.size *= std::sqrt(static_cast<float>(counts[g]) / static_cast<float>(group.count));
        group.count = static_cast<int>(counts[g]);
    }
    return std::nullopt;
}

}  // namespace throng::app
