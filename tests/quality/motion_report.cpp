// throng_motion_report FILE... : root-motion quality figures per capture (issue #11), one
// markdown table row each, or JSON with --json. It measures, it asserts nothing: the figures
// are for the before/after note, and tests pick their own thresholds from them.
//
//   throng_motion_report [--json] [--seconds S] FILE...
//
// Every playback runs one character for S seconds (default 24) at the clip's frame time.
// Exit status: 0, or 2 for bad usage or a file that does not load or bake (its row says why).

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "playback_measures.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng;
using quality::PointSeries;

constexpr double kRadToDeg = 57.29577951308232;
constexpr double kTurningRate = 0.35;  // rad/s (20°/s): a goals character counts as turning above it

// One slide figure over the foot points: the mean of their cm/s and the worst one.
struct SlideSummary {
    double mean = 0.0;
    double max = 0.0;
    double cmPerContact = 0.0;  // mean over the foot points
    int contacts = 0;           // summed over the foot points
    std::vector<quality::Slide> perFoot;
};

struct Figures {
    std::string name;
    std::string error;  // non-empty: the clip did not load or bake, nothing else is set
    int frames = 0;
    motion::LoopRange loop;
    int firstFrame = 0;  // 1 when the bake left a synthetic T-pose frame out
    double statureBake = 0.0, statureMedian = 0.0, statureP90 = 0.0;
    double travel = 0.0, ratedSpeed = 0.0, arcSpeedRaw = 0.0, turnDegPerSecond = 0.0;
    double engineDisplacement = 0.0;  // |rootMotion.loopDisplacement().position|, what Crowd::clipSpeed divides
    double playScale = 1.0;
    SlideSummary rawClip, rawLoop, group, straight, turning, whileTurning;
    SlideSummary rawHeightOnly, groupHeightOnly;  // contacts by the height band alone (see heightBandOnly)
    int turningFrames = 0;  // goals-turning steps that turn faster than kTurningRate
    quality::BoneSpread rawBones, bakedBones, playedBones;
    double belowGround = 0.0;  // fraction of group-mode joint samples below −2 cm
    std::vector<std::string> jointNames;
};

// Slide of every foot point over frames [first, last] of `points`. `planted` holds one mask per
// foot, covering the same frames.
SlideSummary summarise(const PointSeries& points, const std::vector<int>& feet, const std::vector<std::vector<char>>& planted,
                       int first, int last, double lengthScale, std::span<const char> include = {}) {
    SlideSummary out;
    for (std::size_t k = 0; k < feet.size(); ++k) {
        const std::vector<glm::dvec3> track = points.track(feet[k], first, last);
        quality::Slide slide = quality::slideOver(track, points.frameTime, planted[k], include);
        // A character drawn at scale s covers s times the clip's lengths; dividing by s makes
        // playback figures comparable with the raw capture's.
        slide.cmPerSecond /= lengthScale;
        slide.cmPerContact /= lengthScale;
        out.perFoot.push_back(slide);
        out.max = std::max(out.max, slide.cmPerSecond);
        out.mean += slide.cmPerSecond / static_cast<double>(feet.size());
        out.cmPerContact += slide.cmPerContact / static_cast<double>(feet.size());
        out.contacts += slide.contacts;
    }
    return out;
}

// The same with contacts found by the height band alone (no speed gate), the first definition
// tried: kept in the JSON to show why the table doesn't use it (swinging feet count as planted).
SlideSummary heightBandOnly(const PointSeries& points, const std::vector<int>& feet, int first, double stature, double lengthScale) {
    std::vector<std::vector<char>> planted;
    for (int foot : feet)
        planted.push_back(quality::plantedFrames(points.track(foot, first), points.frameTime, stature, {0.03, 1e300}));
    return summarise(points, feet, planted, first, -1, lengthScale);
}

