// Forward kinematics on raw BVH data, checked against answers worked out independently of
// the code under test: right-angle rotations whose effect on a vector is obvious, a tiny
// explicit 3×3 implementation written here from the textbook formulas, and positions of the
// classic Biovision example computed by a separate script.
//
// Convention under test: local = T · R1 · R2 · R3 for rotation channels listed R1 R2 R3,
// column vectors, degrees; global = parent global × local.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "throng/motion/baked_clip.h"
#include "throng/motion/bvh_parser.h"
#include "throng/motion/forward_kinematics.h"

namespace {

using throng::motion::Channel;
using throng::motion::globalTransforms;
using throng::motion::LocalToGlobalJob;
using throng::motion::PositionChannels;
using throng::motion::RawJoint;
using throng::motion::RawMotion;

constexpr double kEps = 1e-9;

RawMotion parseOk(std::string_view text) {
    auto result = throng::motion::parseBvh(text, "fk.bvh");
    if (!result.ok()) {
        ADD_FAILURE() << result.error().describe();
        return {};
    }
    return std::move(result).value();
}

glm::dvec3 positionOf(const glm::dmat4& m) { return {m[3][0], m[3][1], m[3][2]}; }

#define EXPECT_VEC3_NEAR(actual, ex, ey, ez, tol)    \
    do {                                             \
        const glm::dvec3 a_ = (actual);              \
        EXPECT_NEAR(a_.x, (ex), (tol)) << "x";       \
        EXPECT_NEAR(a_.y, (ey), (tol)) << "y";       \
        EXPECT_NEAR(a_.z, (ez), (tol)) << "z";       \
    } while (false)

// --- An independent 3×3 rotation implementation, row-major, from the textbook formulas ---

using Mat3 = std::array<std::array<double, 3>, 3>;  // m[row][column]
using Vec3 = std::array<double, 3>;

Mat3 axisRotation(char axis, double degrees) {
    const double a = degrees * 3.14159265358979323846 / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    switch (axis) {
        case 'X': return Mat3{{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
        case 'Y': return Mat3{{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
        default: return Mat3{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
    }
}

Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            for (std::size_t k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

Vec3 apply(const Mat3& m, const Vec3& v) {
    Vec3 r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = 0; k < 3; ++k) r[i] += m[i][k] * v[k];
    return r;
}

Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

/// R1 · R2 · R3 for an order like "ZXY", taking each axis's angle from `anglesXyz`.
Mat3 orderedRotation(std::string_view order, const Vec3& anglesXyz) {
    Mat3 r{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (char axis : order) r = multiply(r, axisRotation(axis, anglesXyz[static_cast<std::size_t>(axis - 'X')]));
    return r;
}

std::string channelsFor(std::string_view order) {
    std::string out;
    for (char axis : order) out += std::string(" ") + axis + "rotation";
    return out;
}

// --- Rotation orders --------------------------------------------------------------------

struct OrderCase {
    const char* order;
    Vec3 expectedChild;  // world position of the child, derived by hand in the comment below
};

// Root at (10, 20, 30) with 90° about each of its three rotation axes; child OFFSET (1, 2, 3).
// 90° rotations act on (x, y, z) as:
//   Rx: (x, -z, y)     Ry: (z, y, -x)     Rz: (-y, x, z)
// and R1·R2·R3·v applies R3 first. For v = (1, 2, 3):
//   XYZ: Rz->(-2,1,3)  Ry->(3,1,2)   Rx->(3,-2,1)   => (13, 18, 31)
//   XZY: Ry->(3,2,-1)  Rz->(-2,3,-1) Rx->(-2,1,3)   => ( 8, 21, 33)
//   YXZ: Rz->(-2,1,3)  Rx->(-2,-3,1) Ry->(1,-3,2)   => (11, 17, 32)
//   YZX: Rx->(1,-3,2)  Rz->(3,1,2)   Ry->(2,1,-3)   => (12, 21, 27)
//   ZXY: Ry->(3,2,-1)  Rx->(3,1,2)   Rz->(-1,3,2)   => ( 9, 23, 32)
//   ZYX: Rx->(1,-3,2)  Ry->(2,-3,-1) Rz->(3,2,-1)   => (13, 22, 29)
class RotationOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(RotationOrder, RightAnglesGiveHandDerivedChildPosition) {
    const OrderCase& c = GetParam();
    const std::string text = std::string("HIERARCHY\nROOT Root\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition") +
                             channelsFor(c.order) +
                             "\n  JOINT Child\n  {\n    OFFSET 1 2 3\n    CHANNELS 0\n"
                             "    End Site\n    {\n      OFFSET 0 0 1\n    }\n  }\n}\n"
                             "MOTION\nFrames: 1\nFrame Time: 0.1\n10 20 30 90 90 90\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 2);
    const auto globals = globalTransforms(m, 0, PositionChannels::Replace);
    ASSERT_EQ(globals.size(), 2U);
    EXPECT_VEC3_NEAR(positionOf(globals[0]), 10.0, 20.0, 30.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), c.expectedChild[0], c.expectedChild[1], c.expectedChild[2], kEps);
}

TEST_P(RotationOrder, DistinctAnglesMatchIndependentMatrices) {
    // Different angle per axis, so a value read for the wrong axis shows; a three-joint chain,
    // so parent × local composition is exercised twice.
    const OrderCase& c = GetParam();
    const Vec3 rootAngles{30.0, -50.0, 70.0};   // X, Y, Z
    const Vec3 childAngles{-15.0, 25.0, 40.0};  // X, Y, Z
    const std::string order = c.order;
    auto rowValues = [&](const Vec3& anglesXyz) {
        std::string out;
        for (char axis : order) out += " " + std::to_string(anglesXyz[static_cast<std::size_t>(axis - 'X')]);
        return out;
    };
    const std::string text = "HIERARCHY\nROOT Root\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition" +
                             channelsFor(order) +
                             "\n  JOINT Child\n  {\n    OFFSET 1 2 3\n    CHANNELS 3" + channelsFor(order) +
                             "\n    JOINT Tip\n    {\n      OFFSET 0 0 4\n      CHANNELS 0\n"
                             "      End Site\n      {\n        OFFSET 0 0 1\n      }\n    }\n  }\n}\n"
                             "MOTION\nFrames: 1\nFrame Time: 0.1\n-4 5 6" +
                             rowValues(rootAngles) + rowValues(childAngles) + "\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 3);

    const Mat3 rootR = orderedRotation(order, rootAngles);
    const Mat3 childR = multiply(rootR, orderedRotation(order, childAngles));
    const Vec3 rootP{-4.0, 5.0, 6.0};
    const Vec3 childP = add(rootP, apply(rootR, {1.0, 2.0, 3.0}));
    const Vec3 tipP = add(childP, apply(childR, {0.0, 0.0, 4.0}));

    const auto globals = globalTransforms(m, 0, PositionChannels::Replace);
    ASSERT_EQ(globals.size(), 3U);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), childP[0], childP[1], childP[2], kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[2]), tipP[0], tipP[1], tipP[2], kEps);
    const std::array<const Mat3*, 3> rotations{&rootR, &childR, &childR};
    for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t row = 0; row < 3; ++row)
            for (std::size_t col = 0; col < 3; ++col) {
                // glm is column-major: m[col][row].
                EXPECT_NEAR(globals[j][static_cast<glm::length_t>(col)][static_cast<glm::length_t>(row)],
                            (*rotations[j])[row][col], kEps)
                    << "joint " << j << " element (" << row << ", " << col << ")";
            }
    EXPECT_DOUBLE_EQ(globals[2][3][3], 1.0);
    EXPECT_DOUBLE_EQ(globals[2][0][3], 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllSix, RotationOrder,
                         ::testing::Values(OrderCase{"XYZ", {13, 18, 31}}, OrderCase{"XZY", {8, 21, 33}},
                                           OrderCase{"YXZ", {11, 17, 32}}, OrderCase{"YZX", {12, 21, 27}},
                                           OrderCase{"ZXY", {9, 23, 32}}, OrderCase{"ZYX", {13, 22, 29}}),
                         [](const ::testing::TestParamInfo<OrderCase>& param) { return std::string(param.param.order); });

TEST(ForwardKinematics, SingleAxisRotationsFollowTheRightHandRule) {
    // +90° about X takes +Y to +Z; about Y takes +Z to +X; about Z takes +X to +Y.
    struct Case {
        const char* channel;
        const char* offset;
        glm::dvec3 expected;
    };
    for (const Case& c : {Case{"Xrotation", "0 1 0", {0, 0, 1}}, Case{"Yrotation", "0 0 1", {1, 0, 0}},
                          Case{"Zrotation", "1 0 0", {0, 1, 0}}}) {
        SCOPED_TRACE(c.channel);
        const std::string text = std::string("HIERARCHY\nROOT R\n{\nOFFSET 0 0 0\nCHANNELS 1 ") + c.channel +
                                 "\nJOINT C\n{\nOFFSET " + c.offset +
                                 "\nCHANNELS 0\n}\n}\nMOTION\nFrames: 1\nFrame Time: 1\n90\n";
        const RawMotion m = parseOk(text);
        ASSERT_EQ(m.jointCount(), 2);
        const auto globals = globalTransforms(m, 0, PositionChannels::Replace);
        EXPECT_VEC3_NEAR(positionOf(globals[1]), c.expected.x, c.expected.y, c.expected.z, kEps);
    }
}

// --- Position channels ------------------------------------------------------------------

// Root: OFFSET (100, 0, 0), one channel Xrotation = 90 (so it keeps its OFFSET, and maps
// (x, y, z) to (x, -z, y)). Child: OFFSET (1, 0, 0) with all six channels, positions
// (0, 5, 0) and Zrotation 90 (maps (x, y, z) to (-y, x, z)). Grandchild: OFFSET (2, 0, 0).
constexpr std::string_view kSixChannelChild =
    "HIERARCHY\n"
    "ROOT R\n"
    "{\n"
    "  OFFSET 100 0 0\n"
    "  CHANNELS 1 Xrotation\n"
    "  JOINT C\n"
    "  {\n"
    "    OFFSET 1 0 0\n"
    "    CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "    JOINT G\n"
    "    {\n"
    "      OFFSET 2 0 0\n"
    "      CHANNELS 0\n"
    "      End Site\n"
    "      {\n"
    "        OFFSET 0 1 0\n"
    "      }\n"
    "    }\n"
    "  }\n"
    "}\n"
    "MOTION\n"
    "Frames: 1\n"
    "Frame Time: 0.1\n"
    "90 0 5 0 90 0 0\n";

TEST(ForwardKinematics, SixChannelChildReplacesOffsetByDefault) {
    EXPECT_EQ(throng::motion::BakeOptions{}.positionChannels, PositionChannels::Replace);
    const RawMotion m = parseOk(kSixChannelChild);
    ASSERT_EQ(m.jointCount(), 3);
    const auto globals = globalTransforms(m, 0, PositionChannels::Replace);
    // Child local translation is (0, 5, 0); Rx90 -> (0, 0, 5); plus root (100, 0, 0).
    EXPECT_VEC3_NEAR(positionOf(globals[0]), 100.0, 0.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), 100.0, 0.0, 5.0, kEps);
    // Grandchild: Rz90 (2,0,0) = (0,2,0); Rx90 -> (0,0,2); plus the child's position.
    EXPECT_VEC3_NEAR(positionOf(globals[2]), 100.0, 0.0, 7.0, kEps);
}

TEST(ForwardKinematics, SixChannelChildAddsToOffsetInAddMode) {
    const RawMotion m = parseOk(kSixChannelChild);
    ASSERT_EQ(m.jointCount(), 3);
    const auto globals = globalTransforms(m, 0, PositionChannels::Add);
    // Child local translation is OFFSET + channels = (1, 5, 0); Rx90 -> (1, 0, 5).
    EXPECT_VEC3_NEAR(positionOf(globals[0]), 100.0, 0.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), 101.0, 0.0, 5.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[2]), 101.0, 0.0, 7.0, kEps);
}

