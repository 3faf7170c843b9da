#include "throng/crowd/orca.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <experimental/simd>

namespace throng::crowd {
namespace {

constexpr float kEpsilon = 1e-5F;

float det(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// Lines are small fixed arrays so the solver never allocates.
struct LineSet {
    std::array<OrcaLine, kMaxOrcaNeighbours> lines;
    std::size_t size = 0;
};

// Best velocity on line `index` within the speed disc that also satisfies lines [0, index).
bool solveOnLine(const LineSet& set, std::size_t index, float radius, glm::vec2 optimum, bool directionOpt, glm::vec2& result) {
    const OrcaLine& line = set.lines[index];
    const float along = glm::dot(line.point, line.direction);
    const float discriminant = along * along + radius * radius - glm::dot(line.point, line.point);
    if (discriminant < 0.0F) return false;  // the line misses the speed disc
    const float root = std::sqrt(discriminant);
    float tLeft = -along - root, tRight = -along + root;
    for (std::size_t i = 0; i < index; ++i) {
        const float denominator = det(line.direction, set.lines[i].direction);
        const float numerator = det(set.lines[i].direction, line.point - set.lines[i].point);
        if (std::abs(denominator) <= kEpsilon) {  // parallel lines
            if (numerator < 0.0F) return false;
            continue;
        }
        const float t = numerator / denominator;
        if (denominator >= 0.0F) {
            tRight = std::min(tRight, t);
        } else {
            tLeft = std::max(tLeft, t);
        }
        if (tLeft > tRight) return false;
    }
    if (directionOpt) {
        result = line.point + (glm::dot(optimum, line.direction) > 0.0F ? tRight : tLeft) * line.direction;
    } else {
        const float t = std::clamp(glm::dot(line.direction, optimum - line.point), tLeft, tRight);
        result = line.point + t * line.direction;
    }
    return true;
}

// Incremental 2D linear program: returns the index of the first line it could not satisfy,
// or set.size when all hold.
std::size_t solvePlanar(const LineSet& set, float radius, glm::vec2 optimum, bool directionOpt, glm::vec2& result) {
    if (directionOpt) {
        result = optimum * radius;
    } else if (glm::dot(optimum, optimum) > radius * radius) {
        result = glm::normalize(optimum) * radius;
    } else {
        result = optimum;
    }
    for (std::size_t i = 0; i < set.size; ++i) {
        if (det(set.lines[i].direction, set.lines[i].point - result) > 0.0F) {  // violates line i
            const glm::vec2 previous = result;
            if (!solveOnLine(set, i, radius, optimum, directionOpt, result)) {
                result = previous;
                return i;
            }
        }
    }
    return set.size;
}

// When the constraints are infeasible, minimise the largest violation (a 3D program reduced
// to a sequence of 2D ones, as in the ORCA paper).
void solveLeastViolation(const LineSet& set, std::size_t begin, float radius, glm::vec2& result) {
    float distance = 0.0F;
    for (std::size_t i = begin; i < set.size; ++i) {
        const OrcaLine& lineI = set.lines[i];
        if (det(lineI.direction, lineI.point - result) <= distance) continue;
        LineSet projected;
        for (std::size_t j = 0; j < i; ++j) {
            const OrcaLine& lineJ = set.lines[j];
            OrcaLine line;
            const float determinant = det(lineI.direction, lineJ.direction);
            if (std::abs(determinant) <= kEpsilon) {
                if (glm::dot(lineI.direction, lineJ.direction) > 0.0F) continue;  // same direction
                line.point = 0.5F * (lineI.point + lineJ.point);
            } else {
                line.point = lineI.point + (det(lineJ.direction, lineI.point - lineJ.point) / determinant) * lineI.direction;
            }
            const glm::vec2 difference = lineJ.direction - lineI.direction;
            if (glm::dot(difference, difference) <= kEpsilon * kEpsilon) continue;
            line.direction = glm::normalize(difference);
            projected.lines[projected.size++] = line;
        }
        const glm::vec2 previous = result;
        if (solvePlanar(projected, radius, glm::vec2(-lineI.direction.y, lineI.direction.x), true, result) < projected.size)
            result = previous;  // rounding: keep the previous answer
        distance = det(lineI.direction, lineI.point - result);
    }
}

}  // namespace

OrcaLine orcaLine(const OrcaAgent& agent, const OrcaAgent& other, const OrcaParameters& parameters) {
    const glm::vec2 relativePosition = other.position - agent.position;
    const glm::vec2 relativeVelocity = agent.velocity - other.velocity;
    const float distanceSq = glm::dot(relativePosition, relativePosition);
    const float combinedRadius = agent.radius + other.radius;
    const float combinedRadiusSq = combinedRadius * combinedRadius;
    const float invTimeHorizon = 1.0F / parameters.timeHorizon;
    OrcaLine line;
    glm::vec2 u;
    if (distanceSq > combinedRadiusSq) {
        // Not touching: the velocity obstacle is a truncated cone; push out of it the short way.
        const glm::vec2 w = relativeVelocity - invTimeHorizon * relativePosition;
        const float wLengthSq = glm::dot(w, w);
        const float dotProduct = glm::dot(w, relativePosition);
        if (dotProduct < 0.0F && dotProduct * dotProduct > combinedRadiusSq * wLengthSq) {
            const float wLength = std::sqrt(wLengthSq);  // nearest point is on the cut-off circle
            const glm::vec2 unitW = w / wLength;
            line.direction = glm::vec2(unitW.y, -unitW.x);
            u = (combinedRadius * invTimeHorizon - wLength) * unitW;
        } else {
            const float leg = std::sqrt(distanceSq - combinedRadiusSq);  // nearest point is on a leg
            if (det(relativePosition, w) > 0.0F) {
                line.direction = glm::vec2(relativePosition.x * leg - relativePosition.y * combinedRadius,
                                           relativePosition.x * combinedRadius + relativePosition.y * leg) / distanceSq;
            } else {
                line.direction = -glm::vec2(relativePosition.x * leg + relativePosition.y * combinedRadius,
                                            -relativePosition.x * combinedRadius + relativePosition.y * leg) / distanceSq;
            }
            u = glm::dot(relativeVelocity, line.direction) * line.direction - relativeVelocity;
        }
    } else {
        // Already overlapping: separate within one time step.
        const float invTimeStep = 1.0F / parameters.timeStep;
        const glm::vec2 w = relativeVelocity - invTimeStep * relativePosition;
        const float wLength = std::max(glm::length(w), kEpsilon);
        const glm::vec2 unitW = w / wLength;
        line.direction = glm::vec2(unitW.y, -unitW.x);
        u = (combinedRadius * invTimeStep - wLength) * unitW;
    }
    line.point = agent.velocity + 0.5F * u;  // reciprocal: each agent takes half
    return line;
}

void orcaLines(const OrcaAgent& agent, std::span<const OrcaAgent> neighbours, const OrcaParameters& parameters, std::span<OrcaLine> lines) {
    // orcaLine's arithmetic, operation for operation, on a few neighbours at once: every branch
    // is evaluated and each lane keeps its own, so the lines are bit-identical (no fused
    // multiply-adds: the baseline x86-64 target has none). One neighbour at a time, the branches
    // (which cone leg, or overlapping) were a coin toss that mispredicted often.
    namespace stdx = std::experimental;
    using Lanes = stdx::fixed_size_simd<float, 4>;
    constexpr std::size_t kLanes = Lanes::size();
    const std::size_t count = std::min(lines.size(), neighbours.size());
    const float invTimeHorizon = 1.0F / parameters.timeHorizon;
    const float invTimeStep = 1.0F / parameters.timeStep;
    for (std::size_t first = 0; first < count; first += kLanes) {
        // Lanes past the last neighbour repeat it; their lines are not kept.
        const auto at = [&](std::size_t lane) -> const OrcaAgent& { return neighbours[std::min(first + lane, count - 1)]; };
        const Lanes relX([&](std::size_t lane) { return at(lane).position.x - agent.position.x; });
        const Lanes relY([&](std::size_t lane) { return at(lane).position.y - agent.position.y; });
        const Lanes velX([&](std::size_t lane) { return agent.velocity.x - at(lane).velocity.x; });
        const Lanes velY([&](std::size_t lane) { return agent.velocity.y - at(lane).velocity.y; });
        const Lanes combined([&](std::size_t lane) { return agent.radius + at(lane).radius; });
        const Lanes distanceSq = relX * relX + relY * relY;
        const Lanes combinedSq = combined * combined;
        // Not touching: the truncated cone, by its cut-off circle or by a leg.
        const Lanes wX = velX - invTimeHorizon * relX, wY = velY - invTimeHorizon * relY;
        const Lanes wLengthSq = wX * wX + wY * wY;
        const Lanes dotProduct = wX * relX + wY * relY;
        const auto onCircle = (dotProduct < 0.0F) && (dotProduct * dotProduct > combinedSq * wLengthSq);
        const Lanes wLength = stdx::sqrt(wLengthSq);
        const Lanes unitX = wX / wLength, unitY = wY / wLength;
        const Lanes leg = stdx::sqrt(distanceSq - combinedSq);
        const auto leftLeg = relX * wY - relY * wX > 0.0F;
        Lanes directionX = -((relX * leg + relY * combined) / distanceSq);
        Lanes directionY = -((-relX * combined + relY * leg) / distanceSq);
        stdx::where(leftLeg, directionX) = (relX * leg - relY * combined) / distanceSq;
        stdx::where(leftLeg, directionY) = (relX * combined + relY * leg) / distanceSq;
        const Lanes along = velX * directionX + velY * directionY;
        Lanes uX = along * directionX - velX, uY = along * directionY - velY;
        stdx::where(onCircle, directionX) = unitY;
        stdx::where(onCircle, directionY) = -unitX;
        const Lanes circleScale = combined * invTimeHorizon - wLength;
        stdx::where(onCircle, uX) = circleScale * unitX;
        stdx::where(onCircle, uY) = circleScale * unitY;
        // Already overlapping: separate within one time step. Rare, so worked out only when a
        // lane needs it (a square root and two divisions saved most of the time).
        const auto touching = !(distanceSq > combinedSq);
        if (stdx::any_of(touching)) {
            const Lanes sX = velX - invTimeStep * relX, sY = velY - invTimeStep * relY;
            Lanes sLength = stdx::sqrt(sX * sX + sY * sY);
            stdx::where(sLength < kEpsilon, sLength) = kEpsilon;  // as std::max(length, kEpsilon), NaN kept
            const Lanes sUnitX = sX / sLength, sUnitY = sY / sLength;
            const Lanes separateScale = combined * invTimeStep - sLength;
            stdx::where(touching, directionX) = sUnitY;
            stdx::where(touching, directionY) = -sUnitX;
            stdx::where(touching, uX) = separateScale * sUnitX;
            stdx::where(touching, uY) = separateScale * sUnitY;
        }
        const Lanes pointX = agent.velocity.x + 0.5F * uX, pointY = agent.velocity.y + 0.5F * uY;
        for (std::size_t lane = 0; lane < kLanes && first + lane < count; ++lane)
            lines[first + lane] = {{pointX[lane], pointY[lane]}, {directionX[lane], directionY[lane]}};
    }
}

glm::vec2 orcaVelocity(const OrcaAgent& agent, glm::vec2 preferredVelocity, std::span<const OrcaAgent> neighbours,
                       const OrcaParameters& parameters) {
    LineSet set;
    set.size = std::min(neighbours.size(), set.lines.size());
    orcaLines(agent, neighbours, parameters, std::span(set.lines.data(), set.size));
    glm::vec2 result(0.0F);
    const std::size_t failed = solvePlanar(set, parameters.maxSpeed, preferredVelocity, false, result);
    if (failed < set.size) solveLeastViolation(set, failed, parameters.maxSpeed, result);
    return result;
}

}  // namespace throng::crowd
