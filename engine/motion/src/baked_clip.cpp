// BakedClip's own methods, and the per-joint sizes and level of detail the bake hands it.
#include <algorithm>
#include <cmath>

#include "bake_steps.h"

namespace throng::motion {

const char* upAxisName(UpAxis axis) {
    static constexpr const char* kNames[] = {"y", "-y", "z", "-z", "x", "-x"};
    return kNames[static_cast<int>(axis)];
}

std::optional<UpAxis> upAxisFromName(std::string_view name) {
    for (UpAxis axis : {UpAxis::PlusY, UpAxis::MinusY, UpAxis::PlusZ, UpAxis::MinusZ, UpAxis::PlusX, UpAxis::MinusX})
        if (name == upAxisName(axis)) return axis;
    return std::nullopt;
}

namespace {

// The two frames around a fractional frame position among `frames`, and how far from the
// lower to the upper (clamped to the table; NaN reads as frame 0), as poses and every per-frame
// table are interpolated.
struct Bracket {
    int lower, upper;
    float t;
};
Bracket bracket(double frame, int frames) {
    const int lower = clampedFloor(frame, 0, frames - 1);
    const double fraction = frame - lower;
    return {lower, std::min(lower + 1, frames - 1), static_cast<float>(fraction > 0.0 ? std::min(fraction, 1.0) : 0.0)};
}

// Linear interpolation of a per-frame table at a fractional frame.
template <typename T>
T interpolated(const std::vector<T>& table, double frame) {
    const auto [lower, upper, t] = bracket(frame, static_cast<int>(table.size()));
    return table[static_cast<std::size_t>(lower)] + t * (table[static_cast<std::size_t>(upper)] - table[static_cast<std::size_t>(lower)]);
}

}  // namespace

glm::dvec2 BakedClip::pivotAt(double frame) const {
    return pivots.empty() ? glm::dvec2(0.0) : glm::dvec2(interpolated(pivots, frame));
}

double BakedClip::turnFreedomAt(double frame) const {
    return turnFreedom.empty() ? 1.0 : static_cast<double>(interpolated(turnFreedom, frame));
}

glm::dvec2 BakedClip::footHoldAt(double frame) const {
    return footHold.empty() ? glm::dvec2(0.0) : glm::dvec2(interpolated(footHold, frame));
}

std::array<glm::dvec2, 2> BakedClip::anklesAt(double frame) const {
    std::array<glm::dvec2, 2> out{};
    if (frameCount <= 0) return out;  // no poses to read either way
    if (ankleGround.size() != static_cast<std::size_t>(frameCount)) {
        for (std::size_t l = 0; l < 2; ++l)
            if (const int ankle = anatomy.legs[l].ankle; ankle >= 0) {
                const glm::vec3 p = positionAt(frame, ankle);
                out[l] = {p.x, p.z};
            }
        return out;
    }
    // glm::mix, as positionAt blends the translations, so both give the same bits.
    const auto [lower, upper, t] = bracket(frame, frameCount);
    const std::array<glm::vec2, 2>& a = ankleGround[static_cast<std::size_t>(lower)];
    const std::array<glm::vec2, 2>& b = ankleGround[static_cast<std::size_t>(upper)];
    for (std::size_t l = 0; l < 2; ++l) out[l] = glm::dvec2(glm::mix(a[l], b[l], t));
    return out;
}

double BakedClip::turnGainAt(double frame) const {
    // At most 3x: a slow walk free for a tenth of its cycle turned at up to 10 rad/s in short
    // bursts at 4x (7.8 at 3x), twisting the held foot to its bound every step (CMU 131_02 slid
    // 1.3x while turning at 4x, 1.1x at 3x, over straight walking at the same phases).
    constexpr double kRarelyFree = 0.1, kLargestGain = 3.0;
    if (meanTurnFreedom < kRarelyFree) return 1.0;
    return std::min(kLargestGain, turnFreedomAt(frame) / meanTurnFreedom);
}

double BakedClip::gaitPhaseAt(double frame) const {
    if (leftLeg < 0 || footContacts[static_cast<std::size_t>(leftLeg)].empty()) return -1.0;
    const std::vector<FootContact>& left = footContacts[static_cast<std::size_t>(leftLeg)];
    const LoopRange range = loop();
    const double length = range.length();
    // Everything as an offset from the first left strike, modulo the loop.
    const auto offset = [&](double x) {
        const double t = std::fmod(x - left.front().strike, length);
        return t < 0 ? t + length : t;
    };
    const double t = std::isfinite(frame) ? offset(frame) : 0.0;
    for (std::size_t i = 0; i < left.size(); ++i) {
        const double from = offset(left[i].strike);  // ascending: the strikes are sorted
        const double to = i + 1 < left.size() ? offset(left[i + 1].strike) : length;
        if (t < to || i + 1 == left.size()) return std::clamp((t - from) / (to - from), 0.0, 1.0);
    }
    return 0.0;
}

glm::mat4 BakedClip::matrix(int frame, int joint) const {
    const JointPose& p = pose(frame, joint);
    glm::mat4 m = glm::mat4_cast(p.rotation);
    m[3] = glm::vec4(p.translation, 1.0F);
    return m;
}

JointPose BakedClip::sample(double frame, int joint) const {
    const auto [lower, upper, t] = bracket(frame, frameCount);
    const JointPose& a = pose(lower, joint);
    const JointPose& b = pose(upper, joint);
    // nlerp along the shorter arc; neighbouring frames are close, so it matches slerp closely.
    const glm::quat bq = glm::dot(a.rotation, b.rotation) < 0 ? -b.rotation : b.rotation;
    JointPose out;
    out.rotation = glm::normalize(a.rotation * (1.0F - t) + bq * t);
    out.translation = glm::mix(a.translation, b.translation, t);
    return out;
}

glm::vec3 BakedClip::positionAt(double frame, int joint) const {
    const auto [lower, upper, t] = bracket(frame, frameCount);
    return glm::mix(pose(lower, joint).translation, pose(upper, joint).translation, t);
}

glm::dvec3 BakedClip::worldPosition(const GroundFrame& ground, double frame, int joint) const {
    return glm::dvec3(ground.matrix() * glm::dvec4(glm::dvec3(positionAt(frame, joint)), 1.0));
}

namespace bake_steps {

std::vector<std::array<glm::vec2, 2>> ankleGround(const BakedClip& clip) {
    std::vector<std::array<glm::vec2, 2>> table(static_cast<std::size_t>(clip.frameCount));
    for (int f = 0; f < clip.frameCount; ++f)
        for (std::size_t l = 0; l < 2; ++l)
            if (const int ankle = clip.anatomy.legs[l].ankle; ankle >= 0) {
                const glm::vec3& p = clip.pose(f, ankle).translation;
                table[static_cast<std::size_t>(f)][l] = {p.x, p.z};
            }
    return table;
}

// Sphere size per joint: a fraction of the shortest bone that touches it, so fingers get
// small spheres and hips big ones, clamped to the skeleton's height.
std::vector<float> jointRadii(const RawMotion& motion, double metresPerUnit, double height) {
    const int joints = motion.jointCount();
    std::vector<double> shortest(static_cast<std::size_t>(joints), 1e300);
    auto touch = [&](int joint, double length) {
        if (joint >= 0 && length > 1e-9) shortest[static_cast<std::size_t>(joint)] = std::min(shortest[static_cast<std::size_t>(joint)], length);
    };
    for (int j = 0; j < joints; ++j) {
        const double length = glm::length(motion.joints[static_cast<std::size_t>(j)].offset) * metresPerUnit;
        touch(j, length);
        touch(motion.joints[static_cast<std::size_t>(j)].parent, length);
    }
    for (const RawEndSite& site : motion.endSites) touch(site.parent, glm::length(site.offset) * metresPerUnit);
    std::vector<float> radius;
    for (double length : shortest) {
        // Fairly even beads read best as a figure; the clamp keeps fingers visible and knees modest.
        const double r = length > 1e299 ? 0.03 * height : 0.22 * length;
        radius.push_back(static_cast<float>(std::clamp(r, 0.022 * height, 0.04 * height)));
    }
    return radius;
}

// Level of detail: which joints a distant character may leave out because another joint
// stands (almost) where it does. Within 7% of the height counts as the same spot. A link with
// a child that close is represented by that child (so chains end at the head, the hip, the
// hand); a link sitting on its parent by the parent (CMU's zero-length hip and neck links); a
// short leaf beside a sibling by the sibling (the thumb beside the fingers).
std::vector<std::uint8_t> footLegs(const std::vector<int>& parents, const Anatomy& anatomy) {
    std::vector<std::uint8_t> leg(parents.size(), 0);
    if (!anatomy.biped()) return leg;
    for (std::size_t j = 0; j < parents.size(); ++j)
        for (int up = static_cast<int>(j); up >= 0 && leg[j] == 0; up = parents[static_cast<std::size_t>(up)])
            for (std::size_t l = 0; l < 2; ++l)
                if (up == anatomy.legs[l].ankle) leg[j] = static_cast<std::uint8_t>(1 + l);
    return leg;
}

std::vector<std::uint8_t> detailJoints(const BakedClip& clip, int frame) {
    const int joints = clip.jointCount();
    const float near = 0.07F * static_cast<float>(clip.stature);
    const auto gap = [&](int a, int b) { return glm::length(clip.pose(frame, a).translation - clip.pose(frame, b).translation); };
    std::vector<std::vector<int>> children(static_cast<std::size_t>(joints));
    for (int j = 1; j < joints; ++j)
        if (clip.parents[static_cast<std::size_t>(j)] >= 0) children[static_cast<std::size_t>(clip.parents[static_cast<std::size_t>(j)])].push_back(j);
    std::vector<std::uint8_t> detail(static_cast<std::size_t>(joints), 0);
    for (int j = 0; j < joints; ++j) {
        const int parent = clip.parents[static_cast<std::size_t>(j)];
        if (parent < 0) continue;  // roots always stay
        const auto& kids = children[static_cast<std::size_t>(j)];
        const bool childClose = std::any_of(kids.begin(), kids.end(), [&](int c) { return gap(c, j) < near; });
        // Only a parent that stays can stand in (depth-first order decides parents first).
        const bool onParent = !kids.empty() && gap(j, parent) < near && detail[static_cast<std::size_t>(parent)] == 0;
        const bool besideSibling = kids.empty() && gap(j, parent) < near && children[static_cast<std::size_t>(parent)].size() > 1 &&
                                   children[static_cast<std::size_t>(parent)].front() != j;
        detail[static_cast<std::size_t>(j)] = childClose || onParent || besideSibling ? 1 : 0;
    }
    return detail;
}

}  // namespace bake_steps
}  // namespace throng::motion
