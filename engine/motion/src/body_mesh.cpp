#include "throng/motion/body_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bake_steps.h"
#include "surface_nets.h"

namespace throng::motion {
namespace {

constexpr float kFar = 1e9F;  // the field where no capsule is near: outside
// The bind pose lowers each arm this far below the horizontal: clear of the trunk, and close
// to how arms hang in a walk, so the shoulder deforms least there.
constexpr float kArmDrop = 0.698F;  // 40 degrees
// Where two capsules meet, their union is rounded over this width (fraction of stature).
constexpr float kBlendFraction = 0.014F;
// A vertex is shared between the bones whose surfaces lie within this distance of its
// nearest bone's surface (fraction of stature), weighted more the closer.
constexpr float kWeightFraction = 0.012F;
// The grid is coarsened past this many points (a giant or absurdly spread skeleton).
constexpr double kMostGridPoints = 4.0e6;

// The shortest rotation taking unit vector `from` to unit vector `to`.
glm::quat shortestArc(glm::vec3 from, glm::vec3 to) {
    const float cosine = glm::dot(from, to);
    if (cosine < -0.9999F) {  // opposite: half a turn about any axis across them
        const glm::vec3 axis = glm::normalize(glm::cross(from, std::abs(from.x) < 0.9F ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
        return glm::quat(0.0F, axis.x, axis.y, axis.z);
    }
    const glm::vec3 axis = glm::cross(from, to);
    return glm::normalize(glm::quat(1.0F + cosine, axis.x, axis.y, axis.z));
}

// One body bone's tapered capsule (the convex hull of its two end spheres), possibly
// flattened across its axis.
struct Capsule {
    glm::vec3 start{0.0F}, axis{0.0F, 1.0F, 0.0F};
    float length = 0.0F, radiusStart = 0.0F, radiusEnd = 0.0F;
    float sine = 0.0F, cosine = 1.0F;  // of the slope of its side
    bool nested = false;               // one end sphere holds the other
    glm::vec3 flat{0.0F};              // unit, across the axis: the direction it is thin in
    float thickness = 1.0F;

    Capsule(glm::vec3 a, glm::vec3 b, float ra, float rb, glm::vec3 flatAcross, float thin)
        : start(a), radiusStart(ra), radiusEnd(rb), thickness(thin) {
        length = glm::distance(a, b);
        if (length > 1e-6F) axis = (b - a) / length;
        nested = std::abs(ra - rb) >= length;
        if (!nested) {
            sine = (ra - rb) / length;
            cosine = std::sqrt(std::max(0.0F, 1.0F - sine * sine));
        }
        const glm::vec3 across = flatAcross - glm::dot(flatAcross, axis) * axis;
        if (thin < 1.0F && glm::length(across) > 1e-3F) flat = glm::normalize(across);
        else thickness = 1.0F;
    }

    // Signed distance (a lower bound outside when flattened: space is stretched by 1/thickness
    // across, and scaled back).
    [[nodiscard]] float distance(glm::vec3 p) const {
        glm::vec3 q = p - start;
        if (thickness < 1.0F) q += (1.0F / thickness - 1.0F) * glm::dot(q, flat) * flat;
        const float y = glm::dot(q, axis);
        const float x = glm::length(q - y * axis);
        float d = 0.0F;
        if (nested) {
            d = std::min(std::hypot(x, y) - radiusStart, std::hypot(x, y - length) - radiusEnd);
        } else {
            const float along = -x * sine + y * cosine;  // along the side, from the start sphere's tangent point
            if (along < 0.0F) d = std::hypot(x, y) - radiusStart;
            else if (along > length * cosine) d = std::hypot(x, y - length) - radiusEnd;
            else d = x * cosine + y * sine - radiusStart;
        }
        return d * thickness;
    }
    /// The radius where the axis passes nearest `p`.
    [[nodiscard]] float radiusNear(glm::vec3 p) const {
        return length > 0.0F ? glm::mix(radiusStart, radiusEnd, glm::distance(start, nearestOnAxis(p)) / length) : radiusStart;
    }
    [[nodiscard]] glm::vec3 nearestOnAxis(glm::vec3 p) const { return start + std::clamp(glm::dot(p - start, axis), 0.0F, length) * axis; }
};

// Polynomial smooth minimum: min(a, b), rounded where they are within k of each other.
float smoothMin(float a, float b, float k) {
    const float h = std::max(k - std::abs(a - b), 0.0F) / k;
    return std::min(a, b) - h * h * k * 0.25F;
}

struct BodyField {
    std::vector<Capsule> capsules;
    float blend = 0.0F;

    [[nodiscard]] float at(glm::vec3 p) const {
        float value = kFar;
        for (const Capsule& capsule : capsules) value = smoothMin(value, capsule.distance(p), blend);
        return value;
    }
    [[nodiscard]] glm::vec3 gradient(glm::vec3 p, float step) const {
        const glm::vec3 dx(step, 0, 0), dy(0, step, 0), dz(0, 0, step);
        return glm::vec3(at(p + dx) - at(p - dx), at(p + dy) - at(p - dy), at(p + dz) - at(p - dz)) / (2.0F * step);
    }
};

// Samples the field on a grid around the capsules, each capsule only near itself.
detail::DistanceGrid sampleField(const BodyField& field, float cell) {
    glm::vec3 low(kFar), high(-kFar);
    for (const Capsule& c : field.capsules) {
        const float reach = std::max(c.radiusStart, c.radiusEnd);
        low = glm::min(low, glm::min(c.start, c.start + c.axis * c.length) - reach);
        high = glm::max(high, glm::max(c.start, c.start + c.axis * c.length) + reach);
    }
    const float margin = field.blend + 3.0F * cell;
    low -= margin;
    high += margin;
    const glm::vec3 extent = high - low;
    cell = std::max(cell, static_cast<float>(std::cbrt(static_cast<double>(extent.x) * extent.y * extent.z / kMostGridPoints)));
    detail::DistanceGrid grid;
    grid.origin = low;
    grid.cell = cell;
    grid.size = glm::ivec3(glm::ceil(extent / cell)) + 1;
    grid.values.assign(static_cast<std::size_t>(grid.size.x) * static_cast<std::size_t>(grid.size.y) * static_cast<std::size_t>(grid.size.z), kFar);
    for (const Capsule& c : field.capsules) {
        const float reach = std::max(c.radiusStart, c.radiusEnd) + field.blend + 2.0F * cell;
        const glm::vec3 end = c.start + c.axis * c.length;
        const glm::ivec3 from = glm::max(glm::ivec3(glm::floor((glm::min(c.start, end) - reach - low) / cell)), glm::ivec3(0));
        const glm::ivec3 to = glm::min(glm::ivec3(glm::ceil((glm::max(c.start, end) + reach - low) / cell)), grid.size - 1);
        for (int k = from.z; k <= to.z; ++k)
            for (int j = from.y; j <= to.y; ++j)
                for (int i = from.x; i <= to.x; ++i) {
                    float& value = grid.values[grid.index(i, j, k)];
                    value = smoothMin(value, c.distance(low + cell * glm::vec3(i, j, k)), field.blend);
                }
    }
    return grid;
}

// The clip's body bones as capsules in the bind pose; soles thin along the up axis, palms
// across the body, the trunk front to back.
std::vector<Capsule> bindCapsules(const BakedClip& clip, const std::vector<JointPose>& bind) {
    glm::vec3 sideways(1.0F, 0.0F, 0.0F);
    if (clip.anatomy.biped()) {
        glm::vec3 hips = bind[static_cast<std::size_t>(clip.anatomy.legs[0].hip)].translation - bind[static_cast<std::size_t>(clip.anatomy.legs[1].hip)].translation;
        hips.y = 0.0F;
        if (glm::length(hips) > 1e-4F) sideways = glm::normalize(hips);
    }
    const glm::vec3 forward = glm::cross(sideways, glm::vec3(0.0F, 1.0F, 0.0F));
    std::vector<Capsule> capsules;
    for (const BodyBone& bone : clip.body) {
        const auto [a, b] = boneEnds(bone, bind);
        const bool sole = bone.part == BodyPart::Foot || bone.part == BodyPart::Toe;
        const bool trunk = bone.part == BodyPart::Spine || bone.part == BodyPart::Hips;
        capsules.emplace_back(a, b, bone.radiusStart, bone.radiusEnd, sole ? glm::vec3(0.0F, 1.0F, 0.0F) : trunk ? forward : sideways, bone.thickness);
    }
    return capsules;
}

// Where bones `a` and `b` turn against each other: the joint between them when one's joint is
// the other's parent (their relative motion is a rotation about it); nullopt when they move
// as one (the same joint) or are not neighbours (a vertex is not shared between them).
struct Pivot {
    bool shared = false;  // they may share vertices
    bool rigid = false;   // same joint: no pivot needed
    glm::vec3 at{0.0F};
};
Pivot pivotBetween(const BakedClip& clip, const std::vector<JointPose>& bind, const BodyBone& a, const BodyBone& b) {
    if (a.joint == b.joint) return {.shared = true, .rigid = true};
    if (clip.parents[static_cast<std::size_t>(b.joint)] == a.joint) return {.shared = true, .at = bind[static_cast<std::size_t>(b.joint)].translation};
    if (clip.parents[static_cast<std::size_t>(a.joint)] == b.joint) return {.shared = true, .at = bind[static_cast<std::size_t>(a.joint)].translation};
    return {};
}

// Up to four joints sharing a vertex: its nearest bone's, and those of neighbouring bones
// whose surfaces lie within `width` of it, near the joint the two turn about (further away a
// blend would swing the vertex off both). Sets mainBone and girth too.
void weigh(SkinVertex& vertex, const BakedClip& clip, const std::vector<JointPose>& bind, const std::vector<Capsule>& capsules, float width) {
    std::vector<float> distance(capsules.size());
    std::size_t nearest = 0;
    for (std::size_t b = 0; b < capsules.size(); ++b) {
        distance[b] = capsules[b].distance(vertex.position);
        if (distance[b] < distance[nearest]) nearest = b;
    }
    vertex.mainBone = static_cast<std::uint32_t>(nearest);
    vertex.girth = vertex.position - capsules[nearest].nearestOnAxis(vertex.position);
    const BodyBone& main = clip.body[nearest];
    std::vector<std::pair<float, int>> byJoint;  // (weight, joint), a joint's best bone
    for (std::size_t b = 0; b < capsules.size(); ++b) {
        const Pivot pivot = pivotBetween(clip, bind, main, clip.body[b]);
        if (!pivot.shared) continue;
        float closeness = 1.0F - (distance[b] - distance[nearest]) / width;
        if (!pivot.rigid) {
            // Within the slimmer bone's girth of the pivot, plus the blend's width.
            const float reach = std::min(capsules[nearest].radiusNear(pivot.at), capsules[b].radiusNear(pivot.at));
            closeness *= std::clamp(1.0F - (glm::distance(vertex.position, pivot.at) - reach) / width, 0.0F, 1.0F);
        }
        if (closeness <= 0.0F) continue;
        const int joint = clip.body[b].joint;
        auto same = std::find_if(byJoint.begin(), byJoint.end(), [&](const auto& entry) { return entry.second == joint; });
        if (same == byJoint.end()) byJoint.emplace_back(closeness * closeness, joint);
        else same->first = std::max(same->first, closeness * closeness);
    }
    std::stable_sort(byJoint.begin(), byJoint.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    byJoint.resize(std::min<std::size_t>(byJoint.size(), 4));
    float total = 0.0F;
    for (const auto& entry : byJoint) total += entry.first;
    int given = 0;
    for (std::size_t i = 0; i < byJoint.size(); ++i) {
        vertex.joints[i] = static_cast<std::uint16_t>(byJoint[i].second);
        const int share = static_cast<int>(std::lround(255.0F * byJoint[i].first / total));
        vertex.weights[i] = static_cast<std::uint8_t>(std::clamp(share, 0, 255 - given));
        given += vertex.weights[i];
    }
    vertex.weights[0] = static_cast<std::uint8_t>(vertex.weights[0] + (255 - given));  // rounding's remainder to the largest
}

}  // namespace

std::array<glm::vec3, 2> boneEnds(const BodyBone& bone, std::span<const JointPose> pose) {
    const JointPose& from = pose[static_cast<std::size_t>(bone.joint)];
    const glm::vec3 end = bone.child >= 0 ? pose[static_cast<std::size_t>(bone.child)].translation : from.translation + from.rotation * bone.tip;
    return {from.translation, end};
}

std::vector<JointPose> bodyBindPose(const BakedClip& clip) {
    const auto joints = static_cast<std::size_t>(clip.jointCount());
    std::vector<JointPose> bind(joints);
    if (clip.frameCount <= 0 || clip.poses.size() < joints) return bind;
    // Each joint's offset from its parent, in the parent's frame, as the clip plays it (units,
    // position channels and the foot lock included), laid out with no rotation but the turn
    // that stands the file upright.
    const int reference = std::clamp(clip.loop().first, 0, clip.frameCount - 1);
    const glm::quat upright = glm::quat_cast(glm::mat3(bake_steps::toYUp(clip.upAxis)));
    for (std::size_t j = 0; j < joints; ++j) {
        const JointPose& here = clip.pose(reference, static_cast<int>(j));
        const int parent = clip.parents[j];
        bind[j].rotation = upright;
        if (parent < 0) {
            bind[j].translation = here.translation;
            continue;
        }
        const JointPose& up = clip.pose(reference, parent);
        const glm::vec3 local = glm::inverse(up.rotation) * (here.translation - up.translation);
        bind[j].translation = bind[static_cast<std::size_t>(parent)].translation + upright * local;
    }
    // Lower each upper arm, and everything it carries, to kArmDrop below the horizontal,
    // pointing away from the trunk.
    const glm::vec3 trunk = clip.anatomy.pelvis >= 0 ? bind[static_cast<std::size_t>(clip.anatomy.pelvis)].translation : bind[0].translation;
    for (const BodyBone& bone : clip.body) {
        if (bone.part != BodyPart::UpperArm) continue;
        const std::size_t shoulder = static_cast<std::size_t>(bone.joint);
        const glm::vec3 pivot = bind[shoulder].translation;
        glm::vec3 outward = pivot - trunk;
        outward.y = 0.0F;
        const auto [start, end] = boneEnds(bone, bind);
        if (glm::length(outward) < 1e-4F || glm::distance(start, end) < 1e-5F) continue;
        const glm::vec3 target = std::cos(kArmDrop) * glm::normalize(outward) - std::sin(kArmDrop) * glm::vec3(0.0F, 1.0F, 0.0F);
        const glm::quat turn = shortestArc(glm::normalize(end - start), target);
        std::vector<char> carried(joints, 0);
        carried[shoulder] = 1;
        for (std::size_t j = shoulder + 1; j < joints; ++j)
            carried[j] = clip.parents[j] >= 0 && carried[static_cast<std::size_t>(clip.parents[j])];
        for (std::size_t j = shoulder; j < joints; ++j) {
            if (!carried[j]) continue;
            bind[j].rotation = glm::normalize(turn * bind[j].rotation);
            bind[j].translation = pivot + turn * (bind[j].translation - pivot);
        }
    }
    return bind;
}

bool skinnable(const BakedClip& clip) {
    return !clip.body.empty() && clip.body.size() <= kMostSkinnedBones && clip.jointCount() <= std::numeric_limits<std::uint16_t>::max();
}

BodyMesh makeBodyMesh(const BakedClip& clip, const BodyMeshOptions& options) {
    BodyMesh mesh;
    mesh.bind = bodyBindPose(clip);
    if (!skinnable(clip)) return mesh;
    const auto stature = static_cast<float>(std::max(clip.stature, 1e-3));
    BodyField field{.capsules = bindCapsules(clip, mesh.bind), .blend = kBlendFraction * stature};
    const detail::DistanceGrid grid = sampleField(field, std::max(options.cellFraction, 1e-3F) * stature);
    mesh.cellSize = grid.cell;
    detail::NetMesh net = detail::surfaceNets(std::move(grid));
    mesh.indices = std::move(net.indices);
    mesh.vertices.resize(net.positions.size());
    const float step = 0.25F * mesh.cellSize;
    for (std::size_t v = 0; v < net.positions.size(); ++v) {
        SkinVertex& vertex = mesh.vertices[v];
        glm::vec3 p = net.positions[v];
        // Onto the surface: a Newton step or two along the field's gradient.
        for (int pass = 0; pass < 2; ++pass) {
            const glm::vec3 g = field.gradient(p, step);
            const float slope = glm::dot(g, g);
            const float value = field.at(p);
            if (slope > 0.25F && std::abs(value) < mesh.cellSize) p -= value * g / slope;
        }
        vertex.position = p;
        const glm::vec3 g = field.gradient(p, step);
        weigh(vertex, clip, mesh.bind, field.capsules, kWeightFraction * stature);
        const glm::vec3 fallback = glm::length(vertex.girth) > 1e-6F ? vertex.girth : glm::vec3(0.0F, 1.0F, 0.0F);
        vertex.normal = glm::normalize(glm::length(g) > 1e-6F ? g : fallback);
    }
    return mesh;
}

}  // namespace throng::motion
