#pragma once
// A body for any BVH skeleton (--body bones): every bone, joint to child joint or to End Site,
// becomes a tapered capsule whose radii come from what part of a body it is, found from the
// skeleton's structure (skeleton_anatomy.h), not from joint names: legs, the spine to the
// head, and the arms that branch off it, each bone named by its place along its chain.

#include <cstdint>
#include <string_view>
#include <vector>

#include "throng/core/math.h"
#include "throng/motion/raw_motion.h"
#include "throng/motion/skeleton_anatomy.h"

namespace throng::motion {

/// What a bone is. Radii and clothing are keyed by it.
enum class BodyPart : std::uint8_t {
    Hips, Spine, Neck, Head, Shoulder, UpperArm, Forearm, Hand, Finger, Thigh, Shin, Foot, Toe, Other,
};

[[nodiscard]] std::string_view bodyPartName(BodyPart part);

/// One capsule of the body. Lengths in metres, at the clip's own scale.
struct BodyBone {
    int joint = -1;          ///< Where it starts.
    int child = -1;          ///< The joint where it ends, or -1: it ends at `tip`.
    glm::vec3 tip{0.0F};     ///< With child -1: the end, in `joint`'s frame (an End Site, or the head's top).
    BodyPart part = BodyPart::Other;
    float radiusStart = 0.0F;
    float radiusEnd = 0.0F;
    /// Soles, palms and the trunk are flattened: thickness over width (1: round), along the
    /// ground's normal for a foot, across the body for a hand, and front to back for the
    /// hips and spine.
    float thickness = 1.0F;
};

/// The body of `motion`'s skeleton: one bone per joint-to-child and joint-to-End-Site link
/// that has length, sized by its part from `stature` (metres; radii are fractions of it) and
/// `metresPerUnit`. A skeleton that is no biped still gets a body: every bone is Other, sized
/// from `jointRadius` (the joint spheres' radii). A head with no End Site gets one along the neck.
[[nodiscard]] std::vector<BodyBone> findBodyBones(const RawMotion& motion, const Anatomy& anatomy, double metresPerUnit,
                                                  double stature, const std::vector<float>& jointRadius);

}  // namespace throng::motion
