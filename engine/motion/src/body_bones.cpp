#include "throng/motion/body_bones.h"

#include <algorithm>
#include <array>

namespace throng::motion {
namespace {

// Radii at a bone's start and end as fractions of stature, and thickness for soles and palms.
// Approximate adult proportions (limb girths over height, roughly as in anthropometric
// tables: a thigh about a third of the way round of a 1.7 m adult's waist), tuned by eye so
// the bodies read as people at crowd distance; not a measurement of anyone.
struct PartShape {
    float start, end, thickness;
};
constexpr std::array<PartShape, 14> kShapes{{
    {0.058F, 0.056F, 0.75F},  // Hips: pelvis to hip joint, or the lower back (front to back 3/4 of across)
    {0.080F, 0.086F, 0.7F},   // Spine: belly to chest, an oval 30 cm across and 21 cm deep at 1.75 m
    {0.032F, 0.030F, 1.0F},   // Neck
    {0.045F, 0.050F, 1.0F},   // Head: from the head joint (the skull's base) to the crown
    {0.034F, 0.032F, 1.0F},   // Shoulder
    {0.031F, 0.026F, 1.0F},   // UpperArm
    {0.025F, 0.019F, 1.0F},   // Forearm
    {0.021F, 0.017F, 0.55F},  // Hand
    {0.008F, 0.007F, 1.0F},   // Finger
    {0.054F, 0.036F, 1.0F},   // Thigh
    {0.035F, 0.023F, 1.0F},   // Shin
    {0.027F, 0.025F, 0.6F},   // Foot: ankle to the ball of the foot
    {0.021F, 0.016F, 0.6F},   // Toe
    {0.0F, 0.0F, 1.0F},       // Other: from the joint spheres
}};

using Parts = std::vector<BodyPart>;  // per joint: the part of the bone that ends there

// Walks up from `joint` to (not including) `stop`, calling visit on each joint.
template <typename Visit>
void upTo(const RawMotion& motion, int joint, int stop, Visit&& visit) {
    for (int j = joint; j >= 0 && j != stop; j = motion.joints[static_cast<std::size_t>(j)].parent) visit(j);
}

double offsetLength(const RawMotion& motion, int joint) { return glm::length(motion.joints[static_cast<std::size_t>(joint)].offset); }

// Each joint of a leg names the bone that ends there: below the ankle the foot (the first
// bone) and toes, then the shin, the thigh, and from the hip up to the pelvis the hips.
void markLegs(const RawMotion& motion, const Anatomy& anatomy, Parts& parts) {
    for (const LegChain& leg : anatomy.legs) {
        BodyPart between = BodyPart::Toe;  // of joints between the landmarks, walking up
        upTo(motion, leg.toe >= 0 ? leg.toe : leg.ankle, anatomy.pelvis, [&](int j) {
            if (j == leg.ankle) between = BodyPart::Shin;
            if (j == leg.knee) between = BodyPart::Thigh;
            if (j == leg.hip) between = BodyPart::Hips;
            const bool belowAnkle = between == BodyPart::Toe;
            parts[static_cast<std::size_t>(j)] =
                belowAnkle && motion.joints[static_cast<std::size_t>(j)].parent == leg.ankle ? BodyPart::Foot : between;
        });
    }
}

// An arm: the chain from where it leaves the spine down its largest branch. Its first bone
// (spine to the chain) is the shoulder's. The wrist is where the chain first branches (the
// thumb leaves the fingers), and the two bones with length before it are the forearm and the
// upper arm. A chain that never branches (a hand with one End Site): of the next four bones
// the upper arm and forearm are the consecutive pair that is longest and, as elbows rest, runs
// on in one direction (a clavicle turns off at the shoulder). Past the forearm the hand,
// then fingers (side branches, a thumb, are fingers too).
struct ArmSplit {
    std::size_t upper = 1, fore = 2, hand = 3;  // chain indices of the bones ending there
};

ArmSplit splitArm(const RawMotion& motion, const std::vector<std::vector<int>>& children, const std::vector<int>& chain) {
    const auto offset = [&](std::size_t k) { return motion.joints[static_cast<std::size_t>(chain[k])].offset; };
    const auto hasLength = [&](std::size_t k) { return glm::length(offset(k)) > 1e-9; };
    ArmSplit split;
    std::vector<std::size_t> long_;  // bones with length, up to the wrist
    for (std::size_t k = 1; k < chain.size(); ++k) {
        if (hasLength(k)) long_.push_back(k);
        if (children[static_cast<std::size_t>(chain[k])].size() >= 2 && long_.size() >= 2) {
            split.upper = long_[long_.size() - 2];
            split.fore = long_.back();
            split.hand = split.fore + 1;
            while (split.hand < chain.size() && !hasLength(split.hand)) ++split.hand;
            return split;
        }
    }
    double best = -1.0;
    for (std::size_t k = 1; k + 1 < std::min<std::size_t>(chain.size(), 5); ++k) {
        const double a = glm::length(offset(k)), b = glm::length(offset(k + 1));
        const bool straight = a > 0.0 && b > 0.0 && glm::dot(offset(k), offset(k + 1)) > 0.7 * a * b;
        const double score = (a + b) * (straight ? 1.0 : 0.5);
        if (score > best) best = score, split = {k, k + 1, k + 2};
    }
    return split;
}

void markArm(const RawMotion& motion, const std::vector<std::vector<int>>& children, int first, Parts& parts) {
    std::vector<int> chain;
    for (int j = first; j >= 0;) {
        chain.push_back(j);
        const auto& next = children[static_cast<std::size_t>(j)];
        j = next.empty() ? -1 : *std::max_element(next.begin(), next.end(), [&](int a, int b) { return offsetLength(motion, a) < offsetLength(motion, b); });
    }
    const ArmSplit split = splitArm(motion, children, chain);
    const auto partAt = [&](std::size_t k) {
        if (chain.size() < 2) return BodyPart::UpperArm;
        if (k < split.upper) return BodyPart::Shoulder;
        if (k == split.upper) return BodyPart::UpperArm;
        if (k <= split.fore) return BodyPart::Forearm;
        return k <= split.hand ? BodyPart::Hand : BodyPart::Finger;
    };
    std::vector<int> stack;
    for (std::size_t k = 0; k < chain.size(); ++k) {
        parts[static_cast<std::size_t>(chain[k])] = partAt(k);
        for (int c : children[static_cast<std::size_t>(chain[k])])
            if (k + 1 >= chain.size() || c != chain[k + 1]) stack.push_back(c);
    }
    while (!stack.empty()) {  // side branches: fingers
        const int j = stack.back();
        stack.pop_back();
        parts[static_cast<std::size_t>(j)] = BodyPart::Finger;
        for (int c : children[static_cast<std::size_t>(j)]) stack.push_back(c);
    }
}

void markTrunkAndArms(const RawMotion& motion, const Anatomy& anatomy, const std::vector<std::vector<int>>& children, Parts& parts) {
    std::vector<char> axial(parts.size(), 0);
    upTo(motion, anatomy.head, anatomy.pelvis, [&](int j) { axial[static_cast<std::size_t>(j)] = 1; });
    // Above the last joint the arms leave from, the spine is the neck.
    int armsFrom = -1;
    upTo(motion, anatomy.head, anatomy.pelvis, [&](int j) {
        for (int c : children[static_cast<std::size_t>(j)])
            if (!axial[static_cast<std::size_t>(c)] && armsFrom < 0) armsFrom = j;
    });
    bool aboveArms = armsFrom >= 0;
    upTo(motion, anatomy.head, anatomy.pelvis, [&](int j) {
        if (j == armsFrom) aboveArms = false;
        parts[static_cast<std::size_t>(j)] = aboveArms ? BodyPart::Neck : BodyPart::Spine;
        if (aboveArms) return;  // a jaw or eyes off the neck and head stay Other
        for (int c : children[static_cast<std::size_t>(j)])
            if (!axial[static_cast<std::size_t>(c)]) markArm(motion, children, c, parts);
    });
}

}  // namespace

std::string_view bodyPartName(BodyPart part) {
    constexpr std::array<std::string_view, 14> names{"hips", "spine", "neck", "head", "shoulder", "upper arm", "forearm",
                                                     "hand", "finger", "thigh", "shin", "foot", "toe", "other"};
    return names[static_cast<std::size_t>(part)];
}

std::vector<BodyBone> findBodyBones(const RawMotion& motion, const Anatomy& anatomy, double metresPerUnit, double stature,
                                    const std::vector<float>& jointRadius) {
    const auto joints = static_cast<std::size_t>(motion.jointCount());
    std::vector<std::vector<int>> children(joints);
    for (std::size_t j = 0; j < joints; ++j)
        if (motion.joints[j].parent >= 0) children[static_cast<std::size_t>(motion.joints[j].parent)].push_back(static_cast<int>(j));
    Parts parts(joints, BodyPart::Other);
    if (anatomy.biped()) {
        markLegs(motion, anatomy, parts);
        if (anatomy.head >= 0) markTrunkAndArms(motion, anatomy, children, parts);
    }
    const auto height = static_cast<float>(stature);
    const auto sized = [&](BodyBone bone, int sphereJoint) {
        const PartShape& shape = kShapes[static_cast<std::size_t>(bone.part)];
        const float fallback = sphereJoint >= 0 && static_cast<std::size_t>(sphereJoint) < jointRadius.size() ? jointRadius[static_cast<std::size_t>(sphereJoint)] : 0.02F * height;
        bone.radiusStart = bone.part == BodyPart::Other ? fallback : shape.start * height;
        bone.radiusEnd = bone.part == BodyPart::Other ? fallback : shape.end * height;
        bone.thickness = shape.thickness;
        return bone;
    };
    std::vector<BodyBone> bones;
    for (std::size_t j = 0; j < joints; ++j) {
        const int parent = motion.joints[j].parent;
        if (parent < 0 || offsetLength(motion, static_cast<int>(j)) * metresPerUnit < 1e-4) continue;
        bones.push_back(sized({.joint = parent, .child = static_cast<int>(j), .part = parts[j]}, static_cast<int>(j)));
    }
    for (const RawEndSite& site : motion.endSites) {
        if (site.parent < 0 || glm::length(site.offset) * metresPerUnit < 1e-4) continue;
        // The bone past a joint continues what ends there: past the ankle the foot, past the
        // foot the toes, past the forearm the hand, past the hand a finger.
        const BodyPart part = parts[static_cast<std::size_t>(site.parent)];
        const bool ankle = site.parent == anatomy.legs[0].ankle || site.parent == anatomy.legs[1].ankle;
        const BodyPart tipPart = site.parent == anatomy.head ? BodyPart::Head
                               : ankle                       ? BodyPart::Foot
                               : part == BodyPart::Foot      ? BodyPart::Toe
                               : part == BodyPart::Forearm   ? BodyPart::Hand
                               : part == BodyPart::Hand      ? BodyPart::Finger
                                                             : part;
        bones.push_back(sized({.joint = site.parent, .child = -1, .tip = glm::vec3(site.offset * metresPerUnit), .part = tipPart}, site.parent));
    }
    if (anatomy.biped() && anatomy.head >= 0 && anatomy.headEndSite < 0) {
        // No head top in the file: a head a tenth of stature tall, along the neck.
        const glm::dvec3 neck = motion.joints[static_cast<std::size_t>(anatomy.head)].offset;
        const double length = glm::length(neck);
        const glm::vec3 up = length > 1e-9 ? glm::vec3(neck / length) : glm::vec3(0.0F, 1.0F, 0.0F);
        bones.push_back(sized({.joint = anatomy.head, .child = -1, .tip = up * (0.1F * height), .part = BodyPart::Head}, anatomy.head));
    }
    // The head's End Site is the crown: the capsule's far end sphere stops there instead of
    // reaching a radius past it.
    for (BodyBone& bone : bones) {
        const float length = glm::length(bone.tip);
        if (bone.part == BodyPart::Head && bone.child < 0 && length > 0.0F) bone.tip *= std::max(0.5F, 1.0F - bone.radiusEnd / length);
    }
    return bones;
}

}  // namespace throng::motion
