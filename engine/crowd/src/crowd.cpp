#include "throng/crowd/crowd.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <stdexcept>
#include <string>

#include "crowd_internal.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/orca.h"

namespace throng::crowd {
namespace {

using detail::randomPointIn;
using detail::yawToward;

// Where a character may be: a non-finite step keeps it where it was, and one that leaves the
// world (range::kWorldEdge) holds it at the edge, so positions stay finite for any clip.
glm::dvec2 keepInWorld(glm::dvec2 next, glm::dvec2 previous) {
    if (!std::isfinite(next.x) || !std::isfinite(next.y)) return previous;
    return glm::clamp(next, -range::kWorldEdge, range::kWorldEdge);
}

// Headings stay finite and, should a clip keep turning for ages, small.
double keepYaw(double yaw) {
    if (!std::isfinite(yaw)) return 0.0;
    return std::abs(yaw) > 1e4 ? wrapAngle(yaw) : yaw;
}

}  // namespace

const char* modeName(Mode mode) {
    switch (mode) {
        case Mode::Group: return "group";
        case Mode::Goals: return "goals";
        case Mode::Avoid: return "avoid";
        case Mode::Follow: return "follow";
    }
    return "?";
}

std::optional<Mode> modeFromName(std::string_view name) {
    for (Mode mode : {Mode::Group, Mode::Goals, Mode::Avoid})
        if (name == modeName(mode)) return mode;
    return std::nullopt;
}

double Crowd::clipSpeed(const motion::BakedClip& clip) { return clip.speed; }

void Crowd::pickGoal(std::size_t i) {
    if (!waypoints_.empty()) {
        goal_[i] = waypoints_[waypoint_[i]];
        waypoint_[i] = (waypoint_[i] + 1) % static_cast<std::uint32_t>(waypoints_.size());
        return;
    }
    // A goal at least a few metres away, so nobody arrives the moment it sets off.
    for (int attempt = 0; attempt < 8; ++attempt) {
        goal_[i] = randomPointIn(area_, rng_[i]);
        if (glm::length(goal_[i] - glm::vec2(ground_[i].position)) > 3.0F * parameters_.arrivalRadius) break;
    }
}

THRONG_NO_VECTORIZE std::size_t Crowd::nearestNeighbours(std::size_t i, glm::vec2 position, std::array<std::uint32_t, kMaxOrcaNeighbours>& nearest) const {
    // Every candidate is written to a buffer and kept by advancing the count, with no branch:
    // about half the candidates are in reach, which no branch predictor guesses, and the
    // mispredictions were most of the scan's time. The buffer is ordered only when it fills
    // and at the end, stably, so the neighbours and their order are those of a sorted scan.
    constexpr std::size_t kBuffer = 64;
    std::array<float, kBuffer> distance;
    std::array<std::uint32_t, kBuffer> where;
    std::size_t count = 0;
    // Each kept candidate's place in the stable order is the count of those before it (nearer,
    // or as near and earlier): counted without branches too, a few dozen comparisons, in scalar
    // code (THRONG_NO_VECTORIZE: 2.6% of the avoid step at 10,000 characters).
    const auto rankOf = [&](std::size_t a) {
        std::size_t rank = 0;
        for (std::size_t b = 0; b < a; ++b) rank += static_cast<std::size_t>(distance[b] <= distance[a]);
        for (std::size_t b = a + 1; b < count; ++b) rank += static_cast<std::size_t>(distance[b] < distance[a]);
        return rank;
    };
    // More in reach than the buffer holds (a crowd packed tighter than people stand): keep the
    // nearest and scan on.
    const auto keepNearest = [&] {
        std::array<std::uint32_t, kMaxOrcaNeighbours> kept{};
        std::array<float, kMaxOrcaNeighbours> keptDistance{};
        for (std::size_t a = 0; a < count; ++a)
            if (const std::size_t rank = rankOf(a); rank < kept.size()) {
                kept[rank] = where[a];
                keptDistance[rank] = distance[a];
            }
        count = kept.size();
        std::copy(kept.begin(), kept.end(), where.begin());
        std::copy(keptDistance.begin(), keptDistance.end(), distance.begin());
    };
    const float reachSq = parameters_.neighbourDistance * parameters_.neighbourDistance;
    const auto self = static_cast<std::uint32_t>(i);
    hash_.forEachCellRange(position, parameters_.neighbourDistance, [&](std::uint32_t first, std::uint32_t last) {
        for (std::uint32_t k = first; k < last; ++k) {
            const Neighbour& n = cellOrdered_[k];
            const float dx = n.x - position.x, dy = n.y - position.y;
            const float d = dx * dx + dy * dy;
            distance[count] = d;
            where[count] = k;
            count += static_cast<std::size_t>(!(d > reachSq)) & static_cast<std::size_t>(n.index != self);
            if (count == kBuffer) keepNearest();
        }
    });
    // Straight into place: no copies (a copy of a variable length is a library call).
    for (std::size_t a = 0; a < count; ++a)
        if (const std::size_t rank = rankOf(a); rank < nearest.size()) nearest[rank] = where[a];
    return std::min(count, nearest.size());
}

void Crowd::preferVelocity(std::span<const motion::BakedClip> clips, std::size_t i) {
    fastest_[i] = -1.0F;  // nothing to avoid unless it avoids
    if (mode_[i] == Mode::Group || mode_[i] == Mode::Follow) return;
    const glm::vec2 position(ground_[i].position);
    // A set's character cruises at its desired speed (its blend shows any speed of the set); a
    // single clip at its own pace times its playback multiplier.
    const bool blends = set_[i] >= 0;
    const glm::vec2 toGoal = goal_[i] - position;
    const float distance = glm::length(toGoal);
    const float cruise = blends ? approachSpeed(i, distance, static_cast<float>(wrapAngle(yawToward(toGoal) - ground_[i].yaw)))
                                : static_cast<float>(clipSpeed(clips[clip_[i]])) * scale_[i];
    desired_[i] = distance > 1e-4F ? toGoal / distance * cruise * (blends ? 1.0F : baseSpeed_[i]) : glm::vec2(0.0F);
    if (mode_[i] == Mode::Avoid)
        fastest_[i] = blends ? static_cast<float>(sets_[static_cast<std::size_t>(set_[i])].fastest()) * scale_[i] : cruise * parameters_.maxPlayback;
}

void Crowd::avoidInCellOrder(float seconds) {
    // In the grid's cell order: consecutive characters scan mostly the same cells, which stay in
    // cache, and everything read here was gathered into that order (cellOrdered_, wishes_), so
    // nothing is fetched from a far place in the per-character arrays.
    pool_->parallelFor(cellOrdered_.size(), [&](std::size_t begin, std::size_t end) {
        std::array<OrcaAgent, kMaxOrcaNeighbours> neighbours{};
        std::array<std::uint32_t, kMaxOrcaNeighbours> nearest{};  // positions in cellOrdered_
        for (std::size_t k = begin; k < end; ++k) {
            const Wish wish = wishes_[k];
            if (!(wish.fastest >= 0.0F)) continue;
            const Neighbour& self = cellOrdered_[k];
            const glm::vec2 position(self.x, self.y);
            const std::size_t count = nearestNeighbours(self.index, position, nearest);
            for (std::size_t n = 0; n < count; ++n) {
                const Neighbour& other = cellOrdered_[nearest[n]];
                neighbours[n] = {{other.x, other.y}, {other.vx, other.vy}, other.radius};
            }
            const OrcaParameters orca{.timeHorizon = parameters_.timeHorizon, .timeStep = seconds, .maxSpeed = wish.fastest};
            desired_[self.index] = orcaVelocity({position, {self.vx, self.vy}, self.radius}, wish.preferred,
                                                std::span(neighbours.data(), count), orca);
        }
    });
}

void Crowd::integrate(std::span<const motion::BakedClip> clips, double seconds, std::size_t i) {
    if (mode_[i] == Mode::Follow) {
        follow(clips, i, time_ + seconds);
        return;
    }
    startWaitingTransition(clips, i);
    if (mode_[i] == Mode::Group) {
        // Paper: C_{i+1} = C_i + M_o (p0^i - p0^{i-1}); composing ground frames is that update,
        // with the clip's own turning included and the loop seam continued (RootMotionTrack).
        const Played played = advance(clips, seconds, i, desiredSpeed_[i]);
        const motion::GroundFrame next = ground_[i].then({played.delta.position * static_cast<double>(scale_[i]), played.delta.yaw});
        ground_[i] = {keepInWorld(next.position, ground_[i].position), keepYaw(next.yaw)};
        return;
    }
    // ORCA's answer is finite for finite inputs; should it not be, the character stands still.
    const glm::vec2 velocity = std::isfinite(desired_[i].x) && std::isfinite(desired_[i].y) ? desired_[i] : glm::vec2(0.0F);
    const float speed = glm::length(velocity);
    const double heading = ground_[i].yaw;
    const double target = speed > 1e-4F ? static_cast<double>(yawToward(velocity)) : heading;
    const auto cruise = static_cast<float>(clipSpeed(clips[clip_[i]])) * scale_[i];
    // Playback follows the chosen speed so feet keep pace with the ground (a set's blend
    // follows it instead, in advance()).
    playback_[i] = mode_[i] == Mode::Goals ? baseSpeed_[i]
                                           : std::clamp(cruise > 1e-4F ? speed / cruise : 1.0F, parameters_.minPlayback,
                                                        parameters_.maxPlayback);
    const Played played = advance(clips, seconds, i, speed);
    const motion::GroundFrame& delta = played.delta;
    const motion::BakedClip& clip = clips[played.clip];
    const double steer = steering(i, wrapAngle(target - heading) - delta.yaw, seconds);
    const double scale = scale_[i];
    motion::GroundFrame next;
    if (mode_[i] == Mode::Avoid && speed > 1e-4F) {
        // Along the velocity ORCA chose, so the avoidance guarantee holds; the body turns
        // toward it with the clip's own turning plus the ramped steering.
        // A blend slows at a bounded rate, so its step may be longer than ORCA's: never go further.
        const double step = glm::length(delta.position) * scale;
        const double length = set_[i] >= 0 ? std::min(step, static_cast<double>(speed) * seconds) : step;
        // Facing `target` is moving along the velocity: its direction is the unit velocity,
        // with no sine and cosine to take.
        next = {ground_[i].position + glm::dvec2(velocity) * (length / static_cast<double>(speed)), heading + delta.yaw + steer};
    } else {
        // The clip's own step and turn, then the steering as a pivot about the planted foot,
        // so a turning character's stance foot stays where it is.
        next = ground_[i].then({delta.position * scale, delta.yaw});
        const double remaining = wrapAngle(target - heading - delta.yaw);
        // A character standing on a set's idle has both feet down: it turns as it sets off,
        // stepping, not by swivelling over its feet.
        const bool standing = set_[i] >= 0 && !clocks_[played.clip];
        if (standing) turnVelocity_[i] = 0.0F;
        const double turn = standing ? 0.0 : gaitTimedTurn(clip, played.frame, steer, remaining);
        const double taken = twistFeet(i, clip, played.frame, turn, remaining, seconds);
        const glm::dvec2 pivot = next.apply(clip.pivotAt(played.frame) * scale);
        next = {pivot + rotateGround(next.position - pivot, taken), next.yaw + taken};
    }
    const glm::dvec2 moved = keepInWorld(next.position, ground_[i].position);
    velocity_[i] = moved == next.position ? glm::vec2((moved - ground_[i].position) / seconds) : glm::vec2(0.0F);
    ground_[i].position = moved;
    ground_[i].yaw = keepYaw(wrapAngle(next.yaw));
    arrive(i, seconds);
}

double Crowd::twistFeet(std::size_t i, const motion::BakedClip& clip, double frame, double turn, double remaining, double seconds) {
    // A held foot takes the body's turn back as a twist about its ankle, so it stays where it
    // is, pointing where it pointed. A leg twists no more than a hip turns comfortably (about
    // 30°): the turn waits for the next step rather than slide the foot.
    constexpr double kSwingSeconds = 0.08, kLargestTwist = 0.5;
    const glm::dvec2 hold = clip.footHoldAt(frame);
    for (int l = 0; l < 2; ++l)
        if (hold[l] > 1e-3) {
            const double twist = footTwist_[i][l];
            turn = std::clamp(turn, (twist - kLargestTwist) / hold[l], (twist + kLargestTwist) / hold[l]);
        }
    // A lifted foot turns in the air (most of the way within a swing) to point where the body
    // will have turned by the end of its next stance, no further than the heading still
    // wanted; the stance then takes that twist back, so the foot lifts less twisted (the guess
    // uses today's rate: a turn that speeds up or ends within the stance leaves some over).
    const double rate = turnVelocity_[i] / std::max(1e-3, static_cast<double>(playback_[i]));
    const double still = remaining - turn;
    for (int l = 0; l < 2; ++l) {
        double ahead = std::clamp(rate * clip.stanceTurnSeconds[l], -kLargestTwist, kLargestTwist);
        if (ahead * still <= 0) ahead = 0.0;
        else if (std::abs(ahead) > std::abs(still)) ahead = still;
        const double held = static_cast<double>(footTwist_[i][l]) - hold[l] * turn;
        const double swing = std::min(1.0, (1.0 - hold[l]) * seconds / kSwingSeconds);
        footTwist_[i][l] = static_cast<float>(std::clamp(held + (ahead - held) * swing, -kLargestTwist, kLargestTwist));
    }
    return turn;
}

double Crowd::gaitTimedTurn(const motion::BakedClip& clip, double frame, double steer, double remaining) {
    // The steering's rate is what the body turns on average over a cycle; it turns when the
    // gait lets it (one foot point held, the pivot) and not while a second point is held,
    // which a turn would slide.
    const double turn = steer * clip.turnGainAt(frame);
    // Never past the wanted heading: a concentrated turn could overshoot it in one step.
    return std::abs(turn) > std::abs(remaining) && turn * remaining > 0 ? remaining : turn;
}

double Crowd::steering(std::size_t i, double wanted, double seconds) {
    // The steering's turn rate ramps (bounded angular acceleration) and brakes in time to stop
    // at the wanted heading: sqrt(2 a |remaining|) is the fastest rate that can still stop there.
    const double rateLimit = parameters_.turnRate, acceleration = parameters_.turnAcceleration;
    const double remaining = wrapAngle(wanted);
    const double reachable = std::min({rateLimit, std::sqrt(2.0 * acceleration * std::abs(remaining)), std::abs(remaining) / seconds});
    const double desiredRate = std::copysign(reachable, remaining);
    const double change = std::clamp(desiredRate - static_cast<double>(turnVelocity_[i]), -acceleration * seconds, acceleration * seconds);
    turnVelocity_[i] = static_cast<float>(std::isfinite(change) ? turnVelocity_[i] + change : 0.0);
    return static_cast<double>(turnVelocity_[i]) * seconds;
}

void Crowd::step(std::span<const motion::BakedClip> clips, double seconds) {
    if (!(seconds > 0)) return;
    applyEvents(clips);
    const bool avoiding = std::any_of(mode_.begin(), mode_.end(), [](Mode m) { return m == Mode::Avoid; });
    const bool steering = avoiding || std::any_of(mode_.begin(), mode_.end(), [](Mode m) { return m == Mode::Goals; });
    // Two phases over all characters: choose (reading everyone's previous state), then move
    // (writing only one's own), so the result does not depend on the thread count. Every pass
    // runs on every thread: on two threads a serial pass over 10,000 characters is a visible
    // share of a 2 ms step. A crowd that only plays its clips' root motion (group and follow)
    // chooses nothing, and skips the choosing pass: a million characters' reads of 24 bytes
    // and writes of 12 each, for nothing.
    if (steering) {
        pool_->parallelFor(ground_.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) preferVelocity(clips, i);
            if (avoiding)
                for (std::size_t i = begin; i < end; ++i) positions_[i] = glm::vec2(ground_[i].position);
        });
    }
    if (avoiding) {
        // Cells of the search radius: 3 rows of 3 cells per query. Cells of half the radius
        // (5 rows of 5) test fewer candidates (10 against 14 in `bench --sim-only -n 10000
        // --modes avoid`), but a row costs more than a few candidates: 3.7% slower.
        hash_.build(positions_, parameters_.neighbourDistance);
        const std::span<const std::uint32_t> order = hash_.sorted();
        cellOrdered_.resize(order.size());
        wishes_.resize(order.size());
        pool_->parallelFor(order.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k) {
                const std::uint32_t j = order[k];
                cellOrdered_[k] = {positions_[j].x, positions_[j].y, velocity_[j].x, velocity_[j].y, radius_[j], j};
                wishes_[k] = {desired_[j], fastest_[j]};
            }
        });
        avoidInCellOrder(static_cast<float>(seconds));
    }
    pool_->parallelFor(ground_.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) integrate(clips, seconds, i);
    });
    pool_->rest();  // the step's last loop: until the next step, the cores are the renderer's
    time_ += seconds;
}

