#pragma once
// Optimal Reciprocal Collision Avoidance (van den Berg, Guy, Lin, Manocha 2011): each agent
// takes half of the responsibility for avoiding each neighbour, expressed as a half-plane of
// allowed velocities, and picks the allowed velocity closest to the one it prefers.
// Pure functions over plain values: no allocation, no state.

#include <span>

#include "throng/core/math.h"

namespace throng::crowd {

/// The agent that is choosing a velocity, and each neighbour it sees. Metres, m/s.
struct OrcaAgent {
    glm::vec2 position{0.0F};
    glm::vec2 velocity{0.0F};
    float radius = 0.3F;
};

struct OrcaParameters {
    float timeHorizon = 2.0F;  ///< Seconds ahead within which collisions with neighbours are avoided.
    float timeStep = 1.0F / 30.0F;  ///< The simulation step; resolves overlaps that already exist.
    float maxSpeed = 2.0F;     ///< Largest speed the agent may choose.
};

/// A half-plane of velocities: allowed on the left of `direction` through `point`.
struct OrcaLine {
    glm::vec2 point{0.0F};
    glm::vec2 direction{1.0F, 0.0F};
};

/// Most neighbours considered per agent; more add cost and little safety.
inline constexpr int kMaxOrcaNeighbours = 8;

/// The velocity `agent` should take, given the neighbours it sees and the velocity it
/// prefers. When the constraints can't all be met (a jam), it returns the velocity that
/// violates them least.
[[nodiscard]] glm::vec2 orcaVelocity(const OrcaAgent& agent, glm::vec2 preferredVelocity,
                                     std::span<const OrcaAgent> neighbours, const OrcaParameters& parameters);

/// The half-plane that `agent` must respect to avoid `other` (exposed for tests).
[[nodiscard]] OrcaLine orcaLine(const OrcaAgent& agent, const OrcaAgent& other, const OrcaParameters& parameters);

/// orcaLine for each of the first `lines.size()` neighbours (at most neighbours.size()), into
/// `lines`, several at once: bit-identical to orcaLine's (exposed for tests; orcaVelocity uses it).
void orcaLines(const OrcaAgent& agent, std::span<const OrcaAgent> neighbours, const OrcaParameters& parameters, std::span<OrcaLine> lines);

}  // namespace throng::crowd
