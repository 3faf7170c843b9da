#pragma once
// What the root-motion acceptance tests (issue #11) share: where the clips are (the generated
// ones with their known answers, the shared captures), loading and baking, and the slide and
// separation figures they compare. Every figure is measured here with playback_measures, apart
// from the bake's own analysis: contacts come from the raw capture, not from BakedClip::contacts.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "playback_measures.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/raw_motion.h"

namespace throng::acceptance {

/// A generated clip by name ("yup_walk"): its path in the folder the generated_clips fixture writes.
[[nodiscard]] std::string generatedClip(const std::string& name);
/// That clip's entry in known_answers.json (arc_speed_m_per_s, stature_m, up_axis, ...).
/// Throws when the file or the entry is missing: the generated_clips fixture did not run.
[[nodiscard]] const nlohmann::json& knownAnswers(const std::string& name);

/// Whether the shared captures are there (THRONG_SHARED_MOCAP_DIR), and their paths, sorted.
[[nodiscard]] bool haveSharedCaptures();
[[nodiscard]] std::vector<std::string> sharedCaptures();
[[nodiscard]] std::string sharedCapture(const std::string& file);
[[nodiscard]] std::string fileName(const std::string& path);

struct Loaded {
    motion::RawMotion raw;
    motion::BakedClip clip;
};
/// Loads and bakes `path`; throws with the engine's message if either fails.
[[nodiscard]] Loaded load(const std::string& path, const motion::BakeOptions& options = {});

/// The first usable frame of the raw capture: 1 when the bake left a synthetic T-pose out.
[[nodiscard]] int firstUsableFrame(const motion::BakedClip& clip);

/// One slide figure over the foot points (each leg's ankle and toe).
struct SlideSummary {
    double cmPerSecond = 0.0;   ///< Mean over the foot points of their cm/s.
    double cmPerContact = 0.0;  ///< Mean over the foot points of their cm per contact.
    int contacts = 0;           ///< Summed over the foot points.
    bool measured = false;      ///< Some foot point had a planted frame with planted neighbours.
    std::vector<quality::Slide> perFoot;
};

/// Planted-foot slide of a capture as it was recorded and as the crowd plays it. Contacts are
/// the raw capture's (plantedFrames at its median stature), and playback is measured over the
/// steps that show a clip frame the capture has planted, as throng_motion_report does.
struct SlideFigures {
    SlideSummary rawLoop;       ///< The raw capture over the clip's loop.
    SlideSummary group;         ///< Group mode (the paper's update).
    SlideSummary straight;      ///< Goals mode, walking straight.
    SlideSummary whileTurning;  ///< Goals mode round a square, over the steps that turn faster than 20°/s.
    /// Goals mode walking straight, at the clip frames whileTurning's steps show, each as often:
    /// the slide the gait itself has where the turns happen (what whileTurning compares with).
    SlideSummary straightAtTurningPhases;
    int turningSteps = 0;
    double statureMedian = 0.0;  ///< Of the raw capture, metres.
};
[[nodiscard]] SlideFigures measureSlides(const Loaded& loaded, double seconds);

/// Played joint positions of one group-mode character of `clip`.
[[nodiscard]] quality::Playback groupPlayback(const motion::BakedClip& clip, double seconds);

/// Spawns `count` characters of `clip` in Avoid mode in a square region of side `side` metres
/// (random goals there), steps for `seconds` at 30 Hz and returns the smallest distance seen
/// between two characters divided by the sum of their radii.
[[nodiscard]] double closestApproach(const motion::BakedClip& clip, int count, float side, double seconds);

}  // namespace throng::acceptance