TEST(ForwardKinematics, RootPositionChannelsReplaceOrAddToOffset) {
    const std::string text =
        "HIERARCHY\nROOT R\n{\nOFFSET 100 200 300\nCHANNELS 3 Zposition Xposition Yposition\n}\n"
        "MOTION\nFrames: 1\nFrame Time: 0.1\n3 1 2\n";
    const RawMotion m = parseOk(text);
    EXPECT_VEC3_NEAR(positionOf(globalTransforms(m, 0, PositionChannels::Replace)[0]), 1.0, 2.0, 3.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globalTransforms(m, 0, PositionChannels::Add)[0]), 101.0, 202.0, 303.0, kEps);
}

TEST(ForwardKinematics, PartialPositionChannelsTouchOnlyTheirAxis) {
    // Only Yposition: X and Z stay at the OFFSET's values.
    const std::string text =
        "HIERARCHY\nROOT R\n{\nOFFSET 1 2 3\nCHANNELS 1 Yposition\n"
        "JOINT C\n{\nOFFSET 10 20 30\nCHANNELS 2 Yrotation Xposition\n"
        "JOINT G\n{\nOFFSET 1 0 0\nCHANNELS 0\n}\n}\n}\n"
        "MOTION\nFrames: 2\nFrame Time: 0.1\n7 90 -4\n-1 0 0\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 3);

    const auto replace = globalTransforms(m, 0, PositionChannels::Replace);
    EXPECT_VEC3_NEAR(positionOf(replace[0]), 1.0, 7.0, 3.0, kEps);
    // C: translation (-4, 20, 30) even though its position channel is listed after a rotation.
    EXPECT_VEC3_NEAR(positionOf(replace[1]), -3.0, 27.0, 33.0, kEps);
    // G: Ry90 takes (1, 0, 0) to (0, 0, -1).
    EXPECT_VEC3_NEAR(positionOf(replace[2]), -3.0, 27.0, 32.0, kEps);

    const auto added = globalTransforms(m, 0, PositionChannels::Add);
    EXPECT_VEC3_NEAR(positionOf(added[0]), 1.0, 9.0, 3.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(added[1]), 7.0, 29.0, 33.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(added[2]), 7.0, 29.0, 32.0, kEps);

    // Frame 1 reads the second row.
    const auto second = globalTransforms(m, 1, PositionChannels::Replace);
    EXPECT_VEC3_NEAR(positionOf(second[0]), 1.0, -1.0, 3.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(second[2]), 2.0, 19.0, 33.0, kEps);
}

