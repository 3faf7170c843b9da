// Skinned bodies (--body skin): the mesh generated from any skeleton's bones is closed and
// consistently wound, its weights are well formed, and, skinned with dual quaternions over
// every frame of every clip (computed here, independently of the engine), each vertex stays
// on its bones: within the bone's radius plus 2 cm of one of the segments it is weighted to,
// and no closer than a third of that radius (no collapse where a joint bends).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "throng/motion/baked_clip.h"
#include "throng/motion/body_mesh.h"
#include "throng/motion/bvh_parser.h"

namespace {

using namespace throng::motion;

struct Named {
    std::string name;
    BakedClip clip;
    BodyMesh mesh;
};

const std::vector<Named>& everyBody() {
    static const std::vector<Named> all = [] {
        std::vector<std::string> paths;
        for (const char* own : {"walk.bvh", "run.bvh"}) paths.push_back(std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path() / own);
        EXPECT_TRUE(std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) << "no shared mocap directory: " << THRONG_SHARED_MOCAP_DIR;
        if (std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR))
            for (const auto& entry : std::filesystem::directory_iterator(THRONG_SHARED_MOCAP_DIR))
                if (entry.path().extension() == ".bvh") paths.push_back(entry.path().string());
        std::sort(paths.begin(), paths.end());
        std::vector<Named> out;
        for (const std::string& path : paths) {
            BakedClip clip = bake(loadBvhFile(path).orThrow()).orThrow();
            const auto start = std::chrono::steady_clock::now();
            BodyMesh mesh = makeBodyMesh(clip);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            std::printf("%s: %zu vertices, %zu triangles, %.1f ms\n", path.c_str(), mesh.vertices.size(), mesh.indices.size() / 3, ms);
            out.push_back({path, std::move(clip), std::move(mesh)});
        }
        return out;
    }();
    return all;
}

// Every edge is used once in each direction: closed, and wound the same way throughout.
void expectWatertight(const BodyMesh& mesh, const std::string& name) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    ASSERT_EQ(mesh.indices.size() % 3, 0U) << name;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) ++directed[{mesh.indices[t + e], mesh.indices[t + (e + 1) % 3]}];
    int bad = 0;
    for (const auto& [edge, count] : directed)
        if (count != 1 || directed.count({edge.second, edge.first}) == 0 || directed.at({edge.second, edge.first}) != 1) ++bad;
    EXPECT_EQ(bad, 0) << name << ": edges not shared by exactly two triangles, once each way";
}

double signedVolume(const BodyMesh& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = mesh.vertices[mesh.indices[t]].position, b = mesh.vertices[mesh.indices[t + 1]].position,
                         c = mesh.vertices[mesh.indices[t + 2]].position;
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

TEST(BodyMesh, EveryBodyIsClosedOutwardAndFinite) {
    ASSERT_GE(everyBody().size(), 9U);
    for (const Named& body : everyBody()) {
        const BodyMesh& mesh = body.mesh;
        ASSERT_GT(mesh.vertices.size(), 500U) << body.name;
        expectWatertight(mesh, body.name);
        // A person's volume: 40 to 120 litres at 1.75 m, scaled by stature cubed.
        const double litres = 1000.0 * signedVolume(mesh) * std::pow(1.75 / body.clip.stature, 3.0);
        EXPECT_GT(litres, 40.0) << body.name;
        EXPECT_LT(litres, 120.0) << body.name;
        for (const SkinVertex& v : mesh.vertices) {
            ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z)) << body.name;
            ASSERT_NEAR(glm::length(v.normal), 1.0F, 1e-4F) << body.name;
            int total = 0;
            for (std::size_t i = 0; i < 4; ++i) {
                total += v.weights[i];
                if (v.weights[i] > 0) {
                    EXPECT_LT(v.joints[i], body.clip.jointCount()) << body.name;
                }
                if (i > 0) {
                    EXPECT_LE(v.weights[i], v.weights[i - 1]) << body.name;
                }
            }
            ASSERT_EQ(total, 255) << body.name;
            ASSERT_LT(v.mainBone, body.clip.body.size()) << body.name;
        }
    }
}

