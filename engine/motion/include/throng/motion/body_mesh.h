#pragma once
// A skinned body for any BVH skeleton (--body skin), generated from its bones: the smooth union
// of the body's tapered capsules (body_bones.h) as a signed distance field, polygonised once
// by surface nets into a closed, watertight mesh, with up to four joint influences per vertex
// weighted by how close the vertex lies to each bone's surface. The mesh is modelled in a
// bind pose of the skeleton's own: its rest offsets with the arms lowered 40 degrees from the
// horizontal, clear of the trunk, whatever pose the file's rest has them in.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "throng/core/math.h"
#include "throng/motion/baked_clip.h"

namespace throng::motion {

/// One vertex of a body mesh, in the bind pose (metres, at the clip's own scale).
struct SkinVertex {
    glm::vec3 position{0.0F};
    glm::vec3 normal{0.0F, 1.0F, 0.0F};  ///< Unit, outward.
    /// From the nearest point on its main bone's axis to the vertex: a slimmer or broader build
    /// scales the body along it.
    glm::vec3 girth{0.0F};
    std::uint32_t mainBone = 0;                  ///< The body bone (BakedClip::body) it lies on: its clothing.
    std::array<std::uint16_t, 4> joints{};       ///< Influences, joint indices.
    std::array<std::uint8_t, 4> weights{};       ///< Their weights out of 255, summing to 255, largest first.
};

struct BodyMesh {
    std::vector<SkinVertex> vertices;
    std::vector<std::uint32_t> indices;  ///< Triangles, counter-clockwise seen from outside.
    /// Per joint, its global transform in the bind pose: a vertex weighted to joint j moves by
    /// pose(j) * inverse(bind[j]).
    std::vector<JointPose> bind;
    float cellSize = 0.0F;  ///< The polygonising grid's spacing, metres.
};

/// How a mesh is made; the defaults suit a body at crowd distance and close up.
struct BodyMeshOptions {
    /// Grid spacing as a fraction of stature (1/72: 2.4 cm for a 1.75 m adult).
    float cellFraction = 1.0F / 72.0F;
};

/// The most body bones a skinned body is made from. A person's skeleton has a few dozen (the
/// CMU captures' 31 joints give 27; hands with fingers add 30 more). Every vertex weighs every
/// bone while the mesh is made, so a skeleton of thousands (a hostile or a machine's file)
/// would take minutes: such a skeleton gets no mesh (see skinnable) and is drawn with bones.
inline constexpr std::size_t kMostSkinnedBones = 256;

/// Whether makeBodyMesh makes a mesh for `clip`: its body has bones, at most kMostSkinnedBones,
/// and its joints fit the vertices' 16-bit indices.
[[nodiscard]] bool skinnable(const BakedClip& clip);

/// The skinned body of `clip`'s skeleton (`clip.body` must be its bones). Empty (no vertices)
/// when the clip is not skinnable. Deterministic: the same clip gives the same mesh.
[[nodiscard]] BodyMesh makeBodyMesh(const BakedClip& clip, const BodyMeshOptions& options = {});

/// The bind pose makeBodyMesh models in: per joint, a global rotation and position (metres).
[[nodiscard]] std::vector<JointPose> bodyBindPose(const BakedClip& clip);

/// Where `bone` starts and ends in a pose given per joint (global rotation and position).
[[nodiscard]] std::array<glm::vec3, 2> boneEnds(const BodyBone& bone, std::span<const JointPose> pose);

}  // namespace throng::motion