TEST(ForwardKinematics, LocalTransformReadsItsOwnSliceOfTheRow) {
    RawJoint joint;
    joint.name = "J";
    joint.offset = {1.0, 2.0, 3.0};
    joint.channels = {Channel::Yposition, Channel::Zrotation};
    joint.firstValue = 2;
    const std::vector<double> row{99.0, 99.0, 7.0, 90.0, 99.0};

    const glm::dmat4 replace = throng::motion::localTransform(joint, row, PositionChannels::Replace);
    EXPECT_VEC3_NEAR(positionOf(replace), 1.0, 7.0, 3.0, kEps);
    // Rz90: the local X axis (first column) points along +Y, the Y axis along -X.
    EXPECT_VEC3_NEAR(glm::dvec3(replace[0]), 0.0, 1.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(glm::dvec3(replace[1]), -1.0, 0.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(glm::dvec3(replace[2]), 0.0, 0.0, 1.0, kEps);
    EXPECT_DOUBLE_EQ(replace[3][3], 1.0);
    EXPECT_DOUBLE_EQ(replace[0][3], 0.0);

    const glm::dmat4 added = throng::motion::localTransform(joint, row, PositionChannels::Add);
    EXPECT_VEC3_NEAR(positionOf(added), 1.0, 9.0, 3.0, kEps);

    // No channels: OFFSET only, identity rotation.
    RawJoint plain;
    plain.offset = {4.0, 5.0, 6.0};
    const glm::dmat4 m = throng::motion::localTransform(plain, {}, PositionChannels::Replace);
    EXPECT_VEC3_NEAR(positionOf(m), 4.0, 5.0, 6.0, 0.0);
    for (glm::length_t c = 0; c < 3; ++c)
        for (glm::length_t r = 0; r < 3; ++r) EXPECT_EQ(m[c][r], c == r ? 1.0 : 0.0);
}

// --- LocalToGlobalJob -------------------------------------------------------------------

// Explicit matrices (column-major, m[column][row]) so no rotation helper is under test.
glm::dmat4 translation(double x, double y, double z) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(x, y, z, 1.0);
    return m;
}
glm::dmat4 rotZ90() {  // (x, y, z) -> (-y, x, z)
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(0, 1, 0, 0);
    m[1] = glm::dvec4(-1, 0, 0, 0);
    return m;
}
glm::dmat4 rotX90() {  // (x, y, z) -> (x, -z, y)
    glm::dmat4 m(1.0);
    m[1] = glm::dvec4(0, 0, 1, 0);
    m[2] = glm::dvec4(0, -1, 0, 0);
    return m;
}

const glm::dmat4 kSentinel(7.0);

TEST(LocalToGlobalJob, KnownAnswersOnAThreeJointChain) {
    const std::vector<int> parents{-1, 0, 1};
    const std::vector<glm::dmat4> locals{translation(1, 0, 0) * rotZ90(), translation(0, 2, 0),
                                         translation(0, 0, 3) * rotX90()};
    std::vector<glm::dmat4> globals(3, kSentinel);
    const LocalToGlobalJob job{parents, locals, globals};
    ASSERT_TRUE(job.validate());
    ASSERT_TRUE(job.run());
    // j0 at (1,0,0). j1: (1,0,0) + Rz90 (0,2,0) = (1,0,0) + (-2,0,0) = (-1,0,0).
    // j2: (-1,0,0) + Rz90 (0,0,3) = (-1,0,3).
    EXPECT_VEC3_NEAR(positionOf(globals[0]), 1.0, 0.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), -1.0, 0.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[2]), -1.0, 0.0, 3.0, kEps);
    // j2's rotation is Rz90·Rx90: X -> X -> Y; Y -> Z -> Z; Z -> -Y -> X.
    EXPECT_VEC3_NEAR(glm::dvec3(globals[2][0]), 0.0, 1.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(glm::dvec3(globals[2][1]), 0.0, 0.0, 1.0, kEps);
    EXPECT_VEC3_NEAR(glm::dvec3(globals[2][2]), 1.0, 0.0, 0.0, kEps);
}

