#pragma once
// Which joints of a skeleton play which part of a human body, found from the tree's shape
// and bone lengths rather than from names (exporters name joints every way there is):
//  - the legs are the two mirror-image chains that hang from one joint, the pelvis;
//  - the spine is the pelvis's remaining, largest branch, and it carries the head;
//  - the arms are the mirror pair that branches off the spine.
// Root motion follows the pelvis, the up axis comes from legs versus spine, stature from the
// head's top and the soles, and the foot lock from the legs.

#include <array>
#include <vector>

#include "throng/motion/raw_motion.h"

namespace throng::motion {

/// One leg, from the joint where it leaves the pelvis to the foot. Joint indices, -1 when the
/// skeleton has no such joint.
struct LegChain {
    int hip = -1;    ///< The thigh's upper end (ball joint): the first joint of the chain that rotates the thigh.
    int knee = -1;   ///< The thigh's lower end.
    int ankle = -1;  ///< The shin's lower end.
    int toe = -1;    ///< The foot's last joint below the ankle, if any.
    /// Points that reach the ground: the ankle, the toe and the End Sites below them, as
    /// (joint, End Site index or -1) pairs. The lowest of them is the sole.
    std::vector<std::pair<int, int>> soles;
    [[nodiscard]] bool complete() const { return hip >= 0 && knee >= 0 && ankle >= 0; }
};

struct Anatomy {
    int pelvis = -1;  ///< The joint the legs and the spine hang from; -1 if no biped was recognised.
    int head = -1;    ///< The last joint of the spine's axial chain (not an arm).
    int headEndSite = -1;  ///< The End Site above `head`, if the file has one (the top of the head).
    std::array<LegChain, 2> legs;  ///< Ordered by joint index: legs[0] comes first in the file.
    std::vector<int> spine;        ///< Joints of the pelvis's spine branch (axial chain, arms, head), depth-first.

    [[nodiscard]] bool biped() const { return pelvis >= 0 && legs[0].complete() && legs[1].complete(); }
};

/// Recognises the body parts of `motion`'s skeleton from its structure and OFFSETs. A skeleton
/// that isn't a biped (a prop, a single chain, a quadruped) gives `biped() == false`, and the
/// bake then falls back to the ROOT and the plain vertical extent.
[[nodiscard]] Anatomy findAnatomy(const RawMotion& motion);

}  // namespace throng::motion
