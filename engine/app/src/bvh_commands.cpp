#include "bvh_commands.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>
#include <nlohmann/json.hpp>

#include "crowd_scene.h"
#include "output.h"
#include "throng/motion/bvh_parser.h"
#include "throng/motion/forward_kinematics.h"

namespace throng::app {
namespace {

using Json = nlohmann::ordered_json;

int emitJson(const Json& json, const std::string& out) { return writeOutput(out, jsonText(json) + "\n"); }

std::string channelList(const motion::RawJoint& joint) {
    std::string out;
    for (motion::Channel c : joint.channels) out += std::string(out.empty() ? "" : " ") + motion::channelName(c);
    return out.empty() ? "(none)" : out;
}

double medianOf(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// What `bvh info` reports of one clip, worked out once for the text and the JSON.
struct InfoFigures {
    motion::LoopRange loop;
    motion::GroundFrame travel;  ///< Over the loop.
    double loopSeconds = 0.0;
    double straightSpeed = 0.0;  ///< Start to end of the loop, m/s (the arc speed is clip.speed).
    std::string travelJoint;     ///< Its name.
    const char* travelSource = "";
};

InfoFigures figuresOf(const BvhInfoCommand& command, const motion::RawMotion& m, const motion::BakedClip& clip) {
    InfoFigures f;
    f.loop = clip.loop();
    f.travel = clip.rootMotion.loopDisplacement();
    f.loopSeconds = f.loop.length() * m.frameTime;
    f.straightSpeed = f.loopSeconds > 0 ? glm::length(f.travel.position) / f.loopSeconds : 0.0;
    const bool named = clip.travelJoint >= 0 && clip.travelJoint < clip.jointCount();
    f.travelJoint = named ? clip.jointNames[static_cast<std::size_t>(clip.travelJoint)] : "?";
    // Given by --root; else the pelvis the anatomy found; else the bake fell back to the ROOT.
    f.travelSource = !command.bake.travelJoint.empty()                                    ? "given"
                     : clip.anatomy.pelvis >= 0 && clip.anatomy.pelvis == clip.travelJoint ? "found by structure"
                                                                                           : "ROOT";
    return f;
}

// The legs left first (BakedClip::leftLeg), each with its ankle's name.
struct Side {
    const char* name;
    int leg;
    std::string ankle;
};
std::vector<Side> sidesOf(const motion::BakedClip& clip) {
    if (clip.leftLeg < 0) return {};
    std::vector<Side> sides;
    for (int right = 0; right < 2; ++right) {
        const int leg = right == 0 ? clip.leftLeg : 1 - clip.leftLeg;
        const int ankle = clip.anatomy.legs[static_cast<std::size_t>(leg)].ankle;
        sides.push_back({right == 0 ? "left" : "right", leg, ankle >= 0 ? clip.jointNames[static_cast<std::size_t>(ankle)] : "?"});
    }
    return sides;
}

// Where the right foot strikes in the gait phase (0 at the left foot's strike).
std::vector<double> rightStrikePhases(const motion::BakedClip& clip) {
    std::vector<double> phases;
    if (clip.leftLeg < 0 || clip.gaitPhaseAt(clip.loop().first) < 0) return phases;
    for (const motion::FootContact& contact : clip.footContacts[static_cast<std::size_t>(1 - clip.leftLeg)])
        phases.push_back(clip.gaitPhaseAt(contact.strike));
    return phases;
}

void printFootfalls(const motion::BakedClip& clip) {
    const std::vector<Side> sides = sidesOf(clip);
    if (sides.empty()) {
        // findGaitEvents needs two legs and a loop of four frames or more.
        const bool twoLegs = clip.anatomy.biped();
        std::printf("Footfalls:   none (%s)\n", twoLegs ? "the clip is too short for a gait cycle" : "no two-legged skeleton found");
        return;
    }
    std::string line;
    for (const Side& side : sides) {
        line += std::string(line.empty() ? "" : "; ") + side.name + " (" + side.ankle + ")";
        const auto& contacts = clip.footContacts[static_cast<std::size_t>(side.leg)];
        if (contacts.empty()) line += " no strike in the loop";
        for (std::size_t c = 0; c < contacts.size(); ++c)
            line += std::string(c == 0 ? " " : ", ") + "strike " + std::to_string(contacts[c].strike) + " lift " + std::to_string(contacts[c].lift);
    }
    std::printf("Footfalls:   %s\n", line.c_str());
    const std::vector<double> right = rightStrikePhases(clip);
    if (clip.gaitPhaseAt(clip.loop().first) < 0) {
        std::printf("Gait phase:  none (the left foot never strikes in the loop)\n");
        return;
    }
    std::string at;
    for (double phase : right) at += (at.empty() ? "" : ", ") + std::to_string(phase).substr(0, 4);
    std::printf("Gait phase:  0 at frame %d (left strike); the right foot strikes at %s\n",
                clip.footContacts[static_cast<std::size_t>(clip.leftLeg)].front().strike, at.empty() ? "none" : at.c_str());
}

Json footfallsJson(const motion::BakedClip& clip) {
    Json out = Json::object();
    for (const Side& side : sidesOf(clip)) {
        Json contacts = Json::array();
        for (const motion::FootContact& c : clip.footContacts[static_cast<std::size_t>(side.leg)])
            contacts.push_back({{"strike", c.strike}, {"lift", c.lift}});
        out[side.name] = {{"ankle", side.ankle}, {"contacts", contacts}};
    }
    return out;
}

void printJoints(const motion::RawMotion& m) {
    std::printf("\n  %-4s %-28s %-20s %s\n", "#", "joint", "parent", "channels");
    // Depth from the parent's, which the parser writes first: walking each joint's chain to the
    // root would be quadratic in a deep skeleton's depth (a minute for 100,000 joints).
    std::vector<int> depths(static_cast<std::size_t>(m.jointCount()), 0);
    for (int j = 0; j < m.jointCount(); ++j) {
        const motion::RawJoint& joint = m.joints[static_cast<std::size_t>(j)];
        const int depth = joint.parent >= 0 && joint.parent < j ? depths[static_cast<std::size_t>(joint.parent)] + 1 : 0;
        depths[static_cast<std::size_t>(j)] = depth;
        const std::string indented = std::string(static_cast<std::size_t>(std::min(depth, 12)), ' ') + joint.name;
        std::printf("  %-4d %-28s %-20s %s\n", j, indented.c_str(),
                    joint.parent < 0 ? "-" : m.joints[static_cast<std::size_t>(joint.parent)].name.c_str(),
                    channelList(joint).c_str());
    }
}

// The body --body bones draws: each bone's part, found from the skeleton's structure.
std::string boneEnd(const motion::RawMotion& m, const motion::BodyBone& bone) {
    return bone.child >= 0 ? m.joints[static_cast<std::size_t>(bone.child)].name : "(end)";
}

void printBody(const motion::RawMotion& m, const motion::BakedClip& clip) {
    std::printf("\n  Body (--body bones): %zu bones\n  %-22s %-22s %-10s %s\n", clip.body.size(), "from", "to", "part", "radius (m)");
    for (const motion::BodyBone& bone : clip.body)
        std::printf("  %-22s %-22s %-10s %.3f..%.3f%s\n", m.joints[static_cast<std::size_t>(bone.joint)].name.c_str(), boneEnd(m, bone).c_str(),
                    std::string(motion::bodyPartName(bone.part)).c_str(), static_cast<double>(bone.radiusStart),
                    static_cast<double>(bone.radiusEnd), bone.thickness < 1.0F ? " flattened" : "");
}

void printInfo(const motion::RawMotion& m, const motion::BakedClip& clip, const InfoFigures& f) {
    std::printf("File:        %s\n", m.sourceName.c_str());
    std::printf("Joints:      %d (+%zu End Sites), %d channels per frame\n", m.jointCount(), m.endSites.size(), m.channelCount);
    std::printf("Frames:      %d at %.7g s (%.2f fps), duration %.3f s\n", m.frameCount, m.frameTime, 1.0 / m.frameTime,
                m.frameCount * m.frameTime);
    std::printf("Height:      %.4g file units = %.3f m (units: %s, %s)\n", clip.stature / clip.metresPerUnit, clip.stature,
                clip.unitName.c_str(), clip.unitInferred ? "inferred" : "given");
    std::printf("Stature:     %.3f m\n", clip.stature);
    std::printf("Up axis:     %s (%s)\n", motion::upAxisName(clip.upAxis), clip.upAxisInferred ? "detected" : "given");
    std::printf("Travel joint: %s (%s)\n", f.travelJoint.c_str(), f.travelSource);
    std::printf("Speed:       %.2f m/s along the path, turns %.1f deg/s\n", clip.speed, glm::degrees(clip.turnRate));
    std::printf("Loop:        frames %d..%d (%d frames, %.3f s), travels %.3f m at %.2f m/s, turns %.1f deg\n", f.loop.first,
                f.loop.last, f.loop.length(), f.loopSeconds, glm::length(f.travel.position), f.straightSpeed,
                glm::degrees(f.travel.yaw));
    if (clip.gaitPeriodFrames > 0)
        std::printf("Gait period: %.0f frames (%.3f s)\n", clip.gaitPeriodFrames, clip.gaitPeriodFrames * m.frameTime);
    else
        std::printf("Gait period: none found (not cyclic locomotion?)\n");
    printFootfalls(clip);
    if (clip.firstFrameSkipped) std::printf("First frame: skipped (looks like a synthetic T-pose)\n");
    if (!clip.warnings.empty()) std::printf("Warnings:\n");
    for (const std::string& warning : clip.warnings) std::printf("  - %s\n", warning.c_str());
    printJoints(m);
    printBody(m, clip);
}

// The keys scripts read; new ones are added, none renamed ("height_m" is the stature).
Json infoJson(const motion::RawMotion& m, const motion::BakedClip& clip, const InfoFigures& f) {
    Json json;
    json["file"] = m.sourceName;
    Json joints = Json::array();
    for (const motion::RawJoint& joint : m.joints)
        joints.push_back({{"name", joint.name}, {"parent", joint.parent}, {"channels", channelList(joint)}});
    json["joints"] = joints;
    json["end_sites"] = m.endSites.size();
    Json body = Json::array();
    for (const motion::BodyBone& bone : clip.body)
        body.push_back({{"from", m.joints[static_cast<std::size_t>(bone.joint)].name}, {"to", bone.child >= 0 ? Json(boneEnd(m, bone)) : Json(nullptr)},
                        {"part", motion::bodyPartName(bone.part)}, {"radius_start_m", bone.radiusStart}, {"radius_end_m", bone.radiusEnd}});
    json["body"] = body;
    json["channels_per_frame"] = m.channelCount;
    json["frame_count"] = m.frameCount;
    json["frame_time"] = m.frameTime;
    json["duration"] = m.frameCount * m.frameTime;
    json["height_m"] = clip.stature;
    json["metres_per_unit"] = clip.metresPerUnit;
    json["units"] = clip.unitName;
    json["units_inferred"] = clip.unitInferred;
    json["loop"] = {{"first", f.loop.first}, {"last", f.loop.last}};
    json["loop_travel_m"] = glm::length(f.travel.position);
    json["loop_turn_deg"] = glm::degrees(f.travel.yaw);
    json["gait_period_frames"] = clip.gaitPeriodFrames;
    json["first_frame_skipped"] = clip.firstFrameSkipped;
    json["stature_m"] = clip.stature;
    json["up_axis"] = motion::upAxisName(clip.upAxis);
    json["up_axis_inferred"] = clip.upAxisInferred;
    json["travel_joint"] = f.travelJoint;
    json["speed_mps"] = clip.speed;
    json["turn_rate_deg_s"] = glm::degrees(clip.turnRate);
    json["locomotion"] = clip.locomotion;
    json["static"] = clip.isStatic;
    json["footfalls"] = footfallsJson(clip);
    const bool timed = clip.gaitPhaseAt(clip.loop().first) >= 0;
    json["gait_phase_zero_frame"] = timed ? Json(clip.footContacts[static_cast<std::size_t>(clip.leftLeg)].front().strike) : Json(nullptr);
    json["right_strike_phases"] = rightStrikePhases(clip);
    json["warnings"] = clip.warnings;
    return json;
}

}  // namespace

int runBvhInfo(const BvhInfoCommand& command) {
    // Before the summary is printed: a --json with nowhere to go fails alone, not after it.
    if (command.jsonOut)
        if (auto problem = checkOutputPath(*command.jsonOut, "--json")) return reportError(*problem);
    auto raw = motion::loadBvhFile(command.file);
    if (!raw) return reportError(raw.error());
    auto baked = motion::bake(raw.value(), command.bake);
    if (!baked) return reportError(baked.error());
    const InfoFigures figures = figuresOf(command, raw.value(), baked.value());
    if (command.jsonOut != "-") printInfo(raw.value(), baked.value(), figures);
    if (!command.jsonOut) return 0;
    return emitJson(infoJson(raw.value(), baked.value(), figures), *command.jsonOut);
}

// The frames to write, in the order asked, each once (they become the keys of one object).
Result<std::vector<int>> bakeFrames(const BvhBakeCommand& command, const motion::RawMotion& m) {
    std::vector<int> frames;
    if (!command.frames) {
        for (int f = 0; f < m.frameCount; ++f) frames.push_back(f);
        return frames;
    }
    std::vector<bool> seen(static_cast<std::size_t>(m.frameCount), false);
    for (int f : *command.frames) {
        if (f >= m.frameCount)
            return Error{Error::Kind::BadInput,
                         "--frames asks for frame " + std::to_string(f) + " but the clip has " + std::to_string(m.frameCount) +
                             " frames (0.." + std::to_string(m.frameCount - 1) + ")",
                         {m.sourceName, 0, 0}};
        if (!seen[static_cast<std::size_t>(f)]) frames.push_back(f);
        seen[static_cast<std::size_t>(f)] = true;
    }
    return frames;
}

int runBvhBake(const BvhBakeCommand& command) {
    if (auto problem = checkOutputPath(command.jsonOut, "--json")) return reportError(*problem);
    // Raw forward kinematics only: no bake, so no unit guess and no loop search.
    auto raw = motion::loadBvhFile(command.file);
    if (!raw) return reportError(raw.error());
    const motion::RawMotion& m = raw.value();
    auto frames = bakeFrames(command, m);
    if (!frames) return reportError(frames.error());
    Json json;
    Json names = Json::array(), parents = Json::array();
    for (const motion::RawJoint& joint : m.joints) {
        names.push_back(joint.name);
        parents.push_back(joint.parent);
    }
    json["joints"] = names;
    json["parents"] = parents;
    json["frame_time"] = m.frameTime;
    json["frame_count"] = m.frameCount;
    // "frames" is written frame by frame: an ordered_json object finds each new key by a
    // linear search, which made a 160,000-frame file take half a minute.
    std::string text = jsonText(json);
    text.pop_back();  // the closing '}'
    text += R"(,"frames":{)";
    for (std::size_t i = 0; i < frames.value().size(); ++i) {
        const int f = frames.value()[i];
        Json positions = Json::array();
        for (const glm::dmat4& g : motion::globalTransforms(m, f, command.positionChannels)) positions.push_back({g[3].x, g[3].y, g[3].z});
        text += (i == 0 ? "\"" : ",\"") + std::to_string(f) + "\":" + jsonText(positions);
    }
    text += "}}\n";
    return writeOutput(command.jsonOut, text);
}

int runBvhBench(const BvhBenchCommand& command) {
    std::vector<std::string> files = command.files;
    if (files.empty()) files.push_back(defaultClipPath());
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::printf("%-44s %8s %7s %10s %10s %10s %10s\n", "file", "frames", "joints", "parse_ms", "bake_ms", "total_ms",
                "spread_ms");
    for (const std::string& file : files) {
        std::vector<double> parse, bakeTimes, total;
        int frames = 0, joints = 0;
        for (int run = 0; run < command.repeat + 1; ++run) {  // run 0 warms caches and is dropped
            const auto t0 = Clock::now();
            auto raw = motion::loadBvhFile(file);
            if (!raw) return reportError(raw.error());
            const auto t1 = Clock::now();
            auto baked = motion::bake(raw.value());
            if (!baked) return reportError(baked.error());
            const auto t2 = Clock::now();
            frames = raw.value().frameCount;
            joints = raw.value().jointCount();
            if (run == 0) continue;
            parse.push_back(ms(t1 - t0));
            bakeTimes.push_back(ms(t2 - t1));
            total.push_back(ms(t2 - t0));
        }
        const auto [lo, hi] = std::minmax_element(total.begin(), total.end());
        std::string shown = file.size() > 44 ? "..." + file.substr(file.size() - 41) : file;
        std::printf("%-44s %8d %7d %10.3f %10.3f %10.3f %10.3f\n", shown.c_str(), frames, joints, medianOf(parse),
                    medianOf(bakeTimes), medianOf(total), *hi - *lo);
    }
    std::printf("(median of %d runs per file; spread = max - min of total)\n", command.repeat);
    return 0;
}

}  // namespace throng::app
