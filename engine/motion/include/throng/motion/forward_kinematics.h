#pragma once
// Forward kinematics on raw BVH data: local transforms from channel values, and the
// local-to-global job. Everything here is double precision in the file's own units.

#include <span>
#include <vector>

#include "throng/motion/raw_motion.h"

namespace throng::motion {

/// Local transform of `joint` for one frame row: T(translation) · R1 · R2 · R3, where the
/// rotations are the joint's rotation channels in the order the file lists them (so
/// "Zrotation Xrotation Yrotation" gives Rz · Rx · Ry), acting on column vectors.
/// The translation is OFFSET, with position channels replacing or added per `mode`.
[[nodiscard]] glm::dmat4 localTransform(const RawJoint& joint, std::span<const double> row, PositionChannels mode);

/// Composes local transforms into global ones: global[i] = global[parent[i]] · local[i].
/// Follows ozz's job pattern: spans in, spans out, no allocation, and run() validates first.
struct LocalToGlobalJob {
    std::span<const int> parents;          ///< Depth-first: parents[i] < i, -1 for a root.
    std::span<const glm::dmat4> locals;    ///< One per joint.
    std::span<glm::dmat4> globals;         ///< Output, one per joint; may not alias locals.
    const glm::dmat4* rootTransform = nullptr;  ///< Optional transform applied above the roots.

    /// True when sizes match and every parent index precedes its child.
    [[nodiscard]] bool validate() const;
    /// Validates, then computes every global. Returns false (writing nothing) if invalid.
    bool run() const;
};

/// Global transforms of every joint at `frame`, file units. Convenience over the job; throws
/// ThrongException (BadInput) for parents that are not in depth-first order.
[[nodiscard]] std::vector<glm::dmat4> globalTransforms(const RawMotion& motion, int frame, PositionChannels mode);

/// Parent indices of every joint, as the job wants them.
[[nodiscard]] std::vector<int> parentIndices(const RawMotion& motion);

}  // namespace throng::motion
