#include "acceptance_support.h"

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include "throng/crowd/crowd.h"
#include "throng/motion/bvh_parser.h"
#include "throng/motion/skeleton_anatomy.h"

namespace throng::acceptance {
namespace {

constexpr double kTurningRate = 0.35;  // rad/s (20°/s): a goals character counts as turning above it

// Slide of every foot point over frames [first, last] of `points`; `planted` holds one mask per
// foot over the same frames. Playback lengths are divided by the body scale the crowd drew, so
// they compare with the capture's.
SlideSummary summarise(const quality::PointSeries& points, const std::vector<int>& feet,
                       const std::vector<std::vector<char>>& planted, int first, int last, double lengthScale,
                       std::span<const char> include = {}) {
    SlideSummary out;
    for (std::size_t k = 0; k < feet.size(); ++k) {
        quality::Slide slide = quality::slideOver(points.track(feet[k], first, last), points.frameTime, planted[k], include);
        slide.cmPerSecond /= lengthScale;
        slide.cmPerContact /= lengthScale;
        out.perFoot.push_back(slide);
        out.cmPerSecond += slide.cmPerSecond / static_cast<double>(feet.size());
        out.cmPerContact += slide.cmPerContact / static_cast<double>(feet.size());
        out.contacts += slide.contacts;
        out.measured = out.measured || slide.measuredFrames > 0;
    }
    return out;
}

// One course's slide, over the steps whose clip frame the capture has planted.
SlideSummary playedSlide(const quality::Playback& played, const std::vector<int>& feet,
                         const std::vector<std::vector<char>>& rawPlanted, std::span<const char> include = {}) {
    std::vector<std::vector<char>> planted;
    for (const std::vector<char>& clipPlanted : rawPlanted)
        planted.push_back(quality::plantedAtClipFrames(clipPlanted, played.clipFrames));
    return summarise(played.joints, feet, planted, 0, -1, played.scale, include);
}

// Straight walking's slide at the clip frames the turning steps show, each as often as they show
// it. A steering turn is concentrated into the gait's turning windows, so the turning steps
// sample some phases of the gait far more than a straight walk does; on a capture whose toes
// roll while they count as planted, that sampling alone would read as slide the turn added.
SlideSummary straightAtTurningPhases(const quality::Playback& straight, const quality::Playback& turning, const std::vector<int>& feet,
                                     const std::vector<std::vector<char>>& rawPlanted, std::span<const char> turns) {
    SlideSummary out;
    const auto speedsOf = [&](const quality::Playback& played, std::size_t k) {
        const std::vector<char> planted = quality::plantedAtClipFrames(rawPlanted[k], played.clipFrames);
        return quality::plantedSpeeds(played.joints.track(feet[k]), played.joints.frameTime, planted);
    };
    const auto nearestFrame = [](double frame) { return static_cast<long>(std::floor(frame + 0.5)); };
    for (std::size_t k = 0; k < feet.size(); ++k) {
        std::map<long, std::pair<double, int>> byFrame;  // straight speed sum and count per clip frame
        const std::vector<double> straightSpeeds = speedsOf(straight, k);
        for (std::size_t s = 0; s < straightSpeeds.size(); ++s)
            if (!std::isnan(straightSpeeds[s])) {
                auto& [sum, count] = byFrame[nearestFrame(straight.clipFrames[s])];
                sum += straightSpeeds[s], ++count;
            }
        quality::Slide slide;
        double sum = 0.0;
        const std::vector<double> turningSpeeds = speedsOf(turning, k);
        for (std::size_t s = 0; s < turningSpeeds.size(); ++s) {
            const auto found = byFrame.find(nearestFrame(turning.clipFrames[s]));
            if (std::isnan(turningSpeeds[s]) || turns[s] == 0 || found == byFrame.end()) continue;
            sum += found->second.first / found->second.second, ++slide.measuredFrames;
        }
        if (slide.measuredFrames > 0) slide.cmPerSecond = 100.0 * sum / slide.measuredFrames / straight.scale;
        out.cmPerSecond += slide.cmPerSecond / static_cast<double>(feet.size());
        out.measured = out.measured || slide.measuredFrames > 0;
        out.perFoot.push_back(slide);
    }
    return out;
}

quality::Playback play(const motion::BakedClip& clip, crowd::Mode mode, double seconds, bool turning) {
    auto played = quality::playback(clip, mode, seconds, 0.0, turning);
    if (!played) throw std::runtime_error(played.error().describe());
    return std::move(played.value());
}

}  // namespace

std::string generatedClip(const std::string& name) { return std::string(THRONG_GENERATED_CLIPS_DIR) + "/" + name + ".bvh"; }

const nlohmann::json& knownAnswers(const std::string& name) {
    static const nlohmann::json all = [] {
        const std::string path = std::string(THRONG_GENERATED_CLIPS_DIR) + "/known_answers.json";
        std::ifstream in(path);
        if (!in) throw std::runtime_error("no " + path + ": the generated_clips fixture (ctest -R generated_clips.write) writes it");
        return nlohmann::json::parse(in);
    }();
    const std::string key = name + ".bvh";
    if (!all.contains("clips") || !all["clips"].contains(key)) throw std::runtime_error("known_answers.json has no " + key);
    return all["clips"][key];
}

bool haveSharedCaptures() { return std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR); }

