// ORCA's half-planes and velocities: the batched lines against the one-at-a-time reference,
// bit for bit, over every case the construction distinguishes; and the chosen velocity's
// guarantees on small scenes whose answers follow from the geometry.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "throng/crowd/orca.h"

namespace throng::crowd {
namespace {

bool sameBits(const OrcaLine& a, const OrcaLine& b) { return std::memcmp(&a, &b, sizeof(OrcaLine)) == 0; }

// Which of orcaLine's three constructions a neighbour falls in, recomputed from the geometry.
enum class Case { CutOffCircle, Leg, Overlap };
Case caseOf(const OrcaAgent& agent, const OrcaAgent& other, float timeHorizon) {
    const glm::vec2 relative = other.position - agent.position;
    const float combined = agent.radius + other.radius;
    if (glm::dot(relative, relative) <= combined * combined) return Case::Overlap;
    const glm::vec2 w = agent.velocity - other.velocity - relative / timeHorizon;
    const float along = glm::dot(w, relative);
    return along < 0.0F && along * along > combined * combined * glm::dot(w, w) ? Case::CutOffCircle : Case::Leg;
}

TEST(Orca, BatchedLinesAreBitIdenticalToOneAtATime) {
    std::mt19937 random(12345);
    std::uniform_real_distribution<float> place(-2.5F, 2.5F), speed(-2.0F, 2.0F), size(0.15F, 0.4F);
    const OrcaParameters parameters{.timeHorizon = 1.5F, .timeStep = 1.0F / 30.0F, .maxSpeed = 2.0F};
    std::array<int, 3> seen{};
    // Every count from none to more than the lines asked for, so the padded lanes are exercised.
    for (int trial = 0; trial < 20000; ++trial) {
        const OrcaAgent agent{{place(random), place(random)}, {speed(random), speed(random)}, size(random)};
        std::vector<OrcaAgent> neighbours(static_cast<std::size_t>(trial % (kMaxOrcaNeighbours + 3)));
        for (OrcaAgent& other : neighbours) {
            other = {{place(random), place(random)}, {speed(random), speed(random)}, size(random)};
            if (trial % 7 == 0) other.position = agent.position + 0.1F * (other.position - agent.position);  // overlapping
            ++seen[static_cast<std::size_t>(caseOf(agent, other, parameters.timeHorizon))];
        }
        std::array<OrcaLine, kMaxOrcaNeighbours> lines{};
        const std::size_t count = std::min(neighbours.size(), lines.size());
        orcaLines(agent, neighbours, parameters, std::span(lines.data(), count));
        for (std::size_t k = 0; k < count; ++k)
            ASSERT_TRUE(sameBits(lines[k], orcaLine(agent, neighbours[k], parameters))) << "trial " << trial << ", neighbour " << k;
    }
    for (const int cases : seen) EXPECT_GT(cases, 1000);  // each construction met many times
}

TEST(Orca, BatchedLinesMatchEvenForCoincidentAndStillNeighbours) {
    // Exactly on top of each other, with equal velocities: the overlap case's w is zero, so its
    // length is clamped, in both forms alike.
    const OrcaParameters parameters{};
    const OrcaAgent agent{{1.0F, 2.0F}, {0.0F, 0.0F}, 0.3F};
    const std::array<OrcaAgent, 3> neighbours{OrcaAgent{{1.0F, 2.0F}, {0.0F, 0.0F}, 0.3F}, OrcaAgent{{1.0F, 2.0F}, {1.0F, 0.0F}, 0.3F},
                                              OrcaAgent{{5.0F, 2.0F}, {0.0F, 0.0F}, 0.3F}};
    std::array<OrcaLine, 3> lines{};
    orcaLines(agent, neighbours, parameters, lines);
    for (std::size_t k = 0; k < lines.size(); ++k) EXPECT_TRUE(sameBits(lines[k], orcaLine(agent, neighbours[k], parameters))) << k;
}

TEST(Orca, AloneTheAgentTakesItsPreferredVelocityWithinItsTopSpeed) {
    const OrcaParameters parameters{.timeHorizon = 1.5F, .timeStep = 1.0F / 30.0F, .maxSpeed = 2.0F};
    const OrcaAgent agent{{0.0F, 0.0F}, {1.0F, 0.0F}, 0.3F};
    EXPECT_EQ(orcaVelocity(agent, {1.2F, 0.5F}, {}, parameters), glm::vec2(1.2F, 0.5F));
    const glm::vec2 capped = orcaVelocity(agent, {6.0F, 8.0F}, {}, parameters);  // 10 m/s wanted
    EXPECT_NEAR(glm::length(capped), 2.0F, 1e-5F);
    EXPECT_NEAR(capped.x / capped.y, 0.75F, 1e-5F);
}

TEST(Orca, HeadOnAgentsSwerveApartAndNeitherCollidesWithinTheHorizon) {
    // Two agents 4 m apart walking straight at each other at 1.4 m/s: each must leave the line,
    // to opposite sides (reciprocity), and with the chosen velocities they stay apart for the
    // whole horizon.
    const OrcaParameters parameters{.timeHorizon = 2.0F, .timeStep = 1.0F / 30.0F, .maxSpeed = 2.0F};
    const OrcaAgent a{{-2.0F, 0.0F}, {1.4F, 0.0F}, 0.3F};
    const OrcaAgent b{{2.0F, 0.01F}, {-1.4F, 0.0F}, 0.3F};
    const glm::vec2 va = orcaVelocity(a, a.velocity, std::span(&b, 1), parameters);
    const glm::vec2 vb = orcaVelocity(b, b.velocity, std::span(&a, 1), parameters);
    EXPECT_GT(std::abs(va.y), 0.05F);
    EXPECT_LT(va.y * vb.y, 0.0F);
    for (int step = 0; step <= 200; ++step) {
        const float t = parameters.timeHorizon * static_cast<float>(step) / 200.0F;
        EXPECT_GE(glm::length((b.position + t * vb) - (a.position + t * va)), a.radius + b.radius - 1e-3F) << "t = " << t;
    }
}

}  // namespace
}  // namespace throng::crowd