void Crowd::pack(std::size_t first, std::span<CharacterState> out) const {
    if (first > ground_.size() || out.size() > ground_.size() - first)
        throw std::out_of_range("Crowd::pack: characters " + std::to_string(first) + " + " + std::to_string(out.size()) +
                                " of a crowd of " + std::to_string(ground_.size()));
    const auto packRange = [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::size_t i = first + k;
            const motion::GroundFrame& g = ground_[i];
            // Scale 0 draws nothing on every path: a follower outside its track's span.
            const float scale = present(static_cast<int>(i)) ? scale_[i] : 0.0F;
            // Whole records in order: `out` may be write-combined GPU memory, which takes
            // sequential full lines fastest and is never read back here.
            out[k] = {glm::vec4(static_cast<float>(g.position.x), 0.0F, static_cast<float>(g.position.y), static_cast<float>(g.yaw)),
                      clip_[i], static_cast<float>(frame_[i]), scale, color_[i], footTwist_[i],
                      blendClip_[i], static_cast<float>(blendFrame_[i]), blend_[i], fromWeight_[i] > 0 ? fromClip_[i] : clip_[i],
                      static_cast<float>(fromWeight_[i] > 0 ? fromFrame_[i] : frame_[i]), fromWeight_[i]};
        }
    };
    // A large crowd's pack reads about 90 bytes a character from a dozen columns and writes 64:
    // at a million characters, on one thread, about as long as the whole step on sixteen. A
    // small one's is a few microseconds, less than waking the pool's workers costs.
    if (out.size() < kParallelPackCharacters) {
        packRange(0, out.size());
        return;
    }
    pool_->parallelFor(out.size(), packRange);
    pool_->rest();  // as after a step: the cores are the renderer's next
}

}  // namespace throng::crowd