std::vector<std::string> sharedCaptures() {
    std::vector<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator(THRONG_SHARED_MOCAP_DIR))
        if (entry.path().extension() == ".bvh") paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::string sharedCapture(const std::string& file) { return std::string(THRONG_SHARED_MOCAP_DIR) + "/" + file; }

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

Loaded load(const std::string& path, const motion::BakeOptions& options) {
    auto raw = motion::loadBvhFile(path);
    if (!raw) throw std::runtime_error(raw.error().describe());
    auto clip = motion::bake(raw.value(), options);
    if (!clip) throw std::runtime_error(clip.error().describe());
    return {std::move(raw.value()), std::move(clip.value())};
}

int firstUsableFrame(const motion::BakedClip& clip) { return clip.firstFrameSkipped && clip.frameCount > 1 ? 1 : 0; }

SlideFigures measureSlides(const Loaded& loaded, double seconds) {
    const motion::BakedClip& clip = loaded.clip;
    const motion::Anatomy anatomy = motion::findAnatomy(loaded.raw);
    const std::vector<int> feet = quality::footPoints(anatomy);
    const int first = firstUsableFrame(clip);
    const motion::LoopRange loop = clip.loop();
    const quality::PointSeries raw = quality::rawWorldPositions(loaded.raw, clip.metresPerUnit, clip.upAxis, true);
    SlideFigures out;
    out.statureMedian = quality::measuredStature(raw, anatomy, 0.5, first);
    // The capture's contacts per clip frame (a synthetic T-pose must not set the floor).
    std::vector<std::vector<char>> planted, inLoop;
    for (int foot : feet) {
        std::vector<char> all(static_cast<std::size_t>(first), 0);
        const std::vector<char> found = quality::plantedFrames(raw.track(foot, first), raw.frameTime, out.statureMedian);
        all.insert(all.end(), found.begin(), found.end());
        inLoop.emplace_back(all.begin() + loop.first, all.begin() + loop.last + 1);
        planted.push_back(std::move(all));
    }
    out.rawLoop = summarise(raw, feet, inLoop, loop.first, loop.last, 1.0);
    out.group = playedSlide(play(clip, crowd::Mode::Group, seconds, false), feet, planted);
    const quality::Playback straight = play(clip, crowd::Mode::Goals, seconds, false);
    out.straight = playedSlide(straight, feet, planted);
    const quality::Playback turning = play(clip, crowd::Mode::Goals, seconds, true);
    const std::vector<char> turns = quality::turningFrames(turning.ground, turning.joints.frameTime, kTurningRate);
    out.turningSteps = static_cast<int>(std::count(turns.begin(), turns.end(), 1));
    out.whileTurning = playedSlide(turning, feet, planted, turns);
    out.straightAtTurningPhases = straightAtTurningPhases(straight, turning, feet, planted, turns);
    return out;
}

quality::Playback groupPlayback(const motion::BakedClip& clip, double seconds) {
    return play(clip, crowd::Mode::Group, seconds, false);
}

double closestApproach(const motion::BakedClip& clip, int count, float side, double seconds) {
    crowd::CrowdSetup setup;
    setup.groups.push_back({.count = count, .clips = {}, .region = {glm::vec2(0.0F), glm::vec2(side)}, .mode = crowd::Mode::Avoid,
                            .speedRange = {1.0F, 1.0F}, .heading = 0.0F, .locomotion = std::nullopt, .groundSpeed = {1.0F, 1.5F}});
    setup.area = {glm::vec2(0.0F), glm::vec2(side)};
    setup.seed = 7;
    setup.threads = 1;
    const std::span<const motion::BakedClip> clips(&clip, 1);
    crowd::Crowd crowd = crowd::Crowd::spawn(clips, setup).orThrow();
    const double dt = 1.0 / 30.0;
    double closest = 1e300;
    for (int s = 0; s < static_cast<int>(seconds / dt); ++s) {
        crowd.step(clips, dt);
        for (int i = 0; i < crowd.size(); ++i)
            for (int j = i + 1; j < crowd.size(); ++j) {
                const double distance = glm::length(crowd.groundFrame(i).position - crowd.groundFrame(j).position);
                closest = std::min(closest, distance / (crowd.radius(i) + crowd.radius(j)));
            }
    }
    return closest;
}

}  // namespace throng::acceptance
