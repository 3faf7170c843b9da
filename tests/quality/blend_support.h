#pragma once
// What the speed-blending (#12) and trajectory-following (#15) acceptance tests share: the
// project's and the CMU locomotion sets, one character walked and sampled as the GPU samples it
// (crowd::sampleJointWorld), and the yardsticks that know nothing of the blend: strides from
// where the left ankle plants, slide over the raw captures' own contacts, joint steps per frame.

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "playback_measures.h"
#include "throng/crowd/crowd.h"
#include "throng/motion/locomotion_set.h"

namespace throng::blendtest {

inline constexpr double kFrame = 1.0 / 60.0;

/// A project asset by file name, and a shared capture by file name.
[[nodiscard]] std::string asset(const std::string& name);
[[nodiscard]] std::string shared(const std::string& name);
/// The project's set's files, in clip-table order: the idle first.
inline constexpr const char* kSetFiles[] = {"idle.bvh", "slow_walk.bvh", "walk.bvh", "run.bvh"};
/// The shared CMU set: two walks and a run, no idle.
inline constexpr const char* kCmuFiles[] = {"cmu_02_01_walk.bvh", "cmu_07_01_walk.bvh", "cmu_16_45_run.bvh"};

struct Set {
    std::vector<std::string> paths;
    std::vector<motion::BakedClip> clips;
    motion::LocomotionSet set;
};
[[nodiscard]] Set loadSet(std::vector<std::string> paths);
/// The project's set, in clip-table order: idle, slow walk, walk, run.
[[nodiscard]] Set projectSet();

/// One character's joints per step, and per step what the blend showed.
struct Walked {
    quality::PointSeries joints;
    double scale = 1.0;
    std::vector<std::uint32_t> upperClip, lowerClip;
    std::vector<double> upperFrame, lowerFrame;
};
/// Appends character 0 of `crowd` as it is now to `out` (joints sampled, clips and frames shown).
void record(const crowd::Crowd& crowd, std::span<const motion::BakedClip> clips, Walked& out);
/// One character of the set in group mode for `seconds`, its desired speed `speedAt(t)` m/s.
[[nodiscard]] Walked walk(const Set& s, double seconds, const std::function<double(double)>& speedAt);

/// Mean horizontal distance between successive left-ankle plantings, per unit of body scale.
[[nodiscard]] double strideLength(const Walked& w, const motion::BakedClip& clip);

/// Per clip of the set and foot point, the capture's own planted frames (raw forward kinematics).
using RawContacts = std::vector<std::map<int, std::vector<char>>>;
[[nodiscard]] RawContacts rawContacts(const Set& s);
/// Worst slide per contact (cm) over both ankles and toes, over the steps where the raw clips
/// shown have the point planted (both clips; the idle's feet never lift).
[[nodiscard]] double worstBlendSlide(const Walked& w, const Set& s, const RawContacts& raw);
/// The largest step any joint takes between frames, metres.
[[nodiscard]] double largestStep(const quality::PointSeries& joints);

}  // namespace throng::blendtest