// Dual quaternions, written out here: real part r (rotation), dual part d = 0.5 * t * r.
struct DualQuat {
    glm::dquat real{1, 0, 0, 0}, dual{0, 0, 0, 0};
};
DualQuat fromRigid(glm::dquat rotation, glm::dvec3 translation) {
    return {rotation, 0.5 * glm::dquat(0.0, translation.x, translation.y, translation.z) * rotation};
}
glm::dvec3 applyBlended(const DualQuat& q, glm::dvec3 p) {
    const double norm = glm::length(q.real);
    const glm::dquat r = q.real / norm, d = q.dual / norm;
    const glm::dquat t = 2.0 * d * glm::conjugate(r);
    return r * p + glm::dvec3(t.x, t.y, t.z);
}

double segmentDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, double& along) {
    const glm::dvec3 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    along = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + along * ab);
}

// Each joint's skinning transform, pose * inverse(bind).
std::vector<DualQuat> skinningAt(const BodyMesh& mesh, std::span<const JointPose> pose) {
    std::vector<DualQuat> skinning(pose.size());
    for (std::size_t j = 0; j < pose.size(); ++j) {
        glm::dquat rotation = glm::dquat(pose[j].rotation) * glm::inverse(glm::dquat(mesh.bind[j].rotation));
        const glm::dvec3 bindAt = mesh.bind[j].translation;
        skinning[j] = fromRigid(rotation, glm::dvec3(pose[j].translation) - rotation * bindAt);
    }
    return skinning;
}

glm::dvec3 skin(const SkinVertex& v, const std::vector<DualQuat>& skinning) {
    DualQuat blended{{0, 0, 0, 0}, {0, 0, 0, 0}};
    const glm::dquat pivot = skinning[v.joints[0]].real;
    for (std::size_t i = 0; i < 4 && v.weights[i] > 0; ++i) {
        const DualQuat& q = skinning[v.joints[i]];
        const double w = v.weights[i] / 255.0 * (glm::dot(q.real, pivot) < 0.0 ? -1.0 : 1.0);
        blended.real += w * q.real;
        blended.dual += w * q.dual;
    }
    return applyBlended(blended, v.position);
}

TEST(BodyMesh, SkinnedVerticesStayOnTheirBonesOverEveryFrame) {
    for (const Named& body : everyBody()) {
        const BakedClip& clip = body.clip;
        const auto joints = static_cast<std::size_t>(clip.jointCount());
        double worstOut = -1.0, worstKept = 2.0;
        for (int frame = 0; frame < clip.frameCount; frame += std::max(1, clip.frameCount / 120)) {
            const std::span<const JointPose> pose(clip.poses.data() + static_cast<std::size_t>(frame) * joints, joints);
            const std::vector<DualQuat> skinning = skinningAt(body.mesh, pose);
            for (const SkinVertex& v : body.mesh.vertices) {
                const glm::dvec3 p = skin(v, skinning);
                double out = 1e9;  // beyond the surface of every bone of its joints
                for (const BodyBone& bone : clip.body) {
                    if (std::find(v.joints.begin(), v.joints.end(), static_cast<std::uint16_t>(bone.joint)) == v.joints.end()) continue;
                    const auto ends = boneEnds(bone, pose);
                    double along = 0.0;
                    const double d = segmentDistance(p, ends[0], ends[1], along);
                    out = std::min(out, d - (bone.radiusStart + along * (bone.radiusEnd - bone.radiusStart)));
                }
                worstOut = std::max(worstOut, out);
                // Shared by a joint and its child alone: the blend turns the vertex about the
                // child joint, keeping its distance from it (linear blending would pull it in,
                // to cos(bend / 2) of it for an even share: the collapsing elbow).
                const int first = v.joints[0], second = v.joints[1];
                if (v.weights[1] < 64 || v.weights[2] > 0) continue;
                const int pivot = clip.parents[static_cast<std::size_t>(second)] == first ? second
                                : clip.parents[static_cast<std::size_t>(first)] == second ? first : -1;
                if (pivot < 0) continue;
                const double bindReach = glm::distance(glm::dvec3(v.position), glm::dvec3(body.mesh.bind[static_cast<std::size_t>(pivot)].translation));
                if (bindReach > 0.01) worstKept = std::min(worstKept, glm::distance(p, glm::dvec3(pose[static_cast<std::size_t>(pivot)].translation)) / bindReach);
            }
        }
        std::printf("%s: farthest out %.1f mm; about a bending joint, kept %.2f of the distance\n", body.name.c_str(), worstOut * 1000.0, worstKept);
        EXPECT_LE(worstOut, 0.02) << body.name;
        EXPECT_GE(worstKept, 0.9) << body.name;
    }
}

