// The character's ground path: where the body is and which way it faces, frame by frame.
#include <algorithm>
#include <cmath>

#include "bake_steps.h"

namespace throng::motion::bake_steps {
namespace {

constexpr double kPi = 3.141592653589793;

std::vector<double> unwrapped(std::vector<double> yaw) {
    for (std::size_t f = 1; f < yaw.size(); ++f) yaw[f] = yaw[f - 1] + wrapAngle(yaw[f] - yaw[f - 1]);
    return yaw;
}

// Heading of a joint from its own axes: where its local +Z points on the ground. A joint whose
// +Z is nearly vertical has no usable heading from +Z, so its +X, turned a quarter, stands in.
double jointYaw(const glm::dmat4& joint) {
    const glm::dvec3 forward(joint[2]);
    if (std::hypot(forward.x, forward.z) > 0.3) return yawOf(forward);
    return yawOf(glm::dvec3(joint[0])) - 0.5 * kPi;
}

}  // namespace

std::vector<double> bodyHeading(std::span<const glm::dmat4> globals, int joints, const Anatomy& anatomy, int travelJoint,
                                const RawMotion& motion) {
    const std::size_t frames = globals.size() / static_cast<std::size_t>(joints);
    std::vector<double> yaw(frames, 0.0);
    if (!anatomy.biped()) {
        for (std::size_t f = 0; f < frames; ++f) yaw[f] = jointYaw(globals[f * static_cast<std::size_t>(joints) + static_cast<std::size_t>(travelJoint)]);
        return unwrapped(std::move(yaw));
    }
    // Facing is square to the line through the hips. Which of the two ways is forward: the
    // feet point forward (toes ahead of ankles), summed over the clip; for a skeleton without
    // feet that point anywhere, the way the body travels.
    double toesAhead = 0.0;
    glm::dvec2 meanForward(0.0);
    for (std::size_t f = 0; f < frames; ++f) {
        const glm::dmat4* g = &globals[f * static_cast<std::size_t>(joints)];
        const glm::dvec3 lateral = glm::dvec3(g[anatomy.legs[0].hip][3]) - glm::dvec3(g[anatomy.legs[1].hip][3]);
        const glm::dvec3 forward(-lateral.z, 0.0, lateral.x);
        yaw[f] = yawOf(forward);
        meanForward += glm::dvec2(forward.x, forward.z);
        for (const LegChain& leg : anatomy.legs) {
            const glm::dvec3 tip = pointAt(g, motion, leg.soles.back()) - glm::dvec3(g[leg.ankle][3]);
            toesAhead += tip.x * forward.x + tip.z * forward.z;
        }
    }
    const glm::dvec3 first(globals[static_cast<std::size_t>(travelJoint)][3]);
    const glm::dvec3 last(globals[(frames - 1) * static_cast<std::size_t>(joints) + static_cast<std::size_t>(travelJoint)][3]);
    const double travelAhead = (last.x - first.x) * meanForward.x + (last.z - first.z) * meanForward.y;
    const double scaleOfFeet = 1e-3 * glm::length(meanForward);
    const bool backwards = std::abs(toesAhead) > scaleOfFeet ? toesAhead < 0 : travelAhead < 0;
    if (backwards)
        for (double& y : yaw) y += kPi;
    return unwrapped(std::move(yaw));
}

std::vector<double> smoothed(const std::vector<double>& values, int begin, double frameTime, double seconds) {
    std::vector<double> out = values;
    const int count = static_cast<int>(values.size());
    const int half = clampedFloor(0.5 * seconds / frameTime + 0.5, 0, std::max(count, 1));  // lround, bounded by the clip
    // Window sums from prefix sums: linear in frames whatever the window (a 1e-6 s frame time
    // makes it a million frames wide).
    std::vector<double> prefix(values.size() + 1, 0.0);
    for (std::size_t f = 0; f < values.size(); ++f) prefix[f + 1] = prefix[f] + values[f];
    for (int f = begin; f < count; ++f) {
        // Symmetric about f, so a straight, steady path stays exactly where it was, ends included.
        const int reach = std::min({half, f - begin, count - 1 - f});
        const int lo = f - reach, hi = f + reach;
        out[static_cast<std::size_t>(f)] = (prefix[static_cast<std::size_t>(hi) + 1] - prefix[static_cast<std::size_t>(lo)]) / (hi - lo + 1);
    }
    return out;
}

std::vector<GroundFrame> groundPath(std::span<const glm::dmat4> globals, int joints, int travelJoint, double scale,
                                    const std::vector<double>& heading, int begin, double frameTime, double seconds) {
    const std::size_t frames = heading.size();
    std::vector<double> xs(frames), zs(frames);
    for (std::size_t f = 0; f < frames; ++f) {
        const glm::dmat4& g = globals[f * static_cast<std::size_t>(joints) + static_cast<std::size_t>(travelJoint)];
        xs[f] = g[3].x * scale;
        zs[f] = g[3].z * scale;
    }
    xs = smoothed(xs, begin, frameTime, seconds);
    zs = smoothed(zs, begin, frameTime, seconds);
    std::vector<GroundFrame> path(frames);
    for (std::size_t f = 0; f < frames; ++f) path[f] = {{xs[f], zs[f]}, heading[f]};
    return path;
}

std::vector<GroundFrame> straightened(const std::vector<GroundFrame>& path, LoopRange loop) {
    // Each step as the walker saw it (in its own frame), replayed without the turn.
    std::vector<GroundFrame> out(path.size());
    const auto first = static_cast<std::size_t>(loop.first);
    const double yaw = path[first].yaw;
    out[first] = path[first];
    for (std::size_t f = first + 1; f < path.size(); ++f)
        out[f] = {out[f - 1].position + rotateGround(rotateGround(path[f].position - path[f - 1].position, -path[f - 1].yaw), yaw), yaw};
    for (std::size_t f = first; f-- > 0;)
        out[f] = {out[f + 1].position - rotateGround(rotateGround(path[f + 1].position - path[f].position, -path[f + 1].yaw), yaw), yaw};
    return out;
}

double arcLength(const std::vector<GroundFrame>& path, int first, int last) {
    double length = 0.0;
    for (int f = first; f < last; ++f)
        length += glm::length(path[static_cast<std::size_t>(f) + 1].position - path[static_cast<std::size_t>(f)].position);
    return length;
}

}  // namespace throng::motion::bake_steps
