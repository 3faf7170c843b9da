// Up axis and stature: gravity read from the body, and the standing height of a typical frame.
#include <algorithm>
#include <array>
#include <cmath>

#include "bake_steps.h"

namespace throng::motion::bake_steps {
namespace {

constexpr double kQuarterTurn = 1.5707963267948966;

}  // namespace

glm::dvec3 pointAt(const glm::dmat4* frame, const RawMotion& motion, std::pair<int, int> point) {
    if (point.second < 0) return glm::dvec3(frame[point.first][3]);
    return glm::dvec3(frame[point.first] * glm::dvec4(motion.endSites[static_cast<std::size_t>(point.second)].offset, 1.0));
}

double percentile(std::vector<double> values, double fraction, Rank rank) {
    if (values.empty()) return 0.0;
    const double position = fraction * static_cast<double>(values.size() - 1);
    const auto at = values.begin() + (rank == Rank::Nearest ? static_cast<std::ptrdiff_t>(std::lround(position)) : static_cast<std::ptrdiff_t>(position));
    std::nth_element(values.begin(), at, values.end());
    return *at;
}

glm::dmat4 toYUp(UpAxis axis) {
    const glm::dmat4 identity(1.0);
    switch (axis) {
        case UpAxis::PlusY: return identity;
        case UpAxis::MinusY: return glm::rotate(identity, 2.0 * kQuarterTurn, glm::dvec3(1, 0, 0));
        case UpAxis::PlusZ: return glm::rotate(identity, -kQuarterTurn, glm::dvec3(1, 0, 0));   // +Z -> +Y
        case UpAxis::MinusZ: return glm::rotate(identity, kQuarterTurn, glm::dvec3(1, 0, 0));   // -Z -> +Y
        case UpAxis::PlusX: return glm::rotate(identity, kQuarterTurn, glm::dvec3(0, 0, 1));    // +X -> +Y
        case UpAxis::MinusX: return glm::rotate(identity, -kQuarterTurn, glm::dvec3(0, 0, 1));  // -X -> +Y
    }
    return identity;
}

std::optional<UpAxis> detectUpAxis(std::span<const glm::dmat4> globals, int joints, const Anatomy& anatomy) {
    if (!anatomy.biped() || joints <= 0) return std::nullopt;
    std::vector<int> legJoints;
    for (const LegChain& leg : anatomy.legs)
        for (int j : {leg.hip, leg.knee, leg.ankle, leg.toe})
            if (j >= 0) legJoints.push_back(j);
    // Spine minus legs, summed over frames: with the arms hanging or raised, the trunk and head
    // outweigh them, so this points up for anyone standing, walking, running or dancing.
    glm::dvec3 up(0.0);
    const std::size_t frames = globals.size() / static_cast<std::size_t>(joints);
    for (std::size_t f = 0; f < frames; ++f) {
        const glm::dmat4* g = &globals[f * static_cast<std::size_t>(joints)];
        glm::dvec3 spine(0.0), legs(0.0);
        for (int j : anatomy.spine) spine += glm::dvec3(g[j][3]);
        for (int j : legJoints) legs += glm::dvec3(g[j][3]);
        const glm::dvec3 direction = spine / static_cast<double>(anatomy.spine.size()) - legs / static_cast<double>(legJoints.size());
        const double length = glm::length(direction);
        if (length > 0) up += direction / length;
    }
    const std::array<std::pair<UpAxis, glm::dvec3>, 6> axes{{{UpAxis::PlusY, {0, 1, 0}},
                                                            {UpAxis::MinusY, {0, -1, 0}},
                                                            {UpAxis::PlusZ, {0, 0, 1}},
                                                            {UpAxis::MinusZ, {0, 0, -1}},
                                                            {UpAxis::PlusX, {1, 0, 0}},
                                                            {UpAxis::MinusX, {-1, 0, 0}}}};
    if (!(glm::length(up) > 0)) return std::nullopt;
    const auto best = std::max_element(axes.begin(), axes.end(), [&](const auto& a, const auto& b) {
        return glm::dot(a.second, up) < glm::dot(b.second, up);
    });
    return best->first;
}

double uprightStature(std::span<const glm::dmat4> globals, const RawMotion& motion, const Anatomy& anatomy) {
    const int joints = motion.jointCount();
    const std::size_t frames = globals.size() / static_cast<std::size_t>(joints);
    std::vector<double> heights;
    heights.reserve(frames);
    for (std::size_t f = 0; f < frames; ++f) {
        const glm::dmat4* g = &globals[f * static_cast<std::size_t>(joints)];
        if (anatomy.biped()) {
            const double top = pointAt(g, motion, {anatomy.head, anatomy.headEndSite}).y;
            double sole = 1e300;
            for (const LegChain& leg : anatomy.legs)
                for (const auto& point : leg.soles) sole = std::min(sole, pointAt(g, motion, point).y);
            heights.push_back(top - sole);
            continue;
        }
        double lo = 1e300, hi = -1e300;
        for (int j = 0; j < joints; ++j) lo = std::min(lo, g[j][3].y), hi = std::max(hi, g[j][3].y);
        for (std::size_t s = 0; s < motion.endSites.size(); ++s) {
            const double y = pointAt(g, motion, {motion.endSites[s].parent, static_cast<int>(s)}).y;
            lo = std::min(lo, y), hi = std::max(hi, y);
        }
        heights.push_back(hi - lo);
    }
    // Upright, not typical: a median counts every crouch, bow and stride's knee bend (a dance
    // reads 20 cm short), while a few frames of the clip stand tall. The 90th percentile is
    // those frames, and no single outlier (a jump) decides it.
    return std::max(percentile(std::move(heights), 0.9, Rank::Nearest), 0.0);
}

}  // namespace throng::motion::bake_steps