TEST(LocalToGlobalJob, RootTransformIsAppliedAboveEveryRoot) {
    const std::vector<int> parents{-1, 0, -1};  // two roots
    const std::vector<glm::dmat4> locals{translation(1, 0, 0), translation(0, 2, 0), translation(0, 0, 5)};
    std::vector<glm::dmat4> globals(3, kSentinel);
    const glm::dmat4 root = translation(10, 20, 30) * rotZ90();
    const LocalToGlobalJob job{parents, locals, globals, &root};
    ASSERT_TRUE(job.run());
    // Rz90 (1,0,0) = (0,1,0); Rz90 (1,2,0) = (-2,1,0); Rz90 (0,0,5) = (0,0,5).
    EXPECT_VEC3_NEAR(positionOf(globals[0]), 10.0, 21.0, 30.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), 8.0, 21.0, 30.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[2]), 10.0, 20.0, 35.0, kEps);

    // Without a root transform, the roots sit at their locals.
    const LocalToGlobalJob plain{parents, locals, globals};
    ASSERT_TRUE(plain.run());
    EXPECT_VEC3_NEAR(positionOf(globals[0]), 1.0, 0.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[1]), 1.0, 2.0, 0.0, kEps);
    EXPECT_VEC3_NEAR(positionOf(globals[2]), 0.0, 0.0, 5.0, kEps);
}

