// Checks the GPU compute pass against the CPU: reads `throng render --dump-instances`
// output, re-bakes each clip from its source file, and recomputes every joint of every
// character on the CPU from the same ground frame, frame position and scale with
// crowd::sampleJointWorld (the C++ twin of shaders/pose.glsl). Passes when
// all positions agree within 1e-5 of the clip's height and orientations within 1e-3 (the fast
// path leaves orientations out). Optionally checks which characters were culled, or that some
// character has a foot twisted (so the twist's path through the shaders is compared too), or
// that some character blends two clips (speed blending's path through the shaders). Also
// checks where each character's joints were written: after the previous character's, in
// character order, on the paths that write only the visible ones.
//   check_instances DUMP.json [--expect-kept 0,2] [--expect-culled 1] [--expect-twist] [--expect-blend]
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "throng/crowd/character_state.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"
#include "dump_character.h"

using namespace throng;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: check_instances DUMP.json [--expect-kept LIST] [--expect-culled LIST] [--expect-twist] [--expect-blend]\n");
        return 2;
    }
    std::optional<std::set<std::size_t>> expectKept, expectCulled;
    bool expectTwist = false, expectBlend = false;
    for (int a = 2; a < argc; ++a) {
        const std::string flag = argv[a];
        if (flag == "--expect-twist" || flag == "--expect-blend") {
            (flag == "--expect-twist" ? expectTwist : expectBlend) = true;
            continue;
        }
        if ((flag != "--expect-kept" && flag != "--expect-culled") || a + 1 >= argc) {
            std::fprintf(stderr, "check_instances: unknown or incomplete option %s\n", flag.c_str());
            return 2;
        }
        std::set<std::size_t> values;
        std::stringstream list(argv[++a]);
        for (std::string item; std::getline(list, item, ',');) values.insert(std::stoul(item));
        (flag == "--expect-kept" ? expectKept : expectCulled) = values;
    }
    std::ifstream in(argv[1]);
    if (!in) {
        std::fprintf(stderr, "check_instances: cannot open %s\n", argv[1]);
        return 2;
    }
    const nlohmann::json dump = nlohmann::json::parse(in);
    const bool checkOrientations = dump.value("path", std::string("compute")) != "fast";
    std::set<std::size_t> kept, culled;
    for (const auto& c : dump.at("characters")) kept.insert(c.at("index").get<std::size_t>());
    for (const auto& c : dump.value("culled", nlohmann::json::array())) culled.insert(c.get<std::size_t>());
    std::vector<motion::BakedClip> clips;
    for (const auto& clip : dump.at("clips")) {
        auto raw = motion::loadBvhFile(clip.at("source").get<std::string>());
        if (!raw) {
            std::fprintf(stderr, "check_instances: %s\n", raw.error().describe().c_str());
            return 2;
        }
        clips.push_back(motion::bake(raw.value()).orThrow());
    }
    double worstPosition = 0, worstRotation = 0;
    std::size_t checked = 0;
    std::set<std::uint32_t> clipsSeen;
    int fractionalFrames = 0;
    int twisted = 0;  // characters with a foot twisted about its ankle (goals mode, turning)
    int blended = 0;      // characters mixing two clips of a locomotion set
    int crossfading = 0;  // characters in a transition
    // The compacting paths write each visible character's joints after the previous one's, in
    // character order (slot_allocation.glsl), so that ties between bodies fall the same way
    // every run; the others each character's at its index times the joints per character.
    const std::string path = dump.value("path", std::string("compute"));
    const bool compacted = path == "fast" || path == "visibility";
    const auto perCharacter = dump.at("joints_per_character").get<std::size_t>();
    std::size_t written = 0;
    bool inOrder = true;
    for (const auto& character : dump.at("characters")) {
        const auto clipIndex = character.at("clip").get<std::uint32_t>();
        const motion::BakedClip& clip = clips.at(clipIndex);
        clipsSeen.insert(clipIndex);
        const double frame = character.at("frame").get<double>();
        fractionalFrames += frame != std::floor(frame) ? 1 : 0;
        const auto twist = character.at("foot_twist").get<std::vector<float>>();  // per leg
        const crowd::CharacterState state = characterFromDump(character);
        blended += state.blend != 0.0F && state.blendClip < clips.size() && state.blendClip != clipIndex ? 1 : 0;
        crossfading += state.fromWeight != 0.0F ? 1 : 0;
        if (state.blendClip >= clips.size() || state.fromClip >= clips.size()) {
            std::fprintf(stderr, "check_instances: a character names a clip that isn't in the dump\n");
            return 1;
        }
        twisted += twist[0] != 0.0F || twist[1] != 0.0F ? 1 : 0;
        const auto& positions = character.at("positions");
        const auto& orientations = character.at("orientations");
        // Which joints were drawn: all of them, or (fast path, far away) the major ones.
        std::vector<int> joints;
        for (const auto& j : character.value("joints", nlohmann::json::array())) joints.push_back(j.get<int>());
        if (joints.empty())
            for (int j = 0; j < clip.jointCount(); ++j) joints.push_back(j);
        if (positions.size() != joints.size()) {
            std::fprintf(stderr, "check_instances: %zu positions for %zu joints\n", positions.size(), joints.size());
            return 1;
        }
        const auto first = character.at("first_instance").get<std::size_t>();
        const std::size_t expectedFirst = compacted ? written : character.at("index").get<std::size_t>() * perCharacter;
        if (first != expectedFirst) {
            std::printf("check_instances: character %zu's joints start at instance %zu, not %zu\n", character.at("index").get<std::size_t>(),
                        first, expectedFirst);
            inOrder = false;
        }
        written += joints.size();
        for (std::size_t slot = 0; slot < joints.size(); ++slot) {
            const int j = joints[slot];
            // CPU: ground frame ∘ (scale × in-place pose), as the compute pass is specified.
            const crowd::JointWorld expected = crowd::sampleJointWorld(clips, state, j);
            const auto p = positions[slot].get<std::vector<double>>();
            worstPosition = std::max(worstPosition, glm::length(glm::dvec3(p[0], p[1], p[2]) - glm::dvec3(expected.position)) / clip.stature);
            if (!checkOrientations) {
                ++checked;
                continue;
            }
            const glm::dquat expectedRotation(expected.orientation);
            const auto q = orientations[slot].get<std::vector<double>>();
            const glm::dquat actual(q[3], q[0], q[1], q[2]);
            // q and -q are the same rotation.
            worstRotation = std::max(worstRotation, 1.0 - std::abs(glm::dot(actual, expectedRotation)));
            ++checked;
        }
    }
    bool pass = worstPosition <= 1e-5 && worstRotation <= 1e-3 && checked > 0 && inOrder;
    if (expectKept && *expectKept != kept) {
        std::printf("check_instances: kept characters differ from the expected ones\n");
        pass = false;
    }
    if (expectCulled && *expectCulled != culled) {
        std::printf("check_instances: culled characters differ from the expected ones\n");
        pass = false;
    }
    if (expectTwist && twisted == 0) {
        std::printf("check_instances: no character has a foot twist, so the twist was not compared\n");
        pass = false;
    }
    if (expectBlend && blended == 0) {
        std::printf("check_instances: no character blends two clips, so the blend was not compared\n");
        pass = false;
    }
    std::printf("check_instances: %zu joints, %zu characters kept, %zu culled, %zu clips, %d fractional frames, %d with a foot "
                "twist, %d blending, %d crossfading, worst position error %.3g of height, worst rotation 1-|dot| %.3g: %s\n",
                checked, kept.size(), culled.size(), clipsSeen.size(), fractionalFrames, twisted, blended, crossfading, worstPosition, worstRotation,
                pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
}
