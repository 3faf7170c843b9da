// See blend_support.h.
#include "blend_support.h"

#include <cmath>
#include <filesystem>

#include "throng/motion/bvh_parser.h"

namespace throng::blendtest {

// The project's set, in clip-table order: the idle first.

std::string asset(const std::string& name) { return (std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path() / name).string(); }
std::string shared(const std::string& name) { return (std::filesystem::path(THRONG_SHARED_MOCAP_DIR) / name).string(); }


Set loadSet(std::vector<std::string> paths) {
    Set out;
    out.paths = std::move(paths);
    std::vector<std::uint32_t> members;
    for (const std::string& path : out.paths) {
        members.push_back(static_cast<std::uint32_t>(out.clips.size()));
        out.clips.push_back(motion::bake(motion::loadBvhFile(path).orThrow()).orThrow());
    }
    out.set = motion::makeLocomotionSet(out.clips, members).orThrow();
    return out;
}

Set projectSet() {
    std::vector<std::string> paths;
    for (const char* name : kSetFiles) paths.push_back(asset(name));
    return loadSet(paths);
}


// One character of the set in group mode for `seconds`, its desired speed `speedAt(t)` m/s.
void record(const crowd::Crowd& crowd, std::span<const motion::BakedClip> clips, Walked& out) {
    std::vector<crowd::CharacterState> state(static_cast<std::size_t>(crowd.size()));
    crowd.pack(state);
    out.upperClip.push_back(crowd.blendClip(0));
    out.upperFrame.push_back(crowd.blendFrame(0));
    out.lowerClip.push_back(crowd.clip(0));
    out.lowerFrame.push_back(crowd.frame(0));
    for (int j = 0; j < out.joints.joints; ++j) out.joints.positions.emplace_back(crowd::sampleJointWorld(clips, state[0], j).position);
    ++out.joints.frames;
}

Walked walk(const Set& s, double seconds, const std::function<double(double)>& speedAt) {
    crowd::GroupSpec group;
    group.count = 1;
    group.region = {{0.0F, 0.0F}, {0.5F, 0.5F}};
    group.locomotion = 0;
    group.groundSpeed = glm::vec2(static_cast<float>(speedAt(0.0)));
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.locomotion = {s.set};
    setup.threads = 1;
    crowd::Crowd crowd = crowd::Crowd::spawn(s.clips, setup).orThrow();
    const int steps = static_cast<int>(std::lround(seconds / kFrame));
    const motion::BakedClip& any = s.clips[0];
    Walked out;
    out.joints = {0, any.jointCount(), any.jointCount(), kFrame, any.parents, {}};
    out.scale = crowd.scale(0);
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) {
            crowd.setDesiredSpeed(0, static_cast<float>(speedAt(step * kFrame) * out.scale));
            crowd.step(s.clips, kFrame);
        }
        record(crowd, s.clips, out);
    }
    return out;
}

// Mean horizontal distance between successive left-ankle plantings, per unit of body scale.
double strideLength(const Walked& w, const motion::BakedClip& clip) {
    const int ankle = clip.anatomy.legs[static_cast<std::size_t>(clip.leftLeg)].ankle;
    const std::vector<glm::dvec3> track = w.joints.track(ankle);
    const std::vector<char> planted = quality::plantedFrames(track, kFrame, clip.stature);
    std::vector<glm::dvec3> plants;
    for (std::size_t f = 1; f < planted.size(); ++f)
        if (planted[f] && !planted[f - 1]) plants.push_back(track[f]);
    double total = 0;
    for (std::size_t k = 1; k < plants.size(); ++k) total += glm::length(glm::dvec2(plants[k].x - plants[k - 1].x, plants[k].z - plants[k - 1].z));
    return plants.size() > 1 ? total / static_cast<double>(plants.size() - 1) / w.scale : 0.0;
}

// Per clip of the set and foot point, the capture's own contacts: planted frames found on the
// raw file's forward kinematics, not by the bake.
RawContacts rawContacts(const Set& s) {
    RawContacts out;
    for (std::size_t c = 0; c < s.clips.size(); ++c) {
        const motion::BakedClip& clip = s.clips[c];
        const quality::PointSeries raw = quality::rawWorldPositions(motion::loadBvhFile(s.paths[c]).orThrow(), clip.metresPerUnit);
        out.emplace_back();
        for (const motion::LegChain& leg : clip.anatomy.legs)
            for (int point : {leg.ankle, leg.toe})
                if (point >= 0) out.back()[point] = quality::plantedFrames(raw.track(point), clip.frameTime, clip.stature);
    }
    return out;
}

// Worst slide per contact (cm) over both ankles and toes of a blend, over the steps where
// the raw clips it showed have the point planted (both clips; the idle's feet never lift).
double worstBlendSlide(const Walked& w, const Set& s, const RawContacts& raw) {
    double worst = 0;
    const motion::BakedClip& clip = s.clips[s.set.gaits.front().clip];
    for (const motion::LegChain& leg : clip.anatomy.legs)
        for (int point : {leg.ankle, leg.toe}) {
            if (point < 0) continue;
            std::vector<char> planted(w.upperClip.size(), 0);
            for (std::size_t step = 0; step < planted.size(); ++step) {
                const auto down = [&](std::uint32_t c, double frame) {
                    return raw[c].at(point)[static_cast<std::size_t>(std::lround(frame))] != 0;
                };
                const bool lowerDown = !s.set.idle || w.lowerClip[step] != s.set.idle->clip ? down(w.lowerClip[step], w.lowerFrame[step]) : true;
                planted[step] = down(w.upperClip[step], w.upperFrame[step]) && lowerDown ? 1 : 0;
            }
            worst = std::max(worst, quality::slideOver(w.joints.track(point), kFrame, planted).cmPerContact);
        }
    return worst;
}


// The largest step any joint takes between frames.
double largestStep(const quality::PointSeries& joints) {
    double largest = 0;
    for (int f = 1; f < joints.frames; ++f)
        for (int j = 0; j < joints.points; ++j) largest = std::max(largest, glm::length(joints.at(f, j) - joints.at(f - 1, j)));
    return largest;
}


}  // namespace throng::blendtest
