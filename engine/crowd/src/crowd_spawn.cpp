// Spawning: seeded placement without overlaps, per-character draws, and the checks that
// refuse a setup that doesn't make sense.
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "crowd_internal.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/crowd.h"

namespace throng::crowd {
namespace {

// What errors call group `index`: its name, else its index.
std::string groupName(const GroupSpec& group, std::size_t index) { return group.name.empty() ? "group " + std::to_string(index) : group.name; }

using detail::randomPointIn;
using detail::shown;
using detail::yawToward;

// Pleasant, distinguishable clothing colours: hue spread evenly, fairly saturated.
std::uint32_t characterColor(Rng& rng) {
    const float hue = rng.uniform() * 6.0F;
    const float saturation = rng.uniform(0.55F, 0.85F), value = rng.uniform(0.6F, 0.95F);
    const float c = value * saturation, x = c * (1.0F - std::abs(std::fmod(hue, 2.0F) - 1.0F)), m = value - c;
    glm::vec3 rgb;
    switch (static_cast<int>(hue)) {
        case 0: rgb = {c, x, 0}; break;
        case 1: rgb = {x, c, 0}; break;
        case 2: rgb = {0, c, x}; break;
        case 3: rgb = {0, x, c}; break;
        case 4: rgb = {x, 0, c}; break;
        default: rgb = {c, 0, x}; break;
    }
    rgb += m;
    const auto byte = [](float v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0F, 1.0F) * 255.0F)); };
    return byte(rgb.r) | (byte(rgb.g) << 8U) | (byte(rgb.b) << 16U) | (255U << 24U);
}

// Placed bodies bucketed on a coarse grid, so each dart tests only its neighbourhood.
class PlacementGrid {
public:
    explicit PlacementGrid(float cell) : cell_(cell) {}
    [[nodiscard]] bool isFree(glm::vec2 p, float radius, std::span<const glm::vec2> placed, std::span<const float> radii) const {
        const auto [cx, cy] = cellOf(p);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const auto found = cells_.find(key(cx + dx, cy + dy));
                if (found == cells_.end()) continue;
                for (std::uint32_t j : found->second)
                    if (glm::length(placed[j] - p) < radius + radii[j]) return false;
            }
        return true;
    }
    void add(glm::vec2 p, std::uint32_t index) {
        const auto [cx, cy] = cellOf(p);
        cells_[key(cx, cy)].push_back(index);
    }

private:
    [[nodiscard]] std::pair<int, int> cellOf(glm::vec2 p) const {
        constexpr int kLimit = 1 << 30;  // cells this far out are one cell: dart tests stay correct, only slower
        return {clampedFloor(p.x / cell_, -kLimit, kLimit), clampedFloor(p.y / cell_, -kLimit, kLimit)};
    }
    static std::int64_t key(int x, int y) { return (static_cast<std::int64_t>(x) << 32) ^ static_cast<std::uint32_t>(y); }
    float cell_;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

// A group's own mistakes: no characters, a clip or set that doesn't exist, empty ranges.
std::optional<Error> checkGroup(const GroupSpec& group, const std::string& which, std::span<const motion::BakedClip> clips,
                                const CrowdSetup& setup) {
    if (group.count < 1) return Error{Error::Kind::BadInput, which + " needs at least one character", {}};
    for (std::uint32_t c : group.clips)
        if (c >= clips.size()) return Error{Error::Kind::BadInput, which + " names clip " + std::to_string(c) + ", which doesn't exist", {}};
    if (!(group.region.size.x > 0 && group.region.size.y > 0))
        return Error{Error::Kind::BadInput, which + " has an empty spawn region", {}};
    if (!(group.speedRange.x > 0 && group.speedRange.y >= group.speedRange.x))
        return Error{Error::Kind::BadInput, which + " needs a speed range with 0 < min <= max", {}};
    if (!(group.pause.x >= 0 && group.pause.y >= group.pause.x && group.pause.y <= range::kMaxTimeSeconds))
        return Error{Error::Kind::BadInput, which + " needs a pause range with 0 <= min <= max <= " +
                                                std::to_string(static_cast<int>(range::kMaxTimeSeconds)) + " s", {}};
    if (group.mode == Mode::Follow && (!setup.trajectories || !group.locomotion))
        return Error{Error::Kind::BadInput, which + " follows trajectories: it needs the setup's trajectories and a locomotion set", {}};
    return Crowd::checkLocomotion(group, which, clips, setup);
}