TEST(BodyMesh, IsTheSameEveryTime) {
    const Named& body = everyBody().front();
    const BodyMesh again = makeBodyMesh(body.clip);
    ASSERT_EQ(again.vertices.size(), body.mesh.vertices.size());
    EXPECT_EQ(again.indices, body.mesh.indices);
    for (std::size_t v = 0; v < again.vertices.size(); ++v) ASSERT_EQ(again.vertices[v].position, body.mesh.vertices[v].position);
}

// Skeletons that are no person still get a closed body with finite vertices, or none at all
// (a lone joint with no End Site has no bone), never NaN.
BakedClip bakeText(const std::string& text) { return bake(parseBvh(text, "hostile.bvh").orThrow()).orThrow(); }

std::string chain(int joints, double length) {
    std::string text = "HIERARCHY\nROOT j0\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
    for (int j = 1; j < joints; ++j) text += " JOINT j" + std::to_string(j) + "\n {\n OFFSET 0 " + std::to_string(length) + " 0\n CHANNELS 3 Zrotation Xrotation Yrotation\n";
    text += " End Site\n {\n OFFSET 0 " + std::to_string(length) + " 0\n }\n";
    for (int j = 1; j < joints; ++j) text += " }\n";
    text += "}\nMOTION\nFrames: 2\nFrame Time: 0.033333\n";
    for (int f = 0; f < 2; ++f) {
        text += "0 0 0 0 0 0";
        for (int j = 1; j < joints; ++j) text += " " + std::to_string(10 * f) + " 0 0";
        text += "\n";
    }
    return text;
}

void expectSoundOrEmpty(const BakedClip& clip, const std::string& name) {
    const BodyMesh mesh = makeBodyMesh(clip);
    EXPECT_EQ(mesh.bind.size(), static_cast<std::size_t>(clip.jointCount())) << name;
    if (clip.body.empty()) {
        EXPECT_TRUE(mesh.vertices.empty()) << name;
        return;
    }
    ASSERT_FALSE(mesh.vertices.empty()) << name;
    expectWatertight(mesh, name);
    for (const SkinVertex& v : mesh.vertices) {
        ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z)) << name;
        ASSERT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.y) && std::isfinite(v.normal.z)) << name;
    }
}

TEST(BodyMesh, OddSkeletonsGetABodyOrNone) {
    expectSoundOrEmpty(bakeText(chain(1, 10.0)), "one joint with an End Site");
    expectSoundOrEmpty(bakeText(chain(6, 10.0)), "a plain chain, no limbs");
    expectSoundOrEmpty(bakeText(chain(6, 0.0)), "zero-length bones");
    expectSoundOrEmpty(bakeText("HIERARCHY\nROOT lone\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0\n"),
                       "one joint, no End Site");
}

}  // namespace