// Raw capture figures: stature, the pelvis's arc speed, the feet's slide as captured, and the
// capture's contacts (per foot, per clip frame), which playback is then measured over.
std::vector<std::vector<char>> measureRaw(const motion::RawMotion& raw, const motion::BakedClip& clip,
                                          const motion::Anatomy& anatomy, const std::vector<int>& feet, Figures& out) {
    const PointSeries points = quality::rawWorldPositions(raw, clip.metresPerUnit, clip.upAxis, true);
    out.statureMedian = quality::measuredStature(points, anatomy, 0.5, out.firstFrame);
    out.statureP90 = quality::measuredStature(points, anatomy, 0.9, out.firstFrame);
    const int pelvis = anatomy.pelvis >= 0 ? anatomy.pelvis : 0;
    out.arcSpeedRaw = quality::arcSpeed(quality::groundPath(points, pelvis), points.frameTime, out.loop.first, out.loop.last);
    std::vector<std::vector<char>> planted, usable, inLoop;
    for (int foot : feet) {
        // Contacts are found on the usable frames only: a synthetic T-pose must not set the floor.
        const std::vector<char> found =
            quality::plantedFrames(points.track(foot, out.firstFrame), points.frameTime, out.statureMedian);
        usable.push_back(found);
        std::vector<char> all(static_cast<std::size_t>(out.firstFrame), 0);
        all.insert(all.end(), found.begin(), found.end());
        inLoop.emplace_back(all.begin() + out.loop.first, all.begin() + out.loop.last + 1);
        planted.push_back(std::move(all));
    }
    out.rawClip = summarise(points, feet, usable, out.firstFrame, -1, 1.0);
    out.rawLoop = summarise(points, feet, inLoop, out.loop.first, out.loop.last, 1.0);
    out.rawHeightOnly = heightBandOnly(points, feet, out.firstFrame, out.statureMedian, 1.0);
    out.rawBones = quality::boneLengthSpread(quality::withoutEndSites(points), out.statureMedian);
    return planted;
}

// One course's slide, over the steps where the clip frame shown is one the capture has planted.
SlideSummary playedSlide(const quality::Playback& played, const std::vector<int>& feet,
                         const std::vector<std::vector<char>>& rawPlanted, std::span<const char> include = {}) {
    std::vector<std::vector<char>> planted;
    for (const std::vector<char>& clipPlanted : rawPlanted) planted.push_back(quality::plantedAtClipFrames(clipPlanted, played.clipFrames));
    return summarise(played.joints, feet, planted, 0, -1, played.scale, include);
}

// Playback figures: the three courses, bone lengths and ground penetration as the crowd plays.
void measurePlayback(const motion::BakedClip& clip, const std::vector<int>& feet, const std::vector<std::vector<char>>& rawPlanted,
                     double seconds, Figures& out) {
    auto group = quality::playback(clip, crowd::Mode::Group, seconds, 0.0, false);
    auto straight = quality::playback(clip, crowd::Mode::Goals, seconds, 0.0, false);
    auto turning = quality::playback(clip, crowd::Mode::Goals, seconds, 0.0, true);
    for (const auto* played : {&group, &straight, &turning})
        if (!*played) {
            out.error = played->error().describe();
            return;
        }
    out.playScale = group.value().scale;  // one seed, one draw: the same in all three
    out.group = playedSlide(group.value(), feet, rawPlanted);
    out.straight = playedSlide(straight.value(), feet, rawPlanted);
    out.turning = playedSlide(turning.value(), feet, rawPlanted);
    const std::vector<char> turns =
        quality::turningFrames(turning.value().ground, turning.value().joints.frameTime, kTurningRate);
    out.turningFrames = static_cast<int>(std::count(turns.begin(), turns.end(), 1));
    out.whileTurning = playedSlide(turning.value(), feet, rawPlanted, turns);
    const double stature = out.statureMedian * out.playScale;
    out.groupHeightOnly = heightBandOnly(group.value().joints, feet, 0, stature, out.playScale);
    out.playedBones = quality::boneLengthSpread(group.value().joints, stature);
    out.belowGround = quality::fractionBelow(group.value().joints, -0.02);
}