TEST(LocalToGlobalJob, EmptyInputIsValid) {
    const LocalToGlobalJob job{};
    EXPECT_TRUE(job.validate());
    EXPECT_TRUE(job.run());
}

void expectRejected(const std::vector<int>& parents, std::size_t localCount, std::size_t globalCount,
                    const char* why) {
    SCOPED_TRACE(why);
    const std::vector<glm::dmat4> locals(localCount, translation(1, 2, 3));
    std::vector<glm::dmat4> globals(globalCount, kSentinel);
    const glm::dmat4 root = translation(5, 5, 5);
    for (const glm::dmat4* rootTransform : {static_cast<const glm::dmat4*>(nullptr), &root}) {
        const LocalToGlobalJob job{parents, locals, globals, rootTransform};
        EXPECT_FALSE(job.validate());
        EXPECT_FALSE(job.run());
        for (const glm::dmat4& g : globals) EXPECT_EQ(g, kSentinel) << "run() wrote output for an invalid job";
    }
}

TEST(LocalToGlobalJob, ValidateRejectsBadInputAndRunWritesNothing) {
    expectRejected({-1, 0, 1}, 2, 3, "too few locals");
    expectRejected({-1, 0, 1}, 4, 3, "too many locals");
    expectRejected({-1, 0, 1}, 3, 2, "too few globals");
    expectRejected({-1, 0, 1}, 3, 4, "too many globals");
    expectRejected({0}, 1, 1, "root is its own parent");
    expectRejected({-1, 1}, 2, 2, "joint is its own parent");
    expectRejected({-1, 2, 0}, 3, 3, "parent after child");
    expectRejected({-1, 0, 7}, 3, 3, "parent out of range");
    expectRejected({-2}, 1, 1, "parent below -1");
    expectRejected({-1, 0, -5}, 3, 3, "later parent below -1");
}

