// Speed blending: a character of a locomotion set plays two of its clips at one gait phase,
// weighted so that the blend walks at the character's speed (motion::blendForSpeed), and moves
// by the same blend of the two clips' root motion, so the ground speed is what the pose shows.
#include <algorithm>
#include <cmath>

#include "crowd_internal.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/crowd.h"

namespace throng::crowd {

using detail::fraction;
using detail::nearestWhole;

std::optional<Error> Crowd::checkLocomotion(const GroupSpec& group, const std::string& which, std::span<const motion::BakedClip> clips,
                                            const CrowdSetup& setup) {
    if (!group.locomotion) return std::nullopt;
    if (*group.locomotion >= setup.locomotion.size())
        return Error{Error::Kind::BadInput, which + " names locomotion set " + std::to_string(*group.locomotion) + ", which doesn't exist", {}};
    const motion::LocomotionSet* set = &setup.locomotion[*group.locomotion];
    const auto inTable = [&](const motion::LocomotionClip& c) { return c.clip < clips.size(); };
    if (set->gaits.empty() || !std::all_of(set->gaits.begin(), set->gaits.end(), inTable) || (set->idle && !inTable(*set->idle)))
        return Error{Error::Kind::BadInput, which + "'s locomotion set names a clip that doesn't exist", {}};
    // As makeLocomotionSet leaves it: every gait timed, travelling, faster than the one before.
    for (std::size_t k = 0; k < set->gaits.size(); ++k)
        if (!set->gaits[k].gait || !(set->gaits[k].speed > (k == 0 ? 0.0 : set->gaits[k - 1].speed)))
            return Error{Error::Kind::BadInput, which + "'s locomotion set is not one makeLocomotionSet made", {}};
    if (!(group.groundSpeed.x >= 0 && group.groundSpeed.y >= group.groundSpeed.x && group.groundSpeed.y <= range::kLargestSpeed))
        return Error{Error::Kind::BadInput, which + " needs a ground speed range with 0 <= min <= max <= " +
                                                std::to_string(static_cast<int>(range::kLargestSpeed)) + " m/s", {}};
    return std::nullopt;
}

Crowd::Played Crowd::advance(std::span<const motion::BakedClip> clips, double seconds, std::size_t i, double targetSpeed) {
    targetSpeed = glideForWaitingTransition(i, targetSpeed);
    // One clip alone, no transition: the paper's playback, untouched.
    const bool mixes = set_[i] >= 0 || fromWeight_[i] > 0;
    const PoseMix before = mixes ? poseMix(i) : PoseMix{};
    Played played = set_[i] >= 0 ? advanceBlend(clips, seconds, i, targetSpeed) : advanceClip(clips, seconds, i);
    crossfade(clips, seconds, i, played);
    if (mixes) played.delta.position -= heldFootSlide(clips, before, poseMix(i));
    return played;
}

Crowd::Played Crowd::advanceClip(std::span<const motion::BakedClip> clips, double seconds, std::size_t i) {
    const motion::BakedClip& clip = clips[clip_[i]];
    const double from = frame_[i];
    const double to = from + seconds / clip.frameTime * playback_[i];
    frame_[i] = clip.rootMotion.wrap(to);
    Played played{clip.rootMotion.delta(from, to), clip_[i], frame_[i]};
    // Gait cycles played, for a transition's outgoing clip to keep step with.
    const std::optional<motion::GaitClock>& clock = clocks_[clip_[i]];
    if (fromWeight_[i] > 0 && clock) played.cycles = clock->cyclesAt(to) - clock->cyclesAt(from);
    return played;
}

Crowd::PoseMix Crowd::poseMix(std::size_t i) const {
    PoseMix mix;
    const auto add = [&](std::uint32_t clip, double frame, double weight) {
        if (!(weight > 0)) return;
        const auto k = static_cast<std::size_t>(mix.count++);
        mix.clip[k] = clip;
        mix.frame[k] = frame;
        mix.weight[k] = weight;
    };
    const double from = fromWeight_[i], blend = blend_[i];
    add(clip_[i], frame_[i], (1.0 - from) * (1.0 - blend));
    add(blendClip_[i], blendFrame_[i], (1.0 - from) * blend);
    add(fromClip_[i], fromFrame_[i], from);
    return mix;
}

glm::dvec2 Crowd::heldFootSlide(std::span<const motion::BakedClip> clips, const PoseMix& before, const PoseMix& after) {
    // A foot's place in the ground frame is the weighted sum of where each clip shown puts it
    // (translations mix linearly), so changing a weight by dw moves it by dw times that clip's
    // place less the blended place: the slide a held foot would make. Weights are matched by
    // clip, so a pair that hands over at an end (the leaving clip at weight 0) slides nothing.
    std::array<double, 3> change{};
    bool changed = false;
    for (int k = 0; k < after.count; ++k) {
        const auto ku = static_cast<std::size_t>(k);
        double prior = 0.0, shared = 0.0;
        for (int j = 0; j < before.count; ++j)
            if (before.clip[static_cast<std::size_t>(j)] == after.clip[ku]) prior += before.weight[static_cast<std::size_t>(j)];
        for (int j = 0; j < after.count; ++j)
            if (after.clip[static_cast<std::size_t>(j)] == after.clip[ku]) shared += after.weight[static_cast<std::size_t>(j)];
        change[ku] = after.weight[ku] * (1.0 - prior / shared);  // exactly 0 when nothing changed
        changed = changed || change[ku] != 0.0;
    }
    if (!changed) return glm::dvec2(0.0);
    const auto shown = [&](int k) -> const motion::BakedClip& { return clips[after.clip[static_cast<std::size_t>(k)]]; };
    const auto everyShown = [&](const auto& holds) {
        for (int k = 0; k < after.count; ++k)
            if (!holds(shown(k))) return false;
        return true;
    };
    const int joints = shown(0).jointCount();
    if (!everyShown([joints](const motion::BakedClip& clip) { return clip.jointCount() == joints; })) return glm::dvec2(0.0);
    // Planted in the blend only where every clip shown has it planted.
    glm::dvec2 hold(1.0);
    for (int k = 0; k < after.count; ++k) hold = glm::min(hold, shown(k).footHoldAt(after.frame[static_cast<std::size_t>(k)]));
    if (hold.x <= 0.0 && hold.y <= 0.0) return glm::dvec2(0.0);  // both feet in flight: nothing held to slide
    std::array<std::array<glm::dvec2, 2>, 3> place{};  // per clip shown, per leg
    for (int k = 0; k < after.count; ++k) place[static_cast<std::size_t>(k)] = shown(k).anklesAt(after.frame[static_cast<std::size_t>(k)]);
    glm::dvec2 slide(0.0);
    double held = 0.0;
    for (std::size_t l = 0; l < 2; ++l) {
        const double legHold = hold[static_cast<glm::length_t>(l)];
        // A leg some clip shown has no ankle for (a skeleton of the same joint count, built
        // otherwise) has no place to hold.
        if (legHold <= 0.0 || !everyShown([l](const motion::BakedClip& clip) { return clip.anatomy.legs[l].ankle >= 0; })) continue;
        glm::dvec2 blended(0.0);
        for (int k = 0; k < after.count; ++k) blended += after.weight[static_cast<std::size_t>(k)] * place[static_cast<std::size_t>(k)][l];
        glm::dvec2 moved(0.0);
        for (int k = 0; k < after.count; ++k)
            moved += change[static_cast<std::size_t>(k)] * (place[static_cast<std::size_t>(k)][l] - blended);
        slide += legHold * moved;
        held += legHold;
    }
    // One foot held: it stays put; both: they share the correction; in flight: none.
    return slide / std::max(1.0, held);
}

void Crowd::setDesiredSpeed(int i, float metresPerSecond) {
    const std::size_t c = at(i);
    if (set_[c] < 0 || !std::isfinite(metresPerSecond)) return;
    const motion::LocomotionSet& set = sets_[static_cast<std::size_t>(set_[c])];
    desiredSpeed_[c] = std::clamp(metresPerSecond, static_cast<float>(set.slowest()) * scale_[c], static_cast<float>(set.fastest()) * scale_[c]);
}

void Crowd::startBlend(std::span<const motion::BakedClip> clips, std::size_t i, double phase) {
    const motion::LocomotionSet& set = sets_[static_cast<std::size_t>(set_[i])];
    const motion::SpeedBlend blend = motion::blendForSpeed(set, speed_[i] / scale_[i]);
    // The same gait phase for both clips; the idle, which has none, that far into its loop.
    const auto frameAtPhase = [&](const motion::LocomotionClip& member) {
        const motion::BakedClip& clip = clips[member.clip];
        if (!member.gait) return clip.loop().first + phase * clip.loop().length();
        return clip.rootMotion.wrap(member.gait->frameAt(phase));
    };
    showBlend(i, blend, frameAtPhase(*blend.lower), frameAtPhase(*blend.upper));
}

void Crowd::showBlend(std::size_t i, const motion::SpeedBlend& blend, double lowerFrame, double upperFrame) {
    clip_[i] = blend.lower->clip;
    frame_[i] = lowerFrame;
    blendClip_[i] = blend.upper->clip;
    blendFrame_[i] = upperFrame;
    blend_[i] = static_cast<float>(blend.weight);
    playback_[i] = static_cast<float>(blend.playback);
}

Crowd::Played Crowd::advanceBlend(std::span<const motion::BakedClip> clips, double seconds, std::size_t i, double targetSpeed) {
    const motion::LocomotionSet& set = sets_[static_cast<std::size_t>(set_[i])];
    // The speed follows the wanted one at a bounded acceleration, so the blend's weights glide.
    const double scale = scale_[i];
    const double wanted = std::isfinite(targetSpeed) ? std::clamp(targetSpeed, set.slowest() * scale, set.fastest() * scale) : speed_[i];
    // The weights only change while a foot is free: with both feet planted (double support in
    // every clip shown) a changing weight would drag one of them, so the speed holds until one lifts.
    const auto held = [&](std::uint32_t clip, double frame) { return clips[clip].footHoldAt(frame); };
    const glm::dvec2 planted = glm::min(held(clip_[i], frame_[i]), held(blendClip_[i], blendFrame_[i]));
    const double most = parameters_.acceleration * seconds * (1.0 - std::min(planted.x, planted.y));
    speed_[i] = static_cast<float>(speed_[i] + std::clamp(wanted - speed_[i], -most, most));
    const motion::SpeedBlend blend = motion::blendForSpeed(set, speed_[i] / scale);

    // Where each clip of the new pair is: a clip already playing goes on from its frame; one that
    // joins (at weight 0, as the speed passes a clip's own) starts at the gait phase shown.
    // blendClip_ is always a gait of the set (startBlend and every step put one there).
    const auto frameOf = [&](const motion::LocomotionClip& member) {
        if (member.clip == clip_[i]) return frame_[i];
        if (member.clip == blendClip_[i]) return blendFrame_[i];
        // Only now, as a clip joins, is the phase shown needed (most steps keep their pair).
        const auto shown = std::find_if(set.gaits.begin(), set.gaits.end(), [&](const motion::LocomotionClip& g) { return g.clip == blendClip_[i]; });
        const double shownPhase = shown == set.gaits.end() ? 0.0 : fraction(shown->gait->cyclesAt(blendFrame_[i]));
        const motion::BakedClip& clip = clips[member.clip];
        return member.gait ? clip.rootMotion.wrap(member.gait->frameAt(shownPhase)) : static_cast<double>(clip.loop().first);
    };
    // Both gaits advance by the same number of cycles, at the blend's cadence; the idle keeps
    // its own time. frameAt(cyclesAt(f)) is f (to rounding), so each gait's new frame is its
    // clock read at the gait time reached.
    const double cycles = blend.cyclesPerSecond * seconds;
    const double upperFrom = frameOf(*blend.upper), lowerFrom = frameOf(*blend.lower);
    const motion::BakedClip& lower = clips[blend.lower->clip];
    const motion::BakedClip& upper = clips[blend.upper->clip];
    double upperTo = 0.0, lowerTo = 0.0;
    if (!blend.upper->gait) {
        upperTo = upperFrom + seconds / upper.frameTime;  // no gait to keep in step: each keeps its own time
        lowerTo = lowerFrom + seconds / lower.frameTime;
    } else {
        const double upperCycles = blend.upper->gait->cyclesAt(upperFrom) + cycles;
        upperTo = blend.upper->gait->frameAt(upperCycles);
        if (blend.lower == blend.upper) {
            lowerTo = upperTo;
        } else if (!blend.lower->gait) {
            lowerTo = lowerFrom + seconds / lower.frameTime;
        } else {
            // The slower gait lands on the faster's phase, so rounding never lets the two drift apart.
            const double lowerCycles = blend.lower->gait->cyclesAt(lowerFrom) + cycles;
            const double apart = fraction(upperCycles) - fraction(lowerCycles);
            lowerTo = blend.lower->gait->frameAt(lowerCycles + apart - nearestWhole(apart));
        }
    }
    const motion::GroundFrame lowerStep = lower.rootMotion.delta(lowerFrom, lowerTo);
    const motion::GroundFrame upperStep = upper.rootMotion.delta(upperFrom, upperTo);
    const double w = blend.weight;
    showBlend(i, blend, lower.rootMotion.wrap(lowerTo), upper.rootMotion.wrap(upperTo));
    // The feet are timed by the heavier clip, but by the gait as soon as a character leaving
    // or nearing a stand moves visibly: the idle holds both feet, so it could turn no further
    // than its feet twist, and a slow walk-off that has to turn would never come round.
    const bool upperTimes = w >= (blend.lower->gait ? 0.5 : 0.2);
    return {{lowerStep.position * (1.0 - w) + upperStep.position * w, lowerStep.yaw * (1.0 - w) + upperStep.yaw * w},
            upperTimes ? blendClip_[i] : clip_[i],
            upperTimes ? blendFrame_[i] : frame_[i],
            cycles};
}

}  // namespace throng::crowd