// Mode::Follow groups take tracks in order: there must be enough of them.
std::optional<Error> checkFollowers(const CrowdSetup& setup) {
    std::size_t followers = 0;
    for (const GroupSpec& group : setup.groups)
        if (group.mode == Mode::Follow) followers += static_cast<std::size_t>(group.count);
    if (followers == 0 || followers <= setup.trajectories->tracks.size()) return std::nullopt;
    return Error{Error::Kind::BadInput, std::to_string(followers) + " characters follow trajectories, but the file has " +
                                            std::to_string(setup.trajectories->tracks.size()) + " tracks", {}};
}

}  // namespace

std::optional<Error> Crowd::checkSetup(std::span<const motion::BakedClip> clips, const CrowdSetup& setup) {
    // Groups first: the events' checks read the clips and sets the groups name.
    for (std::size_t g = 0; g < setup.groups.size(); ++g)
        if (std::optional<Error> bad = checkGroup(setup.groups[g], groupName(setup.groups[g], g), clips, setup)) return *bad;
    if (std::optional<Error> bad = checkEvents(clips, setup)) return *bad;
    if (setup.threads == 0) {  // the pool's size comes from THRONG_THREADS, refused as an error here, not thrown later
        try {
            (void)defaultThreadCount();
        } catch (const ThrongException& refused) {
            return refused.error();
        }
    }
    return checkFollowers(setup);
}

void Crowd::startFollowing(std::span<const motion::BakedClip> clips) {
    if (track_.empty()) return;
    track_.resize(ground_.size(), -1);
    for (std::size_t i = 0; i < ground_.size(); ++i)
        if (track_[i] >= 0) follow(clips, i, 0.0);
}

void Crowd::appendMotion(std::span<const motion::BakedClip> clips, const CrowdSetup& setup, std::size_t g, std::uint32_t clip, float scale,
                         Rng& rng) {
    const GroupSpec& group = setup.groups[g];
    const motion::LocomotionSet* set = group.locomotion ? &setup.locomotion[*group.locomotion] : nullptr;
    const std::size_t i = set_.size();
    set_.push_back(set != nullptr ? static_cast<std::int32_t>(*group.locomotion) : -1);
    // Only a set's characters draw a speed, so crowds without one keep their streams.
    const float wanted = set != nullptr ? std::clamp(rng.uniform(group.groundSpeed.x, group.groundSpeed.y),
                                                     static_cast<float>(set->slowest()) * scale, static_cast<float>(set->fastest()) * scale)
                                        : 0.0F;
    desiredSpeed_.push_back(wanted);
    speed_.push_back(wanted);
    blendClip_.push_back(clip);
    blendFrame_.push_back(frame_.back());
    blend_.push_back(0.0F);
    fromClip_.push_back(clip);
    fromFrame_.push_back(frame_.back());
    fromWeight_.push_back(0.0F);
    fadeRate_.push_back(0.0F);
    fromPlayback_.push_back(1.0F);
    waiting_.emplace_back();
    group_.push_back(static_cast<std::uint32_t>(g));
    pauseLeft_.push_back(0.0F);
    if (set != nullptr) startBlend(clips, i, rng_.back().uniform());
}