Figures measure(const std::string& path, double seconds) {
    Figures out;
    out.name = path.substr(path.find_last_of('/') + 1);
    auto raw = motion::loadBvhFile(path);
    if (!raw) {
        out.error = raw.error().describe();
        return out;
    }
    auto baked = motion::bake(raw.value());
    if (!baked) {
        out.error = baked.error().describe();
        return out;
    }
    const motion::BakedClip& clip = baked.value();
    const motion::Anatomy anatomy = motion::findAnatomy(raw.value());
    const std::vector<int> feet = quality::footPoints(anatomy);
    out.frames = clip.frameCount;
    out.loop = clip.loop();
    out.firstFrame = clip.firstFrameSkipped && clip.frameCount > 1 ? 1 : 0;
    out.jointNames = clip.jointNames;
    out.statureBake = clip.stature;
    const double loopSeconds = out.loop.length() * clip.frameTime;
    // Net ground travel from the loop's first frame to its last. Not |loopDisplacement|: that
    // transform turns about the file's origin, so on a clip that turns over its loop its length
    // grows with the capture's distance from the origin (kept as engineDisplacement).
    const auto& track = clip.rootMotion.frames();
    out.travel = glm::length(track[static_cast<std::size_t>(out.loop.last)].position - track[static_cast<std::size_t>(out.loop.first)].position);
    out.engineDisplacement = glm::length(clip.rootMotion.loopDisplacement().position);
    out.ratedSpeed = clip.speed != 0.0 ? clip.speed : crowd::Crowd::clipSpeed(clip);
    out.turnDegPerSecond = loopSeconds > 0 ? clip.rootMotion.loopDisplacement().yaw / loopSeconds * kRadToDeg : 0.0;
    const std::vector<std::vector<char>> planted = measureRaw(raw.value(), clip, anatomy, feet, out);
    out.bakedBones = quality::boneLengthSpread(quality::bakedInPlacePositions(clip), out.statureMedian);
    measurePlayback(clip, feet, planted, seconds, out);
    return out;
}

std::string format(const char* pattern, double a, double b = 0.0) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

// "% of stature / % of the bone's own length", the worst bone by each measure.
std::string boneCell(const quality::BoneSpread& spread) {
    if (spread.point < 0) return "–";
    return format("%.2f%% / %.1f%%", 100.0 * spread.fraction, 100.0 * spread.relative);
}

// "mean / max" over the foot points; a dash when no planted frame was measured.
std::string slideCell(const SlideSummary& s) {
    const bool measured = std::any_of(s.perFoot.begin(), s.perFoot.end(), [](const quality::Slide& f) { return f.measuredFrames > 0; });
    return measured ? format("%.1f / %.1f", s.mean, s.max) : "–";
}

void printHeader() {
    std::cout << "| clip | frames | loop | stature bake / median / p90 (m) | travel per loop (m) | speed rated / pelvis arc (m/s) "
                 "| turn (°/s) | slide raw clip | slide raw loop | slide group | slide goals straight "
                 "| slide goals turning | slide while turning | bones raw | bones baked | bones played | below −2 cm |\n"
                 "|---|---:|---|---|---:|---|---:|---|---|---|---|---|---|---|---|---|---:|\n";
}

void printRow(const Figures& f) {
    if (!f.error.empty()) {
        std::cout << "| " << f.name << " | error: " << f.error << " |\n";
        return;
    }
    std::cout << "| " << f.name << " | " << f.frames << " | " << f.loop.first << "–" << f.loop.last
              << (f.firstFrame > 0 ? " (T-pose skipped)" : "") << " | " << format("%.3f / %.3f", f.statureBake, f.statureMedian) + format(" / %.3f", f.statureP90)
              << " | " << format("%.3f", f.travel) << " | " << format("%.3f / %.3f", f.ratedSpeed, f.arcSpeedRaw) << " | "
              << format("%.1f", f.turnDegPerSecond) << " | " << slideCell(f.rawClip) << " | " << slideCell(f.rawLoop) << " | "
              << slideCell(f.group) << " | " << slideCell(f.straight) << " | " << slideCell(f.turning) << " | "
              << slideCell(f.whileTurning) << " | " << boneCell(f.rawBones) << " | " << boneCell(f.bakedBones) << " | "
              << boneCell(f.playedBones) << " | " << format("%.2f%%", 100.0 * f.belowGround) << " |\n";
}

