// Bone bodies (--body bones): every skeleton, the project's own and each shared capture, gets
// a plausible body from its structure, and the baked poses place an End Site's tip where the
// GPU puts it (the joint's position plus its rotation applied to the offset).
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "throng/motion/baked_clip.h"
#include "throng/motion/body_bones.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng::motion;

struct Baked {
    std::string name;
    RawMotion raw;
    BakedClip clip;
};

// The project's clips and every shared capture. The shared ones must be there: without them
// these tests would check only the project's own skeleton, so their absence fails.
std::vector<Baked> everySkeleton() {
    std::vector<std::string> paths;
    for (const char* own : {"walk.bvh", "idle.bvh", "run.bvh"})
        paths.push_back(std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path() / own);
    EXPECT_TRUE(std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
    if (std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR))
        for (const auto& entry : std::filesystem::directory_iterator(THRONG_SHARED_MOCAP_DIR))
            if (entry.path().extension() == ".bvh") paths.push_back(entry.path().string());
    std::vector<Baked> out;
    for (const std::string& path : paths) {
        RawMotion raw = loadBvhFile(path).orThrow();
        BakedClip clip = bake(raw).orThrow();
        out.push_back({path, std::move(raw), std::move(clip)});
    }
    return out;
}

const std::vector<Baked>& skeletons() {
    static const std::vector<Baked> all = everySkeleton();
    return all;
}

TEST(BodyBones, EveryBipedHasTwoOfEachLimbBoneAndOneHead) {
    int bipeds = 0;
    for (const Baked& s : skeletons()) {
        if (!s.clip.anatomy.biped()) continue;
        ++bipeds;
        std::map<BodyPart, int> count;
        for (const BodyBone& bone : s.clip.body) ++count[bone.part];
        for (BodyPart part : {BodyPart::Thigh, BodyPart::Shin, BodyPart::UpperArm, BodyPart::Forearm})
            EXPECT_EQ(count[part], 2) << s.name << ": " << bodyPartName(part);
        EXPECT_EQ(count[BodyPart::Head], 1) << s.name;
        EXPECT_GE(count[BodyPart::Foot], 2) << s.name;
        EXPECT_GE(count[BodyPart::Spine], 1) << s.name;
    }
    EXPECT_GE(bipeds, 8);  // the project's three and the shared walks and run
}

TEST(BodyBones, MirroredLimbsMatchInLengthAndEveryRadiusIsPlausible) {
    for (const Baked& s : skeletons()) {
        const double stature = s.clip.stature;
        std::map<BodyPart, std::vector<double>> lengths;
        for (const BodyBone& bone : s.clip.body) {
            EXPECT_GT(bone.radiusStart, 0.0F) << s.name;
            EXPECT_GT(bone.radiusEnd, 0.0F) << s.name;
            EXPECT_LT(bone.radiusStart, 0.1 * stature) << s.name;
            EXPECT_LT(bone.radiusEnd, 0.1 * stature) << s.name;
            EXPECT_GT(bone.thickness, 0.0F);
            EXPECT_LE(bone.thickness, 1.0F);
            if (bone.child >= 0)
                lengths[bone.part].push_back(glm::length(s.raw.joints[static_cast<std::size_t>(bone.child)].offset) * s.clip.metresPerUnit);
        }
        for (BodyPart part : {BodyPart::Thigh, BodyPart::Shin, BodyPart::UpperArm, BodyPart::Forearm}) {
            const std::vector<double>& pair = lengths[part];
            if (pair.size() != 2) continue;  // not a biped: counted above
            EXPECT_NEAR(pair[0], pair[1], 0.1 * std::max(pair[0], pair[1])) << s.name << ": " << bodyPartName(part);
            EXPECT_GT(pair[0], 0.1 * stature) << s.name << ": " << bodyPartName(part);  // a limb, not a twist joint
        }
    }
}

// Names are not what the parts are found from, so they check them independently: every
// exporter here calls the elbow ForeArm, Elbow or LowArm, and the knee Leg, Knee or LowLeg.
TEST(BodyBones, PartsAgreeWithWhatExportersNameTheJoints) {
    const auto lower = [](std::string text) {
        for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return text;
    };
    const auto endsWith = [](const std::string& text, const std::string& tail) {
        return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
    };
    int checked = 0;
    for (const Baked& s : skeletons()) {
        for (const BodyBone& bone : s.clip.body) {
            if (bone.child < 0) continue;
            const std::string name = lower(s.raw.joints[static_cast<std::size_t>(bone.child)].name);
            const bool elbow = endsWith(name, "forearm") || endsWith(name, "elbow") || endsWith(name, "lowarm");
            const bool knee = (endsWith(name, "leg") && !endsWith(name, "upleg")) || endsWith(name, "knee");
            if (elbow) {
                EXPECT_EQ(bone.part, BodyPart::UpperArm) << s.name << ": " << name;
                ++checked;
            }
            if (knee) {
                EXPECT_EQ(bone.part, BodyPart::Thigh) << s.name << ": " << name;
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, 4 * 9);  // two elbows and two knees in each of the nine skeletons that name them so
}

// The GPU puts an End Site's tip at the joint plus the joint's baked rotation applied to the
// offset. Where the answer is known, a child joint, that rule must land on the child.
TEST(BodyBones, BakedRotationsCarryOffsetsToTheChildJoint) {
    for (const Baked& s : skeletons()) {
        const BakedClip& clip = s.clip;
        for (int frame : {0, clip.frameCount / 2, clip.frameCount - 1}) {
            double worst = 0.0;
            for (const BodyBone& bone : clip.body) {
                if (bone.child < 0) continue;
                const JointPose& from = clip.pose(frame, bone.joint);
                const glm::vec3 offset(s.raw.joints[static_cast<std::size_t>(bone.child)].offset * clip.metresPerUnit);
                const glm::vec3 predicted = from.translation + from.rotation * offset;
                worst = std::max(worst, static_cast<double>(glm::length(predicted - clip.pose(frame, bone.child).translation)));
            }
            EXPECT_LT(worst, 0.01 * clip.stature) << s.name << " frame " << frame;
        }
    }
}

TEST(BodyBones, ASkeletonThatIsNoBipedStillGetsABody) {
    const RawMotion raw = parseBvh(
                              "HIERARCHY\nROOT A\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n"
                              " JOINT B\n {\n  OFFSET 0 10 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                              "  End Site\n  {\n   OFFSET 0 10 0\n  }\n }\n}\nMOTION\nFrames: 2\nFrame Time: 0.1\n"
                              "0 0 0 0 0 0\n0 0 0 0 0 0\n",
                              "chain.bvh")
                              .orThrow();
    const BakedClip clip = bake(raw).orThrow();
    ASSERT_EQ(clip.body.size(), 2U);  // A to B, and B to its End Site
    for (const BodyBone& bone : clip.body) {
        EXPECT_EQ(bone.part, BodyPart::Other);
        EXPECT_GT(bone.radiusStart, 0.0F);
    }
    EXPECT_EQ(clip.body[1].child, -1);
    EXPECT_GT(glm::length(clip.body[1].tip), 0.0F);
}

}  // namespace