Result<Crowd> Crowd::spawn(std::span<const motion::BakedClip> clips, const CrowdSetup& setup,
                           const LocomotionParameters& parameters) {
    if (clips.empty()) return Error{Error::Kind::BadInput, "a crowd needs at least one clip", {}};
    if (setup.groups.empty()) return Error{Error::Kind::BadInput, "a crowd needs at least one group", {}};
    Crowd crowd;
    crowd.parameters_ = parameters;
    crowd.waypoints_ = setup.waypoints;
    crowd.sets_ = setup.locomotion;
    crowd.area_ = setup.area;
    crowd.groups_ = setup.groups;
    for (const motion::BakedClip& clip : clips) crowd.clocks_.push_back(motion::GaitClock::of(clip));
    if (std::optional<Error> bad = checkSetup(clips, setup)) return *bad;
    crowd.trajectories_ = setup.trajectories;
    std::size_t nextTrack = 0;
    crowd.events_ = setup.events;
    std::stable_sort(crowd.events_.begin(), crowd.events_.end(), [](const CrowdEvent& a, const CrowdEvent& b) { return a.time < b.time; });
    float largestRadius = 0.0F;
    for (const motion::BakedClip& clip : clips)
        largestRadius = std::max(largestRadius, static_cast<float>(clip.stature) * parameters.bodyRadiusPerHeight * 1.05F);
    PlacementGrid grid(2.0F * largestRadius + 0.01F);
    Rng rng(setup.seed);
    for (std::size_t g = 0; g < setup.groups.size(); ++g) {
        const GroupSpec& group = setup.groups[g];
        const std::string which = groupName(group, g);
        const motion::LocomotionSet* set = group.locomotion ? &setup.locomotion[*group.locomotion] : nullptr;
        for (int k = 0; k < group.count; ++k) {
            const std::size_t i = crowd.ground_.size();
            const std::uint32_t clip = set != nullptr        ? set->gaits.front().clip
                                       : group.clips.empty() ? static_cast<std::uint32_t>(i % clips.size())
                                                             : group.clips[static_cast<std::size_t>(k) % group.clips.size()];
            const float scale = rng.uniform(0.95F, 1.05F);
            const float radius = static_cast<float>(clips[clip].stature) * parameters.bodyRadiusPerHeight * scale;
            // Dart throwing: bounded attempts, so an overfull region is an error, never a hang.
            // A follower starts where its track does (follow() places it from then on).
            const Track* track = group.mode == Mode::Follow ? &setup.trajectories->tracks[nextTrack++] : nullptr;
            glm::vec2 position = track != nullptr ? glm::vec2(track->samples.front().position) : glm::vec2(0.0F);
            bool placed = track != nullptr;
            for (int attempt = 0; attempt < 200 && !placed; ++attempt) {
                position = randomPointIn(group.region, rng);
                placed = grid.isFree(position, radius, crowd.positions_, crowd.radius_);
            }
            if (!placed)
                return Error{Error::Kind::BadInput,
                             which + ": its " + shown(group.region.size.x) + " x " + shown(group.region.size.y) +
                                 " m region is too small for " + std::to_string(group.count) + " characters (placed " +
                                 std::to_string(k) + " without overlaps)",
                             {}};
            if (track == nullptr) grid.add(position, static_cast<std::uint32_t>(i));
            crowd.positions_.push_back(position);
            crowd.radius_.push_back(radius);
            const motion::LoopRange loop = clips[clip].loop();
            crowd.frame_.push_back(loop.first + static_cast<double>(rng.uniform()) * std::max(loop.length(), 0));
            crowd.clip_.push_back(clip);
            crowd.mode_.push_back(group.mode);
            crowd.baseSpeed_.push_back(rng.uniform(group.speedRange.x, group.speedRange.y));
            crowd.playback_.push_back(crowd.baseSpeed_.back());
            crowd.scale_.push_back(scale);
            crowd.color_.push_back(characterColor(rng));
            crowd.rng_.emplace_back(setup.seed, 0x5851f42d4c957f2dULL + i);
            crowd.goal_.push_back(position);
            crowd.waypoint_.push_back(crowd.waypoints_.empty() ? 0U : crowd.rng_.back().below(static_cast<std::uint32_t>(crowd.waypoints_.size())));
            crowd.velocity_.emplace_back(0.0F);
            crowd.turnVelocity_.push_back(0.0F);
            crowd.footTwist_.emplace_back(0.0F);
            crowd.appendMotion(clips, setup, g, clip, scale, rng);
            crowd.ground_.push_back({glm::dvec2(position), group.heading});
            if (track != nullptr) {
                crowd.prepareFollowing(i, *track, crowd.rng_.back().uniform());
            } else if (group.mode != Mode::Group) {
                crowd.pickGoal(i);
                crowd.ground_.back().yaw = yawToward(crowd.goal_[i] - position);
            }
        }
    }
    crowd.desired_.assign(crowd.ground_.size(), glm::vec2(0.0F));
    crowd.fastest_.assign(crowd.ground_.size(), -1.0F);
    crowd.startFollowing(clips);
    crowd.applyEvents(clips);  // those at time 0
    crowd.pool_ = std::make_shared<ThreadPool>(setup.threads);
    return crowd;
}

}  // namespace throng::crowd
