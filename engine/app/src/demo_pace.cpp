#include "demo_pace.h"

#include <cmath>
#include <cstdio>

namespace throng::app {

void CrowdPace::adopt(crowd::Crowd& crowd) {
    own_.resize(static_cast<std::size_t>(crowd.size()));
    applied_.resize(own_.size());
    for (int i = 0; i < crowd.size(); ++i) own_[static_cast<std::size_t>(i)] = crowd.desiredSpeed(i);
    apply(crowd);
}

PaceChange CrowdPace::shift(crowd::Crowd& crowd, int steps) {
    keep(crowd);  // an event's speed since the last step is the character's own before the press counts
    const float before = offset_;
    offset_ += static_cast<float>(steps) * kPaceStep;
    if (apply(crowd) > 0) return PaceChange::Changed;
    offset_ = before;  // past the end of every set: more presses would only have to be undone
    apply(crowd);
    for (int i = 0; i < crowd.size(); ++i)
        if (crowd.locomotion(i) != nullptr) return PaceChange::AtLimit;
    return PaceChange::NoSet;
}

void CrowdPace::keep(crowd::Crowd& crowd) {
    if (own_.size() != static_cast<std::size_t>(crowd.size())) return adopt(crowd);
    bool changed = false;
    for (int i = 0; i < crowd.size(); ++i) {
        const auto c = static_cast<std::size_t>(i);
        // Exact comparison on purpose: applied_ is read back from the crowd, so only another
        // writer makes them differ.
        if (crowd.desiredSpeed(i) != applied_[c]) {
            own_[c] = crowd.desiredSpeed(i);
            changed = true;
        }
    }
    if (changed) apply(crowd);
}

int CrowdPace::apply(crowd::Crowd& crowd) {
    int changed = 0;
    for (int i = 0; i < crowd.size(); ++i) {
        const auto c = static_cast<std::size_t>(i);
        if (crowd.locomotion(i) != nullptr) crowd.setDesiredSpeed(i, own_[c] + offset_);
        if (crowd.desiredSpeed(i) != applied_[c]) ++changed;
        applied_[c] = crowd.desiredSpeed(i);
    }
    return changed;
}

namespace {

// Adds character i's pose weights to `weights` (by clip index): the blend's two clips share
// what a transition's outgoing clip leaves, as Crowd::poseMix weighs them for the GPU.
void addPoseWeights(const crowd::Crowd& crowd, int i, std::vector<double>& weights) {
    const auto add = [&](std::uint32_t clip, double weight) {
        if (!(weight > 0)) return;
        if (clip >= weights.size()) weights.resize(clip + 1, 0.0);
        weights[clip] += weight;
    };
    const double from = crowd.fromWeight(i), blend = crowd.blendWeight(i);
    add(crowd.clip(i), (1.0 - from) * (1.0 - blend));
    add(crowd.blendClip(i), (1.0 - from) * blend);
    add(crowd.fromClip(i), from);
}

}  // namespace

PaceSummary summarizePace(const crowd::Crowd& crowd, std::optional<int> only) {
    PaceSummary summary;
    const bool one = only && *only >= 0 && *only < crowd.size();
    const int first = one ? *only : 0, last = one ? *only + 1 : crowd.size();
    std::vector<double> weights;
    for (int i = first; i < last; ++i) {
        ++summary.characters;
        // A followed character that plays one clip still shows what it plays.
        if (crowd.locomotion(i) == nullptr && !one) continue;
        if (crowd.locomotion(i) != nullptr) ++summary.blending;
        summary.desired += crowd.desiredSpeed(i);
        summary.actual += crowd.speed(i);
        addPoseWeights(crowd, i, weights);
    }
    const int counted = one ? 1 : summary.blending;
    if (counted == 0) return summary;
    summary.desired /= counted;
    summary.actual /= counted;
    for (std::size_t c = 0; c < weights.size(); ++c)
        if (weights[c] > 0) summary.shares.push_back({static_cast<std::uint32_t>(c), weights[c] / counted});
    return summary;
}

std::vector<std::string> describePace(const PaceSummary& summary, std::span<const std::string> clipNames, float offset,
                                      std::optional<int> character) {
    const auto nameOf = [&](std::uint32_t clip) {
        return clip < clipNames.size() ? clipNames[clip] : "clip " + std::to_string(clip);
    };
    std::string mix;
    for (const ClipShare& share : summary.shares) {
        if (share.weight < 0.005) continue;  // would read "0%"
        char percent[16];
        std::snprintf(percent, sizeof percent, " %.0f%%", 100.0 * share.weight);
        mix += (mix.empty() ? "" : " / ") + nameOf(share.clip) + percent;
    }
    if (summary.blending == 0) {
        if (!character) return {"pace: no locomotion set here, so walking faster or slower changes nothing"};
        return {"character " + std::to_string(*character) + " plays one clip at its own pace", mix};
    }
    const std::string who = character ? "character " + std::to_string(*character) + ", pace" : "pace";
    const std::string some =
        summary.blending < summary.characters ? " (" + std::to_string(summary.blending) + " of " + std::to_string(summary.characters) + " blend)" : "";
    char head[200];
    std::snprintf(head, sizeof head, "%s %s%.1f m/s: wants %.2f, walks %.2f m/s%s", who.c_str(), offset < 0 ? "-" : "+",
                  static_cast<double>(std::abs(offset)), summary.desired, summary.actual, some.c_str());
    return {head, mix};
}

}  // namespace throng::app
