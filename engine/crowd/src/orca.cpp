#include "throng/crowd/orca.h"

#include <algorithm>
#include <array>
#include <cmath>

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

glm::vec2 orcaVelocity(const OrcaAgent& agent, glm::vec2 preferredVelocity, std::span<const OrcaAgent> neighbours,
                       const OrcaParameters& parameters) {
    LineSet set;
    for (const OrcaAgent& other : neighbours) {
        if (set.size == set.lines.size()) break;
        set.lines[set.size++] = orcaLine(agent, other, parameters);
    }
    glm::vec2 result(0.0F);
    const std::size_t failed = solvePlanar(set, parameters.maxSpeed, preferredVelocity, false, result);
    if (failed < set.size) solveLeastViolation(set, failed, parameters.maxSpeed, result);
    return result;
}

}  // namespace throng::crowd
