// Foot contacts, the foot lock and stance pivots. A capture's planted feet slide a little, and
// loop closing moves them a little more; locking each contact to one spot on the ground, over
// the loop played as a cycle, means the engine never adds skate.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "bake_steps.h"
#include "throng/motion/forward_kinematics.h"

namespace throng::motion::bake_steps {
namespace {

// The lowest sole point of one leg at frame f, in-place metres.
glm::dvec3 lowestSole(const PoseTable& poses, const RawMotion& motion, const LegChain& leg, double scale, int f) {
    glm::dvec3 lowest(0.0, 1e300, 0.0);
    for (const auto& [joint, site] : leg.soles) {
        glm::dvec3 p = poses.pos(f, joint);
        if (site >= 0) p += poses.rot(f, joint) * (motion.endSites[static_cast<std::size_t>(site)].offset * scale);
        if (p.y < lowest.y) lowest = p;
    }
    return lowest;
}

// The loop as a cycle: step k >= 0 shows frame first + k mod L, placed by the ground frame
// that the track gives there (each wrap adds the loop's displacement).
struct Cycle {
    const std::vector<GroundFrame>& path;
    LoopRange loop;
    GroundFrame displacement;
    Cycle(const std::vector<GroundFrame>& track, LoopRange range)
        : path(track), loop(range),
          displacement(track[static_cast<std::size_t>(range.last)].then(track[static_cast<std::size_t>(range.first)].inverse())) {}
    [[nodiscard]] int frame(int k) const { return loop.first + k % loop.length(); }
    [[nodiscard]] GroundFrame ground(int k) const {
        GroundFrame g = path[static_cast<std::size_t>(frame(k))];
        for (int wraps = k / loop.length(); wraps > 0; --wraps) g = displacement.then(g);
        return g;
    }
};

// Rotates the subtree of `root` (joints root .. root + size - 1, depth-first) by `turn` about `centre`.
void turnSubtree(PoseTable& poses, int f, int root, int size, const glm::dquat& turn, const glm::dvec3& centre) {
    for (int j = root; j < root + size; ++j) {
        poses.rot(f, j) = glm::normalize(turn * poses.rot(f, j));
        poses.pos(f, j) = centre + turn * (poses.pos(f, j) - centre);
    }
}

glm::dquat arcBetween(glm::dvec3 from, glm::dvec3 to) {
    const double a = glm::length(from), b = glm::length(to);
    if (!(a > 0 && b > 0)) return {1, 0, 0, 0};
    const glm::dvec3 u = from / a, v = to / b;
    const double cosine = glm::dot(u, v);
    // Opposite directions: any axis square to them serves; legs never bend that far per step.
    if (cosine < -0.999999) {
        const glm::dvec3 axis = std::abs(u.x) < 0.9 ? glm::cross(u, glm::dvec3(1, 0, 0)) : glm::cross(u, glm::dvec3(0, 1, 0));
        return glm::angleAxis(3.141592653589793, glm::normalize(axis));
    }
    const glm::dvec3 axis = glm::cross(u, v);
    return glm::normalize(glm::dquat(1.0 + cosine, axis.x, axis.y, axis.z));
}

// Two-bone IK: bends hip and knee so the ankle reaches `target`, keeping the knee on the side
// it was and the foot's orientation as it was.
void reach(PoseTable& poses, int f, const LegChain& leg, const std::vector<int>& subtreeSize, glm::dvec3 target) {
    const glm::dvec3 hip = poses.pos(f, leg.hip), knee = poses.pos(f, leg.knee), ankle = poses.pos(f, leg.ankle);
    const glm::dquat footWas = poses.rot(f, leg.ankle);
    const double thigh = glm::length(knee - hip), shin = glm::length(ankle - knee);
    if (!(thigh > 0 && shin > 0)) return;
    glm::dvec3 toTarget = target - hip;
    const double distance = std::clamp(glm::length(toTarget), std::abs(thigh - shin) + 1e-6, thigh + shin - 1e-6);
    if (!(glm::length(toTarget) > 0)) return;
    const glm::dvec3 u = glm::normalize(toTarget);
    glm::dvec3 side = (knee - hip) - glm::dot(knee - hip, u) * u;  // where the knee points, square to the leg
    if (!(glm::length(side) > 1e-9)) return;                      // a straight leg along the target: nothing to bend by
    side = glm::normalize(side);
    const double cosHip = std::clamp((thigh * thigh + distance * distance - shin * shin) / (2.0 * thigh * distance), -1.0, 1.0);
    const glm::dvec3 newKnee = hip + thigh * (cosHip * u + std::sqrt(1.0 - cosHip * cosHip) * side);
    turnSubtree(poses, f, leg.hip, subtreeSize[static_cast<std::size_t>(leg.hip)], arcBetween(knee - hip, newKnee - hip), hip);
    const glm::dvec3 newAnkle = hip + distance * u;
    turnSubtree(poses, f, leg.knee, subtreeSize[static_cast<std::size_t>(leg.knee)],
                arcBetween(poses.pos(f, leg.ankle) - newKnee, newAnkle - newKnee), newKnee);
    turnSubtree(poses, f, leg.ankle, subtreeSize[static_cast<std::size_t>(leg.ankle)],
                glm::normalize(footWas * glm::conjugate(poses.rot(f, leg.ankle))), newAnkle);
}

double smoothstep(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

// Per step of the cycle, the world (x, z) the ankle is held to and how firmly (0..1).
struct Hold {
    std::vector<glm::dvec2> target;
    std::vector<double> weight;
};

// Fills gaps of at most `longest` steps between planted steps, around the cycle. A foot can't
// lift and land again in a tenth of a second: such a gap is a noisy frame inside one contact,
// and holding the two halves at their own spots would pop the foot between them.
void closeShortGaps(std::vector<char>& planted, int longest) {
    const int length = static_cast<int>(planted.size());
    const auto at = [&](int k) -> char& { return planted[static_cast<std::size_t>((k % length + length) % length)]; };
    int start = 0;  // a planted step to walk the cycle from
    while (start < length && at(start) == 0) ++start;
    if (start == length) return;
    for (int k = start + 1; k < start + length;) {
        if (at(k) != 0) {
            ++k;
            continue;
        }
        int end = k;
        while (end + 1 < start + length && at(end + 1) == 0) ++end;
        if (end - k + 1 <= longest)
            for (int i = k; i <= end; ++i) at(i) = 1;
        k = end + 1;
    }
}

// Per step of the loop, whether `joint` is planted: near its lowest and slow. Height alone
// would take in the heel's last centimetres before it strikes, and the ankle rolling forward
// as the heel comes up.
std::vector<char> plantedSteps(const PoseTable& poses, const Cycle& cycle, int joint, double frameTime, double stature) {
    const int length = cycle.loop.length();
    const auto world = [&](int k) { return cycle.ground(k).apply({poses.pos(cycle.frame(k), joint).x, poses.pos(cycle.frame(k), joint).z}); };
    std::vector<double> heights(static_cast<std::size_t>(length));
    for (int k = 0; k < length; ++k) heights[static_cast<std::size_t>(k)] = poses.pos(cycle.frame(k), joint).y;
    const double low = percentile(heights, 0.05) + 0.03 * stature;
    std::vector<char> planted(static_cast<std::size_t>(length), 0);
    for (int k = 0; k < length; ++k) {
        // Differences stay inside the capture: the unclosed seam (frame last to first) is a
        // jump of the mismatch, and would split a contact that straddles it in two.
        const double ahead = k + 1 < length ? glm::length(world(k + 1) - world(k)) : 1e300;
        const double behind = k > 0 ? glm::length(world(k) - world(k - 1)) : 1e300;
        const double speed = std::min(ahead, behind) / frameTime;
        planted[static_cast<std::size_t>(k)] = heights[static_cast<std::size_t>(k)] <= low && speed <= 0.2 * stature ? 1 : 0;
    }
    closeShortGaps(planted, std::max(1, clampedFloor(0.1 / frameTime, 0, length / 4)));
    return planted;
}

// From heel-off the toe holds the foot: an ankle contact ends where the ankle has risen `band`
// above its lowest in that contact while the toe is still down. The planted rule alone (near
// the floor and slow) keeps the ankle planted for the heel's first centimetres up, and an ankle
// held there drags the toe the heel pivots on (4 cm a step on a 1.3 m/s walk).
void endAnkleContactsAtHeelOff(std::vector<char>& ankle, const std::vector<char>& toe, const std::vector<double>& heights, double band) {
    const int length = static_cast<int>(ankle.size());
    const auto at = [&](const auto& table, int k) { return table[static_cast<std::size_t>(k % length)]; };
    const auto contacts = cyclicRuns(length, [&](int k) { return at(ankle, k) != 0; });
    if (!contacts || toe.size() != ankle.size()) return;  // an ankle that never lifts has no heel-off
    for (const auto& [first, end] : *contacts) {
        int lowest = first;
        for (int i = first + 1; i <= end; ++i)
            if (at(heights, i) < at(heights, lowest)) lowest = i;
        int heelOff = lowest + 1;
        while (heelOff <= end && !(at(heights, heelOff) > at(heights, lowest) + band && at(toe, heelOff) != 0)) ++heelOff;
        // The whole rest of the contact: a piece left planted after the toe lifts would be held
        // again as a contact of its own, the ankle locked with the toe in the air.
        for (int i = heelOff; i <= end; ++i) ankle[static_cast<std::size_t>(i % length)] = 0;
    }
}

// A foot that never lifts (a dance's pivot foot, a stance) is one contact around the whole
// cycle. It can't stay on one spot if the loop travels, so its spot drifts evenly by the loop's
// displacement: the least slide that still meets itself at the seam.
template <typename World>
Hold wholeCycleHold(const Cycle& cycle, const World& world, double stature) {
    const int length = cycle.loop.length();
    glm::dvec2 mean(0.0);
    for (int k = 0; k < length; ++k) mean += world(k) / static_cast<double>(length);
    const glm::dvec2 drift = cycle.displacement.apply(mean) - mean;
    const auto spot = [&](int k) { return mean + (static_cast<double>(k) / length - 0.5 * (length - 1) / length) * drift; };
    Hold hold{std::vector<glm::dvec2>(static_cast<std::size_t>(length)), std::vector<double>(static_cast<std::size_t>(length), 0.0)};
    double spread = 0.0;
    for (int k = 0; k < length; ++k) spread = std::max(spread, glm::length(world(k) - spot(k)));
    if (spread > 0.15 * stature) return hold;  // it wanders: a shuffle, not a stance
    for (int k = 0; k < length; ++k) {
        hold.target[static_cast<std::size_t>(k)] = spot(k);
        hold.weight[static_cast<std::size_t>(k)] = 1.0;
    }
    return hold;
}

// `anchor` (per step, may be empty) is the hold weight of a point that holds the foot while
// this one is down (the ankle, for the toe): the contact is held where the anchor's hold puts
// it as the holds hand over, so handing over moves nothing.
Hold planHold(const PoseTable& poses, const Cycle& cycle, int joint, const std::vector<char>& planted, double frameTime,
              double stature, std::span<const double> anchor = {}) {
    const int length = cycle.loop.length();
    Hold hold{std::vector<glm::dvec2>(static_cast<std::size_t>(length)), std::vector<double>(static_cast<std::size_t>(length), 0.0)};
    if (planted.empty()) return hold;
    const auto world = [&](int k) { return cycle.ground(k).apply({poses.pos(cycle.frame(k), joint).x, poses.pos(cycle.frame(k), joint).z}); };
    const auto isPlanted = [&](int k) { return planted[static_cast<std::size_t>(k % length)] != 0; };
    const auto contacts = cyclicRuns(length, isPlanted);
    if (!contacts) return wholeCycleHold(cycle, world, stature);
    const int ramp = std::max(2, clampedFloor(0.1 / frameTime, 0, length / 4));
    for (const auto& [k, end] : *contacts) {
        glm::dvec2 mean(0.0);
        for (int i = k; i <= end; ++i) mean += world(i);
        mean /= static_cast<double>(end - k + 1);
        double spread = 0.0;
        for (int i = k; i <= end; ++i) spread = std::max(spread, glm::length(world(i) - mean));
        // Held where the anchor leaves it: before the anchor's hold (a toe that lands first)
        // where its hold begins, after it (heel-off) where its hold ends.
        int firstAnchored = -1, lastAnchored = -1;
        for (int i = k; i <= end && !anchor.empty(); ++i)
            if (anchor[static_cast<std::size_t>(i % length)] >= 1.0) {
                if (firstAnchored < 0) firstAnchored = i;
                lastAnchored = i;
            }
        const auto spot = [&](int i) { return firstAnchored < 0 ? mean : world(i < firstAnchored ? firstAnchored : lastAnchored); };
        // A "contact" whose ankle wanders further than a foot's length is no plant (a shuffle,
        // a slide the capture meant); holding it would drag the body.
        if (spread <= 0.15 * stature)
            for (int i = k - ramp; i <= end + ramp; ++i) {
                const double w = i < k ? smoothstep(static_cast<double>(i - (k - ramp)) / ramp)
                                       : i > end ? smoothstep(static_cast<double>(end + ramp - i) / ramp) : 1.0;
                const auto slot = static_cast<std::size_t>((i % length + length) % length);
                if (w > hold.weight[slot]) {
                    hold.weight[slot] = w;
                    // Step i lies `wraps` loops from its frame's first showing, where the
                    // target is wanted: each wrap is one loop displacement on the world side.
                    const int wraps = i < 0 ? -1 : i / length;
                    GroundFrame toFirstShowing;
                    for (int n = 0; n < wraps; ++n) toFirstShowing = toFirstShowing.then(cycle.displacement.inverse());
                    if (wraps < 0) toFirstShowing = cycle.displacement;
                    hold.target[slot] = toFirstShowing.apply(spot(i));
                }
            }
    }
    return hold;
}

std::vector<int> subtreeSizes(const std::vector<int>& parents) {
    std::vector<int> size(parents.size(), 1);
    for (std::size_t j = parents.size(); j-- > 0;)
        if (parents[j] >= 0) size[static_cast<std::size_t>(parents[j])] += size[j];
    return size;
}

}  // namespace

double floorHeight(const PoseTable& poses, const RawMotion& motion, const Anatomy& anatomy, double scale) {
    std::vector<double> lowest(static_cast<std::size_t>(poses.frames));
    for (int f = 0; f < poses.frames; ++f) {
        double low = 1e300;
        if (anatomy.biped())
            for (const LegChain& leg : anatomy.legs) low = std::min(low, lowestSole(poses, motion, leg, scale, f).y);
        else
            for (int j = 0; j < poses.joints; ++j) low = std::min(low, poses.pos(f, j).y);
        lowest[static_cast<std::size_t>(f)] = low;
    }
    return percentile(std::move(lowest), 0.05);
}

PlantedFeet findPlantedFeet(const PoseTable& poses, const std::vector<GroundFrame>& path, const Anatomy& anatomy, LoopRange loop,
                            double frameTime, double stature) {
    PlantedFeet feet;
    if (!anatomy.biped() || loop.length() < 4) return feet;
    const Cycle cycle(path, loop);
    for (std::size_t l = 0; l < 2; ++l) {
        feet.ankle[l] = plantedSteps(poses, cycle, anatomy.legs[l].ankle, frameTime, stature);
        if (anatomy.legs[l].toe < 0) continue;
        feet.toe[l] = plantedSteps(poses, cycle, anatomy.legs[l].toe, frameTime, stature);
        std::vector<double> heights(static_cast<std::size_t>(loop.length()));
        for (int k = 0; k < loop.length(); ++k) heights[static_cast<std::size_t>(k)] = poses.pos(cycle.frame(k), anatomy.legs[l].ankle).y;
        endAnkleContactsAtHeelOff(feet.ankle[l], feet.toe[l], heights, 0.004 * stature);
    }
    return feet;
}

namespace {

// How a steering turn may use each frame, from the holds' weights on the poses they made. A
// leg is held as firmly as its firmer point (heel or toe). The body turns about the firmer
// leg's ankle, and the engine twists that foot back about the ankle by the turn (FootPlan::hold),
// so the whole foot stays put. With both legs held a turn would slide one of them by the step's
// length, so freedom falls as the second leg's hold rises. With none held the body turns about
// its travel joint.
void planTurning(const PoseTable& poses, const Cycle& cycle, const Anatomy& anatomy, const std::array<Hold, 2>& ankles,
                 const std::array<Hold, 2>& toes, FootPlan& plan) {
    for (int k = 0; k < cycle.loop.length(); ++k) {
        const auto slot = static_cast<std::size_t>(k);
        const auto f = static_cast<std::size_t>(cycle.frame(k));
        std::array<double, 2> held{};
        for (std::size_t l = 0; l < 2; ++l)
            for (const Hold* hold : {&ankles[l], &toes[l]})
                if (!hold->weight.empty()) held[l] = std::max(held[l], hold->weight[slot]);
        // The firmer foot, not a blend: a point between the feet would slide both.
        const std::size_t firmer = held[1] > held[0] ? 1 : 0;
        const glm::dvec3 ankle = poses.pos(cycle.frame(k), anatomy.legs[firmer].ankle);
        plan.pivots[f] = held[firmer] > 0 ? glm::vec2(static_cast<float>(ankle.x), static_cast<float>(ankle.z)) : glm::vec2(0.0F);
        // A turn swings the other foot about the pivot (by the turn times the distance between
        // the feet), which its twist cannot take back; so the body waits until that foot is
        // nearly off: freedom is the cube of its release (73% at a 10% hold, 34% at 30%).
        const double release = 1.0 - std::min(held[0], held[1]);
        plan.turnFreedom[f] = static_cast<float>(release * release * release);
        plan.hold[f] = glm::vec2(glm::dvec2(held[0], held[1]));
    }
}

}  // namespace

FootPlan planFeet(PoseTable& poses, const std::vector<GroundFrame>& path, const RawMotion& motion, const Anatomy& anatomy,
                  const PlantedFeet& planted, double scale, LoopRange loop, double frameTime, double stature, bool lock) {
    const auto frames = static_cast<std::size_t>(poses.frames);
    FootPlan plan{std::vector<std::uint8_t>(frames, 0), std::vector<glm::vec2>(frames, glm::vec2(0.0F)), std::vector<float>(frames, 1.0F),
                  std::vector<glm::vec2>(frames, glm::vec2(0.0F))};
    if (!anatomy.biped() || loop.length() < 4) return plan;
    const Cycle cycle(path, loop);
    bool closed = true;
    for (int j = 0; j < poses.joints && closed; ++j) closed = glm::length(poses.pos(loop.first, j) - poses.pos(loop.last, j)) < 1e-9;
    const std::vector<int> sizes = subtreeSizes(parentIndices(motion));
    // Moves the whole foot so `point` goes `share` of the way to its hold's target.
    const auto holdPoint = [&](const LegChain& leg, int point, const Hold& hold, const auto& share) {
        for (int k = 0; k < loop.length() && lock; ++k) {
            const double w = share(static_cast<std::size_t>(k));
            if (w <= 0) continue;
            const int f = cycle.frame(k);
            const glm::dvec3 at = poses.pos(f, point);
            const glm::dvec2 here = path[static_cast<std::size_t>(f)].inverse().apply(hold.target[static_cast<std::size_t>(k)]);
            reach(poses, f, leg, sizes, poses.pos(f, leg.ankle) + w * glm::dvec3(here.x - at.x, 0.0, here.y - at.z));
        }
    };
    std::array<Hold, 2> ankleHolds, toeHolds;
    for (std::size_t l = 0; l < 2; ++l) {
        const LegChain& leg = anatomy.legs[l];
        // The heel's contact holds the ankle. From heel-off the toe's contact holds the foot,
        // through the ankle, at the spot the ankle's hold left the toe: the toe's hold is
        // planned on the poses the ankle's hold made. It takes over fully as soon as the
        // ankle's hold is less than whole (its spot is where the toe was then, so nothing
        // jumps); a blend of the two, while the ankle's hold fades, would let the toe wander.
        const Hold& ankle = ankleHolds[l] = planHold(poses, cycle, leg.ankle, planted.ankle[l], frameTime, stature);
        holdPoint(leg, leg.ankle, ankle, [&](std::size_t k) { return ankle.weight[k]; });
        if (planted.toe[l].empty()) continue;
        const Hold& toe = toeHolds[l] = planHold(poses, cycle, leg.toe, planted.toe[l], frameTime, stature, ankle.weight);
        holdPoint(leg, leg.toe, toe, [&](std::size_t k) { return ankle.weight[k] >= 1.0 ? 0.0 : toe.weight[k]; });
    }
    if (lock && closed)
        for (int j = 0; j < poses.joints; ++j) {
            poses.pos(loop.last, j) = poses.pos(loop.first, j);
            poses.rot(loop.last, j) = poses.rot(loop.first, j);
        }
    planTurning(poses, cycle, anatomy, ankleHolds, toeHolds, plan);
    if (closed) {  // the seam frame shows the same pose as the first
        plan.pivots[static_cast<std::size_t>(loop.last)] = plan.pivots[static_cast<std::size_t>(loop.first)];
        plan.turnFreedom[static_cast<std::size_t>(loop.last)] = plan.turnFreedom[static_cast<std::size_t>(loop.first)];
        plan.hold[static_cast<std::size_t>(loop.last)] = plan.hold[static_cast<std::size_t>(loop.first)];
    }
    std::array<double, 2> soleLow{};
    for (std::size_t l = 0; l < 2; ++l) {
        std::vector<double> heights;
        for (int f = loop.first; f < loop.last; ++f) heights.push_back(lowestSole(poses, motion, anatomy.legs[l], scale, f).y);
        soleLow[l] = percentile(heights, 0.05) + 0.03 * stature;
    }
    for (int f = 0; f < poses.frames; ++f)
        for (std::size_t l = 0; l < 2; ++l)
            if (lowestSole(poses, motion, anatomy.legs[l], scale, f).y <= soleLow[l])
                plan.contacts[static_cast<std::size_t>(f)] |= static_cast<std::uint8_t>(1U << l);
    return plan;
}

}  // namespace throng::motion::bake_steps