nlohmann::json toJson(const SlideSummary& s) {
    nlohmann::json feet = nlohmann::json::array();
    for (const quality::Slide& slide : s.perFoot)
        feet.push_back({{"cm_per_s", slide.cmPerSecond}, {"contacts", slide.contacts}, {"cm_per_contact", slide.cmPerContact},
                        {"planted_frames", slide.plantedFrames}, {"measured_frames", slide.measuredFrames}});
    return {{"mean_cm_per_s", s.mean}, {"max_cm_per_s", s.max}, {"contacts", s.contacts},
            {"mean_cm_per_contact", s.cmPerContact}, {"per_foot", feet}};
}

nlohmann::json toJson(const quality::BoneSpread& b, const std::vector<std::string>& names) {
    const auto name = [&](int point) {
        return point >= 0 && point < static_cast<int>(names.size()) ? names[static_cast<std::size_t>(point)] : std::string();
    };
    return {{"metres", b.metres}, {"fraction_of_stature", b.fraction}, {"bone", name(b.point)},
            {"fraction_of_bone", b.relative}, {"bone_by_own_length", name(b.relativePoint)}};
}

nlohmann::json toJson(const Figures& f) {
    if (!f.error.empty()) return {{"clip", f.name}, {"error", f.error}};
    return {{"clip", f.name}, {"frames", f.frames}, {"loop", {f.loop.first, f.loop.last}}, {"first_frame", f.firstFrame},
            {"stature_bake_m", f.statureBake}, {"stature_median_m", f.statureMedian},
            {"stature_p90_m", f.statureP90}, {"travel_per_loop_m", f.travel},
            {"engine_loop_displacement_m", f.engineDisplacement},
            {"rated_speed_m_per_s", f.ratedSpeed}, {"pelvis_arc_speed_raw_m_per_s", f.arcSpeedRaw},
            {"turn_deg_per_s", f.turnDegPerSecond}, {"playback_scale", f.playScale}, {"turning_steps", f.turningFrames},
            {"slide", {{"raw_clip", toJson(f.rawClip)}, {"raw_loop", toJson(f.rawLoop)}, {"group", toJson(f.group)},
                       {"goals_straight", toJson(f.straight)}, {"goals_turning", toJson(f.turning)},
                       {"goals_while_turning", toJson(f.whileTurning)}, {"raw_clip_height_band_only", toJson(f.rawHeightOnly)},
                       {"group_height_band_only", toJson(f.groupHeightOnly)}}},
            {"bone_spread", {{"raw", toJson(f.rawBones, f.jointNames)}, {"baked", toJson(f.bakedBones, f.jointNames)},
                             {"played", toJson(f.playedBones, f.jointNames)}}},
            {"below_ground_fraction", f.belowGround}};
}

int usage() {
    std::cerr << "usage: throng_motion_report [--json] [--seconds S] FILE...\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    bool json = false;
    double seconds = 24.0;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--json") {
            json = true;
        } else if (arg == "--seconds" && i + 1 < argc) {
            seconds = std::strtod(argv[++i], nullptr);
            if (!(seconds > 0 && seconds < 3600)) return usage();
        } else if (arg == "--help" || arg == "-h" || (!arg.empty() && arg[0] == '-')) {
            return usage();
        } else {
            files.push_back(arg);
        }
    }
    if (files.empty()) return usage();
    nlohmann::json all = nlohmann::json::array();
    if (!json) printHeader();
    bool failed = false;
    for (const std::string& file : files) {
        const Figures figures = measure(file, seconds);
        failed = failed || !figures.error.empty();
        if (!figures.error.empty()) std::cerr << figures.error << "\n";  // it names the file
        if (json) all.push_back(toJson(figures));
        else printRow(figures);
    }
    if (json) std::cout << all.dump(2) << "\n";
    return failed ? 2 : 0;  // DESIGN.md §3: a file that won't load or bake is bad input
}
