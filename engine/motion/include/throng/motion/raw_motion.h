#pragma once
// The parsed, editable form of a BVH file: the skeleton tree and the raw channel values,
// exactly as the file states them (its own units and axes, degrees). Baking turns it into
// the flat, immutable BakedClip (see baked_clip.h), as ozz turns a RawSkeleton into a Skeleton.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "throng/core/math.h"

namespace throng::motion {

/// One BVH channel. The order in a joint's CHANNELS line is the order of its values.
enum class Channel : std::uint8_t { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };

[[nodiscard]] const char* channelName(Channel channel);
[[nodiscard]] inline bool isRotation(Channel c) { return c >= Channel::Xrotation; }
/// Axis index 0, 1, 2 for X, Y, Z.
[[nodiscard]] inline int channelAxis(Channel c) { return static_cast<int>(c) % 3; }

/// How position channels combine with a joint's OFFSET (DESIGN.md §3).
enum class PositionChannels : std::uint8_t {
    Replace,  ///< Channels give the full local translation (Blender; the default).
    Add,      ///< Channels are added to OFFSET (three.js BVHLoader).
};

struct RawJoint {
    std::string name;                ///< As written after ROOT/JOINT.
    int parent = -1;                 ///< Index of the parent joint, -1 for the root.
    glm::dvec3 offset{0.0};          ///< OFFSET, in file units.
    std::vector<Channel> channels;   ///< 0 to 6 channels, no duplicates, file order.
    int firstValue = 0;              ///< Index of this joint's first value within a frame row.
    int sourceLine = 0;              ///< Line of the ROOT/JOINT keyword, for messages.
};

/// An End Site: a leaf with an offset and no channels. Not a joint of the animation,
/// but it tells where bones end (skeleton height, tip spheres).
struct RawEndSite {
    int parent = -1;         ///< Joint it hangs from.
    glm::dvec3 offset{0.0};  ///< In file units.
};

struct RawMotion {
    std::string sourceName;           ///< File path or label used in messages.
    std::vector<RawJoint> joints;     ///< Depth-first order: every parent precedes its children.
    std::vector<RawEndSite> endSites;
    int channelCount = 0;             ///< Values per frame row (sum of all joints' channels).
    int frameCount = 0;               ///< Number of rows; equals the `Frames:` header.
    double frameTime = 0.0;           ///< Seconds per frame, > 0.
    std::vector<double> values;       ///< frameCount × channelCount, row-major.

    [[nodiscard]] std::span<const double> frame(int index) const {
        return {values.data() + static_cast<std::size_t>(index) * channelCount,
                static_cast<std::size_t>(channelCount)};
    }
    [[nodiscard]] int jointCount() const { return static_cast<int>(joints.size()); }
};

}  // namespace throng::motion
