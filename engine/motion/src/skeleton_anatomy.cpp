#include "throng/motion/skeleton_anatomy.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "throng/motion/forward_kinematics.h"

namespace throng::motion {
namespace {

// The tree with each joint's bone (its translation from its parent) as the first frame poses
// it: a joint with position channels may carry its bone in them (DESIGN.md §3, replace).
struct Tree {
    std::vector<std::vector<int>> children;
    std::vector<double> bone;     // length of the bone that ends at each joint
    std::vector<int> size;        // joints in each subtree
    std::vector<double> reach;    // total bone length in each subtree, End Sites included
    std::vector<int> depth;       // longest chain below each joint, in joints
};

Tree buildTree(const RawMotion& motion) {
    const auto joints = static_cast<std::size_t>(motion.jointCount());
    Tree tree{std::vector<std::vector<int>>(joints), std::vector<double>(joints, 0.0), std::vector<int>(joints, 1),
              std::vector<double>(joints, 0.0), std::vector<int>(joints, 1)};
    for (std::size_t j = 0; j < joints; ++j) {
        const RawJoint& joint = motion.joints[j];
        const glm::dvec3 translation =
            motion.frameCount > 0 ? glm::dvec3(localTransform(joint, motion.frame(0), PositionChannels::Replace)[3]) : joint.offset;
        tree.bone[j] = joint.parent < 0 ? 0.0 : glm::length(translation);
        if (joint.parent >= 0) tree.children[static_cast<std::size_t>(joint.parent)].push_back(static_cast<int>(j));
    }
    for (const RawEndSite& site : motion.endSites) tree.reach[static_cast<std::size_t>(site.parent)] += glm::length(site.offset);
    // Depth-first order: children follow parents, so a backward sweep sees children first.
    for (std::size_t j = joints; j-- > 0;) {
        tree.reach[j] += tree.bone[j];
        const int parent = motion.joints[j].parent;
        if (parent < 0) continue;
        const auto p = static_cast<std::size_t>(parent);
        tree.size[p] += tree.size[j];
        tree.reach[p] += tree.reach[j];
        tree.depth[p] = std::max(tree.depth[p], tree.depth[j] + 1);
    }
    return tree;
}

// Two branches are a left/right pair when they have the same shape and, within 10%, the same
// total length: a real capture's limbs differ by a few percent at most.
bool mirrorPair(const Tree& tree, int a, int b) {
    const auto ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
    if (tree.size[ia] != tree.size[ib] || tree.depth[ia] != tree.depth[ib]) return false;
    const double longer = std::max(tree.reach[ia], tree.reach[ib]);
    return longer > 0 && std::abs(tree.reach[ia] - tree.reach[ib]) <= 0.1 * longer;
}

// The first mirror pair among `joint`'s children, if any.
std::optional<std::pair<int, int>> findPair(const Tree& tree, int joint) {
    const auto& kids = tree.children[static_cast<std::size_t>(joint)];
    for (std::size_t a = 0; a < kids.size(); ++a)
        for (std::size_t b = a + 1; b < kids.size(); ++b)
            if (mirrorPair(tree, kids[a], kids[b])) return std::pair{kids[a], kids[b]};
    return std::nullopt;
}

// The child with the largest subtree other than `skipA` and `skipB`, or -1.
int largestOtherChild(const Tree& tree, int joint, int skipA, int skipB) {
    int best = -1;
    for (int c : tree.children[static_cast<std::size_t>(joint)])
        if (c != skipA && c != skipB && (best < 0 || tree.size[static_cast<std::size_t>(c)] > tree.size[static_cast<std::size_t>(best)]))
            best = c;
    return best;
}

// A leg from its first joint down: the two longest consecutive bones are the thigh and the
// shin, which names the hip, knee and ankle whatever extra links an exporter added.
LegChain legFrom(const RawMotion& motion, const Tree& tree, int first) {
    std::vector<int> chain{first};
    while (!tree.children[static_cast<std::size_t>(chain.back())].empty())
        chain.push_back(largestOtherChild(tree, chain.back(), -1, -1));
    LegChain leg;
    double best = 0;
    for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
        const double both = tree.bone[static_cast<std::size_t>(chain[i])] + tree.bone[static_cast<std::size_t>(chain[i + 1])];
        if (both > best) {
            best = both;
            leg.hip = chain[i - 1];
            leg.knee = chain[i];
            leg.ankle = chain[i + 1];
            leg.toe = i + 2 < chain.size() ? chain[i + 2] : -1;
        }
    }
    if (!leg.complete()) return {};
    leg.soles.emplace_back(leg.ankle, -1);
    for (std::size_t i = 0; i < chain.size(); ++i)
        if (chain[i] == leg.ankle)
            for (std::size_t k = i + 1; k < chain.size(); ++k) leg.soles.emplace_back(chain[k], -1);
    for (std::size_t s = 0; s < motion.endSites.size(); ++s)
        for (const auto& [joint, site] : std::vector(leg.soles))
            if (site < 0 && motion.endSites[s].parent == joint) leg.soles.emplace_back(joint, static_cast<int>(s));
    return leg;
}

void collectSubtree(const Tree& tree, int joint, std::vector<int>& out) {
    out.push_back(joint);
    for (int c : tree.children[static_cast<std::size_t>(joint)]) collectSubtree(tree, c, out);
}

}  // namespace

Anatomy findAnatomy(const RawMotion& motion) {
    Anatomy anatomy;
    if (motion.jointCount() < 4) return anatomy;
    const Tree tree = buildTree(motion);
    for (int j = 0; j < motion.jointCount() && anatomy.pelvis < 0; ++j) {
        const auto pair = findPair(tree, j);
        const int spine = pair ? largestOtherChild(tree, j, pair->first, pair->second) : -1;
        if (spine < 0) continue;
        const LegChain a = legFrom(motion, tree, pair->first), b = legFrom(motion, tree, pair->second);
        if (!a.complete() || !b.complete()) continue;
        anatomy.pelvis = j;
        anatomy.legs = {a, b};
        // The axial chain: past the arms' branching, on into the largest remaining branch.
        int at = spine;
        for (;;) {
            const auto arms = findPair(tree, at);
            const int next = largestOtherChild(tree, at, arms ? arms->first : -1, arms ? arms->second : -1);
            if (next < 0) break;
            at = next;
        }
        anatomy.head = at;
        collectSubtree(tree, spine, anatomy.spine);
    }
    if (anatomy.head >= 0)
        for (std::size_t s = 0; s < motion.endSites.size(); ++s)
            if (motion.endSites[s].parent == anatomy.head) anatomy.headEndSite = static_cast<int>(s);
    return anatomy;
}

}  // namespace throng::motion