TEST(LocalToGlobalJob, ParentIndicesComeFromTheMotion) {
    const RawMotion m = parseOk(kSixChannelChild);
    EXPECT_EQ(throng::motion::parentIndices(m), (std::vector<int>{-1, 0, 1}));
}

// --- A real capture ---------------------------------------------------------------------

TEST(ForwardKinematics, BiovisionExampleMatchesIndependentValues) {
    if (!std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) GTEST_SKIP() << "no shared mocap directory";
    auto result = throng::motion::loadBvhFile(std::string(THRONG_SHARED_MOCAP_DIR) + "/biovision_example_2frames.bvh");
    ASSERT_TRUE(result.ok()) << result.error().describe();
    const RawMotion& m = result.value();
    auto indexOf = [&](const std::string& name) {
        for (std::size_t i = 0; i < m.joints.size(); ++i)
            if (m.joints[i].name == name) return i;
        ADD_FAILURE() << "no joint " << name;
        return std::size_t{0};
    };
    const std::size_t chest = indexOf("Chest");
    const std::size_t foot = indexOf("RightFoot");
    const auto frame0 = globalTransforms(m, 0, PositionChannels::Replace);
    const auto frame1 = globalTransforms(m, 1, PositionChannels::Replace);
    ASSERT_EQ(frame0.size(), 18U);
    EXPECT_VEC3_NEAR(positionOf(frame0[chest]), 8.32964, 40.0387, 89.6891, 1e-3);
    EXPECT_VEC3_NEAR(positionOf(frame0[foot]), 17.1327, 4.58868, 86.1275, 1e-3);
    EXPECT_VEC3_NEAR(positionOf(frame1[chest]), 8.14475, 40.1666, 87.6367, 1e-3);
    EXPECT_VEC3_NEAR(positionOf(frame1[foot]), 17.1494, 4.64242, 86.0002, 1e-3);
    // The root's OFFSET is zero, so both position-channel modes agree on this file.
    const auto added = globalTransforms(m, 0, PositionChannels::Add);
    EXPECT_VEC3_NEAR(positionOf(added[foot]), 17.1327, 4.58868, 86.1275, 1e-3);
}

}  // namespace
