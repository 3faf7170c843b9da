#pragma once
// The demo's walking pace (the Up and Down keys) and what the HUD says of the blend. The pace
// is one offset in m/s added to the desired ground speed each character of a locomotion set
// chose for itself (drawn at spawn, or given by a scene event), so the crowd keeps its
// variety as it speeds up, and the same presses back give every character its own speed
// again. The crowd clamps each sum into its set's range (standing to a fast run).

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "throng/crowd/crowd.h"

namespace throng::app {

/// How much one press of Up or Down changes the pace, m/s. On the project's set (idle, slow
/// walk, walk, run) the default crowd (1.0 to 1.6 m/s) runs after four presses up and stands
/// after three down.
inline constexpr float kPaceStep = 0.5F;

/// What a press did.
enum class PaceChange : std::uint8_t {
    Changed,  ///< Some character now wants another speed.
    AtLimit,  ///< Every character is already clamped at that end of its set: the offset stays.
    NoSet,    ///< No character blends a set: nothing to change.
};

/// The pace offset and each character's own speed, for one crowd at a time.
class CrowdPace {
public:
    /// The offset added to every set character's own desired speed, m/s (0 at start).
    [[nodiscard]] float offset() const { return offset_; }
    /// Takes a new crowd's desired speeds as the characters' own and adds the offset: call
    /// after every spawn, so a respawned crowd keeps the pace chosen.
    void adopt(crowd::Crowd& crowd);
    /// One press: the offset moves by `steps` x kPaceStep, unless that changes no character.
    PaceChange shift(crowd::Crowd& crowd, int steps);
    /// Call after every step: a character whose desired speed something else changed (a scene
    /// event) takes that speed as its own, plus the offset.
    void keep(crowd::Crowd& crowd);

private:
    /// Sets own + offset on every character of a set; returns how many now want another speed.
    int apply(crowd::Crowd& crowd);

    float offset_ = 0.0F;
    std::vector<float> own_;      ///< Per character: the speed it chose, m/s, before the offset.
    std::vector<float> applied_;  ///< Per character: what the crowd holds after the last apply (clamped).
};

/// One clip's part in the poses shown.
struct ClipShare {
    std::uint32_t clip = 0;  ///< Index into the crowd's clip table.
    double weight = 0.0;     ///< Mean weight in the pose over the characters counted, 0..1.
};

/// The blend as the HUD tells it: of one character, or the mean over every character of a set.
struct PaceSummary {
    int blending = 0;              ///< Characters counted: those of a set (or the one followed, if it has one).
    int characters = 0;            ///< Characters looked at.
    double desired = 0.0;          ///< Mean desired ground speed, m/s.
    double actual = 0.0;           ///< Mean ground speed the blends walk at, m/s.
    std::vector<ClipShare> shares; ///< Clips with a part in the pose, by clip index.
};

/// The crowd's blend, or character `only`'s when given (and in range). A character's pose
/// weighs its blend's two clips and a transition's outgoing clip as the GPU mixes them.
[[nodiscard]] PaceSummary summarizePace(const crowd::Crowd& crowd, std::optional<int> only = std::nullopt);

/// The HUD's lines for `summary`: "pace +1.0 m/s: wants 2.3, walks 2.1 m/s" then "walk 40% /
/// run 60%", clips named by `clipNames` (by index; "clip N" past its end), shares under 0.5%
/// left out. `character` names the followed character; `offset` is CrowdPace::offset().
[[nodiscard]] std::vector<std::string> describePace(const PaceSummary& summary, std::span<const std::string> clipNames,
                                                    float offset, std::optional<int> character = std::nullopt);

}  // namespace throng::app
