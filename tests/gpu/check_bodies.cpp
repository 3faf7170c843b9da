// Checks bone bodies against the CPU: reads `throng render --dump-bodies` output, re-bakes
// each clip from its source file, and recomputes the ends of every bone drawn with
// crowd::sampleJointWorld (the C++ twin of shaders/pose.glsl): a bone starts at its joint and
// ends at its child joint, or at its End Site's offset turned by the joint's orientation.
// Passes when every end agrees within 1e-5 of the clip's height, each character's bones were
// written after the previous character's (in character order, so ties between bodies fall the
// same way every run), and each character named by --expect-levels was drawn at that level.
//   check_bodies DUMP.json [--expect-levels 0=skin,1=bones,2=spheres]
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "dump_character.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"

using namespace throng;

int main(int argc, char** argv) {
    std::map<std::size_t, std::string> expectLevels;
    if (argc == 4 && std::string(argv[2]) == "--expect-levels") {
        std::stringstream list(argv[3]);
        for (std::string item; std::getline(list, item, ',');) {
            const auto equals = item.find('=');
            if (equals == std::string::npos) return 2;
            expectLevels[std::stoul(item.substr(0, equals))] = item.substr(equals + 1);
        }
    } else if (argc != 2) {
        std::fprintf(stderr, "usage: check_bodies DUMP.json [--expect-levels INDEX=LEVEL,...]\n");
        return 2;
    }
    std::ifstream in(argv[1]);
    if (!in) {
        std::fprintf(stderr, "check_bodies: cannot open %s\n", argv[1]);
        return 2;
    }
    const nlohmann::json dump = nlohmann::json::parse(in);
    std::vector<motion::BakedClip> clips;
    for (const auto& clip : dump.at("clips")) clips.push_back(motion::bake(motion::loadBvhFile(clip.at("source").get<std::string>()).orThrow()).orThrow());
    double worst = 0.0;
    std::size_t checked = 0;
    std::map<std::string, int> levels;
    bool pass = true;
    std::size_t written = 0;  // bones written before this character's: they go in character order
    for (const auto& character : dump.at("characters")) {
        const crowd::CharacterState state = characterFromDump(character);
        const motion::BakedClip& clip = clips.at(state.clip);
        const auto level = character.at("level").get<std::string>();
        ++levels[level];
        const auto index = character.at("index").get<std::size_t>();
        if (expectLevels.count(index) && expectLevels[index] != level) {
            std::printf("check_bodies: character %zu drawn as %s, expected %s (%.1f pixels tall)\n", index, level.c_str(),
                        expectLevels[index].c_str(), character.at("pixels_tall").get<double>());
            pass = false;
        }
        const auto& bones = character.at("bones");
        if (!bones.empty()) {
            const auto first = character.at("first_bone").get<std::size_t>();
            if (first != written) {
                std::printf("check_bodies: character %zu's bones start at %zu, not %zu (after the previous characters')\n", index, first, written);
                pass = false;
            }
            written += bones.size();
        }
        if (!bones.empty() && bones.size() != clip.body.size()) {
            std::printf("check_bodies: character %zu has %zu bones drawn, its body %zu\n", index, bones.size(), clip.body.size());
            pass = false;
            continue;
        }
        for (std::size_t b = 0; b < bones.size(); ++b) {
            const motion::BodyBone& bone = clip.body[b];
            const crowd::JointWorld joint = crowd::sampleJointWorld(clips, state, bone.joint);
            const glm::dvec3 end = bone.child >= 0 ? glm::dvec3(crowd::sampleJointWorld(clips, state, bone.child).position)
                                                   : glm::dvec3(joint.position) + glm::dvec3(joint.orientation * (bone.tip * state.scale));
            const auto start = bones[b].at("start").get<std::vector<double>>(), finish = bones[b].at("end").get<std::vector<double>>();
            worst = std::max(worst, glm::length(glm::dvec3(start[0], start[1], start[2]) - glm::dvec3(joint.position)) / clip.stature);
            worst = std::max(worst, glm::length(glm::dvec3(finish[0], finish[1], finish[2]) - end) / clip.stature);
            ++checked;
        }
    }
    pass = pass && worst <= 1e-5 && (checked > 0 || !expectLevels.empty());
    std::printf("check_bodies: %zu bones, levels: %d skin, %d bones, %d spheres, %d culled; worst end error %.3g of height: %s\n", checked,
                levels["skin"], levels["bones"], levels["spheres"], levels["culled"], worst, pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
}
