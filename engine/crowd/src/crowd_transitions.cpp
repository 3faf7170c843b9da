// Transitions, events, starting and stopping: a character crossfades from what it shows to
// another clip or set (the outgoing clip keeps step with the incoming gait), groups change
// what they play at scheduled times, and a character of a set with an idle slows to stand at
// its goal, pauses, and sets off for the next.
#include <algorithm>
#include <cmath>
#include <string>

#include "crowd_internal.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/crowd.h"

namespace throng::crowd {
namespace {

// At or below this a character of a set stands (m/s): braking reaches 0 exactly.
constexpr float kStandingSpeed = 1e-3F;
// A character braking for its goal plans to stand this far short of it (metres).
constexpr float kStopShort = 0.3F;
// A clip weighing less than this in the pose is not shown (for when a fade may start): the
// speed a blend glides to is stored as a float, so its weight lands within ~1e-6 of 0 or 1,
// and dropping 1e-3 of a pose moves a joint well under a millimetre.
constexpr double kNegligibleWeight = 1e-3;

// The clips a group's characters may show at spawn.
std::vector<std::uint32_t> groupClips(const GroupSpec& group, std::span<const motion::BakedClip> clips, const CrowdSetup& setup) {
    if (group.locomotion) {
        const motion::LocomotionSet& set = setup.locomotion[*group.locomotion];
        std::vector<std::uint32_t> out;
        for (const motion::LocomotionClip& gait : set.gaits) out.push_back(gait.clip);
        if (set.idle) out.push_back(set.idle->clip);
        return out;
    }
    if (!group.clips.empty()) return group.clips;
    std::vector<std::uint32_t> every(clips.size());
    for (std::uint32_t c = 0; c < every.size(); ++c) every[c] = c;
    return every;
}

}  // namespace

std::optional<Error> Crowd::checkEvents(std::span<const motion::BakedClip> clips, const CrowdSetup& setup) {
    for (std::size_t e = 0; e < setup.events.size(); ++e) {
        const CrowdEvent& event = setup.events[e];
        const std::string which = "event " + std::to_string(e);
        const auto bad = [&](const std::string& what) { return Error{Error::Kind::BadInput, which + " " + what, {}}; };
        if (!(event.time >= 0 && event.time <= range::kMaxTimeSeconds))
            return bad("needs a time from 0 to " + std::to_string(static_cast<int>(range::kMaxTimeSeconds)) + " s");
        if (event.group >= setup.groups.size()) return bad("names group " + std::to_string(event.group) + ", which doesn't exist");
        if (event.clip && event.locomotion) return bad("both plays a clip and blends a set: give one");
        if (event.clip && event.groundSpeed)
            return bad("plays a clip alone, which walks at its own pace: a ground speed needs a set to blend");
        if (event.clip && *event.clip >= clips.size()) return bad("names clip " + std::to_string(*event.clip) + ", which doesn't exist");
        if (event.locomotion) {
            GroupSpec blends;
            blends.locomotion = event.locomotion;
            if (std::optional<Error> unusable = checkLocomotion(blends, which, clips, setup)) return unusable;
        }
        if (!(event.fade >= 0 && event.fade <= CrowdEvent::kLongestFade))
            return bad("needs a fade from 0 to " + std::to_string(static_cast<int>(CrowdEvent::kLongestFade)) + " s");
        if (event.groundSpeed && !(event.groundSpeed->x >= 0 && event.groundSpeed->y >= event.groundSpeed->x &&
                                   event.groundSpeed->y <= range::kLargestSpeed))
            return bad("needs a ground speed range with 0 <= min <= max <= " + std::to_string(static_cast<int>(range::kLargestSpeed)) + " m/s");
        // A crossfade mixes joint by joint: the incoming clips must have the group's skeleton.
        const std::vector<std::uint32_t> shownClips = groupClips(setup.groups[event.group], clips, setup);
        const std::uint32_t incoming = event.clip ? *event.clip
                                       : event.locomotion ? setup.locomotion[*event.locomotion].gaits.front().clip
                                                          : shownClips.front();
        for (std::uint32_t shown : shownClips)
            if (clips[shown].jointCount() != clips[incoming].jointCount())
                return bad("crossfades group " + std::to_string(event.group) + " between clips of different skeletons (" +
                           std::to_string(clips[shown].jointCount()) + " and " + std::to_string(clips[incoming].jointCount()) + " joints)");
    }
    return std::nullopt;
}

void Crowd::applyEvents(std::span<const motion::BakedClip> clips) {
    while (nextEvent_ < events_.size() && events_[nextEvent_].time <= time_ + 1e-9) {
        const CrowdEvent event = events_[nextEvent_++];
        for (std::size_t i = 0; i < ground_.size(); ++i) {
            if (group_[i] != event.group) continue;
            if (event.clip) playClip(clips, static_cast<int>(i), *event.clip, event.fade);
            if (event.locomotion) blendSet(clips, static_cast<int>(i), *event.locomotion, event.fade);
            if (!event.groundSpeed) continue;
            // A set that waits to start takes its speed when it does (in its own range).
            if (waiting_[i].kind == Waiting::Kind::Set)
                waiting_[i].groundSpeed = rng_[i].uniform(event.groundSpeed->x, event.groundSpeed->y);
            else if (set_[i] >= 0)
                setDesiredSpeed(static_cast<int>(i), rng_[i].uniform(event.groundSpeed->x, event.groundSpeed->y));
        }
    }
}

bool Crowd::showsOneClip(std::size_t i) const {
    const PoseMix mix = poseMix(i);
    return std::count_if(mix.weight.begin(), mix.weight.begin() + mix.count, [](double w) { return w > kNegligibleWeight; }) <= 1;
}

double Crowd::beginTransition(std::size_t i, float fade) {
    const PoseMix mix = poseMix(i);
    const int heaviest = static_cast<int>(std::max_element(mix.weight.begin(), mix.weight.begin() + mix.count) - mix.weight.begin());
    const std::uint32_t clip = mix.clip[static_cast<std::size_t>(heaviest)];
    const double frame = mix.frame[static_cast<std::size_t>(heaviest)];
    const std::optional<motion::GaitClock>& clock = clocks_[clip];
    // A running transition whose outgoing clip still dominates keeps it: replacing it by a
    // lighter pose would jump.
    if (fade > 0 && !(fromWeight_[i] >= 0.5F)) {
        // Without a gait to keep step by, the outgoing clip runs on at the rate it ran.
        double rate = playback_[i];
        if (set_[i] >= 0 && clock) rate = motion::blendForSpeed(sets_[static_cast<std::size_t>(set_[i])], speed_[i] / scale_[i]).cyclesPerSecond * clock->cycleSeconds();
        fromClip_[i] = clip;
        fromFrame_[i] = frame;
        fromWeight_[i] = 1.0F;
        fromPlayback_[i] = static_cast<float>(rate);
    }
    fadeRate_[i] = fade > 0 ? 1.0F / fade : 0.0F;
    if (fade <= 0) fromWeight_[i] = 0.0F;
    return clock ? detail::fraction(clock->cyclesAt(frame)) : -1.0;
}

void Crowd::playClip(std::span<const motion::BakedClip> clips, int character, std::uint32_t clip, float fade) {
    const std::size_t i = at(character);
    if (i >= ground_.size() || clip >= clips.size() || clip >= clocks_.size() || !(fade >= 0 && fade <= CrowdEvent::kLongestFade)) return;
    if (fade > 0 && !showsOneClip(i)) {
        waiting_[i] = {Waiting::Kind::Clip, clip, fade};
        return;
    }
    startClip(clips, i, clip, fade);
}

void Crowd::blendSet(std::span<const motion::BakedClip> clips, int character, std::uint32_t set, float fade) {
    const std::size_t i = at(character);
    if (i >= ground_.size() || set >= sets_.size() || !(fade >= 0 && fade <= CrowdEvent::kLongestFade)) return;
    if (set_[i] == static_cast<std::int32_t>(set)) {
        waiting_[i] = {};  // already blending it (or fading into it): nothing to start or wait for
        return;
    }
    if (fade > 0 && !showsOneClip(i)) {
        waiting_[i] = {Waiting::Kind::Set, set, fade};
        return;
    }
    startSet(clips, i, set, fade);
}

void Crowd::startWaitingTransition(std::span<const motion::BakedClip> clips, std::size_t i) {
    if (waiting_[i].kind == Waiting::Kind::None || !showsOneClip(i)) return;
    const Waiting waiting = waiting_[i];
    if (waiting.kind == Waiting::Kind::Clip) {
        startClip(clips, i, waiting.target, waiting.fade);
        return;
    }
    startSet(clips, i, waiting.target, waiting.fade);
    if (waiting.groundSpeed >= 0) setDesiredSpeed(static_cast<int>(i), waiting.groundSpeed);
}

double Crowd::glideForWaitingTransition(std::size_t i, double targetSpeed) {
    if (waiting_[i].kind == Waiting::Kind::None || set_[i] < 0 || !(blend_[i] > 0.0F && blend_[i] < 1.0F)) return targetSpeed;
    if (waiting_[i].glideTo < 0) {
        // Onto whichever of the blend's two clips is nearer the speed wanted now: at a clip's
        // own speed the blend is that clip alone (motion::blendForSpeed). Chosen once, so a
        // wanted speed that wavers about the middle (avoidance, braking) can't keep it between.
        const motion::LocomotionSet& set = sets_[static_cast<std::size_t>(set_[i])];
        const auto speedOf = [&](std::uint32_t clip) {
            for (const motion::LocomotionClip& gait : set.gaits)
                if (gait.clip == clip) return gait.speed * scale_[i];
            return 0.0;  // the idle
        };
        const double lower = speedOf(clip_[i]), upper = speedOf(blendClip_[i]);
        const double wanted = std::isfinite(targetSpeed) ? targetSpeed : speed_[i];
        waiting_[i].glideTo = static_cast<float>(std::abs(wanted - lower) < std::abs(wanted - upper) ? lower : upper);
    }
    return waiting_[i].glideTo;
}

void Crowd::startClip(std::span<const motion::BakedClip> clips, std::size_t i, std::uint32_t clip, float fade) {
    waiting_[i] = {};
    const double phase = beginTransition(i, fade);
    const motion::BakedClip& next = clips[clip];
    set_[i] = -1;
    pauseLeft_[i] = 0.0F;  // a clip played alone doesn't stand at goals
    clip_[i] = clip;
    frame_[i] = phase >= 0 && clocks_[clip] ? next.rootMotion.wrap(clocks_[clip]->frameAt(phase)) : static_cast<double>(next.loop().first);
    blendClip_[i] = clip;
    blendFrame_[i] = frame_[i];
    blend_[i] = 0.0F;
    playback_[i] = baseSpeed_[i];
}

void Crowd::startSet(std::span<const motion::BakedClip> clips, std::size_t i, std::uint32_t set, float fade) {
    waiting_[i] = {};
    const bool blended = set_[i] >= 0;
    // It goes on at the pace it walks now, within what the new set can show.
    const float now = blended ? speed_[i] : static_cast<float>(clipSpeed(clips[clip_[i]])) * scale_[i] * playback_[i];
    const double phase = beginTransition(i, fade);
    set_[i] = static_cast<std::int32_t>(set);
    const motion::LocomotionSet& next = sets_[set];
    if (!next.idle) pauseLeft_[i] = 0.0F;  // a set with no idle can't stand out a pause
    const auto within = [&](float v) {
        return std::clamp(v, static_cast<float>(next.slowest()) * scale_[i], static_cast<float>(next.fastest()) * scale_[i]);
    };
    speed_[i] = within(now);
    desiredSpeed_[i] = blended ? within(desiredSpeed_[i]) : speed_[i];
    startBlend(clips, i, phase >= 0 ? phase : 0.0);
}

void Crowd::crossfade(std::span<const motion::BakedClip> clips, double seconds, std::size_t i, Played& played) {
    if (!(fromWeight_[i] > 0)) return;
    const motion::BakedClip& from = clips[fromClip_[i]];
    const std::optional<motion::GaitClock>& clock = clocks_[fromClip_[i]];
    double to = fromFrame_[i] + seconds / from.frameTime * fromPlayback_[i];
    if (clock && played.cycles >= 0) {
        // In step with the incoming gait: the same number of cycles, so the feet agree.
        const double cycles = clock->cyclesAt(fromFrame_[i]);
        to = fromFrame_[i] + (clock->frameAt(cycles + played.cycles) - clock->frameAt(cycles));
    }
    const motion::GroundFrame step = from.rootMotion.delta(fromFrame_[i], to);
    fromFrame_[i] = from.rootMotion.wrap(to);
    const double before = fromWeight_[i];
    fromWeight_[i] = static_cast<float>(std::max(0.0, before - seconds * fadeRate_[i]));
    // The root motion mixes at the step's mean weight, the pose at its end.
    const double w = 0.5 * (before + fromWeight_[i]);
    played.delta = {played.delta.position * (1.0 - w) + step.position * w, played.delta.yaw * (1.0 - w) + step.yaw * w};
    if (w >= 0.5) {
        played.clip = fromClip_[i];
        played.frame = fromFrame_[i];
    }
}

float Crowd::approachSpeed(std::size_t i, float distance, float headingError) const {
    if (pauseLeft_[i] > 0) return 0.0F;
    // A sharp turn is taken slowly: someone about to walk off the other way turns first.
    float speed = desiredSpeed_[i] * std::clamp(fastCos(headingError), 0.25F, 1.0F);
    if (sets_[static_cast<std::size_t>(set_[i])].idle) {
        // The fastest speed from which braking still stands at the goal, planned at half the
        // set's acceleration: the weights (so the speed) hold still while both feet are down.
        speed = std::min(speed, std::sqrt(parameters_.acceleration * std::max(0.0F, distance - kStopShort)));
    }
    return speed;
}

void Crowd::arrive(std::size_t i, double seconds) {
    if (pauseLeft_[i] > 0) {
        pauseLeft_[i] = static_cast<float>(std::max(0.0, pauseLeft_[i] - seconds));
        return;
    }
    const float distance = glm::length(goal_[i] - glm::vec2(ground_[i].position));
    const bool stands = set_[i] >= 0 && sets_[static_cast<std::size_t>(set_[i])].idle.has_value();
    if (!stands) {
        if (distance < parameters_.arrivalRadius) pickGoal(i);
        return;
    }
    if (distance < parameters_.arrivalRadius && speed_[i] <= kStandingSpeed) {
        // It stands, then turns toward the next goal (taken now) and sets off when the pause ends.
        const glm::vec2 pause = groups_[group_[i]].pause;
        pauseLeft_[i] = rng_[i].uniform(pause.x, pause.y);
        pickGoal(i);
    }
}

}  // namespace throng::crowd
