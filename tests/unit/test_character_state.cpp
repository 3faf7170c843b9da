// crowd::sampleJointWorld, the C++ definition of joint sampling that the cpu render path and
// the GPU tests share (mirroring shaders/pose.glsl), against hand-computed answers on a tiny
// hand-made clip.
#include <gtest/gtest.h>

#include <numbers>

#include "throng/crowd/character_state.h"

namespace {

using namespace throng;
using crowd::CharacterState;
using crowd::sampleJointWorld;

constexpr float kHalfPi = std::numbers::pi_v<float> / 2.0F;
constexpr float kTolerance = 1e-5F;

glm::quat aboutAxis(float radians, glm::vec3 axis) { return glm::angleAxis(radians, axis); }

// Two joints, three frames. Joint 0 (the root) stands at (0, 1, 2f) at frame f, turned 90°
// about +X at frame 2 only. Joint 1 stands at (1 + 2f, 2, 0) and turns about +Y: 0°, 90°, 90°,
// with frame 2's rotation stored as the negated quaternion (the same rotation, the long way
// round for a naive blend).
motion::BakedClip handMadeClip() {
    motion::BakedClip clip;
    clip.name = "hand-made";
    clip.jointNames = {"root", "arm"};
    clip.parents = {-1, 0};
    clip.frameCount = 3;
    clip.frameTime = 1.0 / 30.0;
    clip.jointRadius = {0.1F, 0.05F};
    clip.jointDetail = {0, 0};
    const glm::quat identity(1.0F, 0.0F, 0.0F, 0.0F);
    const glm::quat yaw90 = aboutAxis(kHalfPi, {0.0F, 1.0F, 0.0F});
    for (int f = 0; f < 3; ++f) {
        const auto x = static_cast<float>(f);
        motion::JointPose root, arm;
        root.rotation = f == 2 ? aboutAxis(kHalfPi, {1.0F, 0.0F, 0.0F}) : identity;
        root.translation = {0.0F, 1.0F, 2.0F * x};
        arm.rotation = f == 0 ? identity : f == 1 ? yaw90 : -yaw90;
        arm.translation = {1.0F + 2.0F * x, 2.0F, 0.0F};
        clip.poses.push_back(root);
        clip.poses.push_back(arm);
    }
    return clip;
}

CharacterState character(glm::vec3 position, float yaw, float frame, float scale = 1.0F) {
    return {.groundFrame = glm::vec4(position, yaw), .clip = 0, .frame = frame, .scale = scale, .color = 0};
}

void expectNear(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(actual.x, expected.x, kTolerance);
    EXPECT_NEAR(actual.y, expected.y, kTolerance);
    EXPECT_NEAR(actual.z, expected.z, kTolerance);
}

// The same rotation: q and -q are equal.
void expectSameRotation(glm::quat actual, glm::quat expected) {
    EXPECT_NEAR(std::abs(glm::dot(actual, expected)), 1.0F, kTolerance) << "actual (w x y z) " << actual.w << " " << actual.x << " "
                                                                        << actual.y << " " << actual.z;
}

TEST(SampleJointWorld, YawZeroKeepsTheBakedPositionAndOrientation) {
    const motion::BakedClip clip = handMadeClip();
    const crowd::JointWorld joint = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 1.0F), 1);
    expectNear(joint.position, {3.0F, 2.0F, 0.0F});
    expectSameRotation(joint.orientation, aboutAxis(kHalfPi, {0.0F, 1.0F, 0.0F}));
    EXPECT_FLOAT_EQ(joint.radius, 0.05F);
}

TEST(SampleJointWorld, YawNinetyDegreesTurnsTheJointAboutUpThenMovesItToTheGroundFrame) {
    const motion::BakedClip clip = handMadeClip();
    // Local (1, 2, 0) turned +90° about +Y: x' = cos·x + sin·z = 0, z' = -sin·x + cos·z = -1.
    const crowd::JointWorld atOrigin = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, kHalfPi, 0.0F), 1);
    expectNear(atOrigin.position, {0.0F, 2.0F, -1.0F});
    // The root at frame 1 is at local (0, 1, 2): straight ahead (+Z) becomes +X.
    const crowd::JointWorld root = sampleJointWorld(std::span(&clip, 1), character({10.0F, 0.0F, 20.0F}, kHalfPi, 1.0F), 0);
    expectNear(root.position, {12.0F, 1.0F, 20.0F});
    const crowd::JointWorld moved = sampleJointWorld(std::span(&clip, 1), character({10.0F, 0.0F, 20.0F}, kHalfPi, 0.0F), 1);
    expectNear(moved.position, {10.0F, 2.0F, 19.0F});
    expectSameRotation(moved.orientation, aboutAxis(kHalfPi, {0.0F, 1.0F, 0.0F}));
}

TEST(SampleJointWorld, ScaleMultipliesTheBakedPositionAndTheRadiusButNotTheGroundFrame) {
    const motion::BakedClip clip = handMadeClip();
    const crowd::JointWorld joint = sampleJointWorld(std::span(&clip, 1), character({10.0F, 0.0F, 20.0F}, 0.0F, 0.0F, 2.0F), 1);
    expectNear(joint.position, {12.0F, 4.0F, 20.0F});
    EXPECT_FLOAT_EQ(joint.radius, 0.1F);
    const crowd::JointWorld root = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 2.0F, 0.5F), 0);
    expectNear(root.position, {0.0F, 0.5F, 2.0F});
    EXPECT_FLOAT_EQ(root.radius, 0.05F);
}

TEST(SampleJointWorld, HalfwayBetweenTwoFramesBlendsPositionAndRotationHalfway) {
    const motion::BakedClip clip = handMadeClip();
    const crowd::JointWorld joint = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 0.5F), 1);
    expectNear(joint.position, {2.0F, 2.0F, 0.0F});
    // Halfway between 0° and 90° about +Y (nlerp's midpoint is slerp's).
    expectSameRotation(joint.orientation, aboutAxis(kHalfPi / 2.0F, {0.0F, 1.0F, 0.0F}));
    const crowd::JointWorld quarter = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 0.25F), 1);
    expectNear(quarter.position, {1.5F, 2.0F, 0.0F});
}

TEST(SampleJointWorld, BlendTakesTheShortArcWhenAFrameStoresTheNegatedQuaternion) {
    const motion::BakedClip clip = handMadeClip();
    // Frames 1 and 2 hold the same rotation with opposite signs; a naive blend would pass
    // through zero halfway. The short arc keeps it.
    const crowd::JointWorld joint = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 1.5F), 1);
    expectSameRotation(joint.orientation, aboutAxis(kHalfPi, {0.0F, 1.0F, 0.0F}));
    EXPECT_NEAR(glm::length(joint.orientation), 1.0F, kTolerance);
    expectNear(joint.position, {4.0F, 2.0F, 0.0F});
}

TEST(SampleJointWorld, FramesBeyondTheClipClampToItsEnds) {
    const motion::BakedClip clip = handMadeClip();
    expectNear(sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 7.3F), 1).position, {5.0F, 2.0F, 0.0F});
    expectNear(sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 2.0F), 1).position, {5.0F, 2.0F, 0.0F});
    expectNear(sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, -1.0F), 1).position, {1.0F, 2.0F, 0.0F});
    expectNear(sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 100.0F), 0).position, {0.0F, 1.0F, 4.0F});
}

TEST(SampleJointWorld, WorldOrientationAppliesTheBakedRotationFirstThenTheYaw) {
    const motion::BakedClip clip = handMadeClip();
    // The root at frame 2 is turned +90° about +X; the character faces +X (yaw +90°).
    const crowd::JointWorld root = sampleJointWorld(std::span(&clip, 1), character({0.0F, 0.0F, 0.0F}, kHalfPi, 2.0F), 0);
    // +Y: about +X to +Z, then about +Y to +X. (The other order would give +Z.)
    expectNear(root.orientation * glm::vec3(0.0F, 1.0F, 0.0F), {1.0F, 0.0F, 0.0F});
    // +Z: about +X to -Y, which the yaw leaves alone.
    expectNear(root.orientation * glm::vec3(0.0F, 0.0F, 1.0F), {0.0F, -1.0F, 0.0F});
    // +X: unchanged by the baked turn, then about +Y to -Z.
    expectNear(root.orientation * glm::vec3(1.0F, 0.0F, 0.0F), {0.0F, 0.0F, -1.0F});
}

}  // namespace

namespace {

// A foot twist turns the foot's joints about the ankle by the leg's twist, the way yaw turns
// the body (x' = c x + s z, z' = -s x + c z), and leaves every other joint as it was. Here
// joint 1 ("arm") plays a foot whose ankle is joint 0: a quarter-turn twist takes its offset
// from the ankle, (x, z), to (z, -x), and turns its orientation by the same quarter turn.
TEST(CharacterState, FootTwistTurnsTheFootAboutItsAnkle) {
    motion::BakedClip clip = handMadeClip();
    clip.anatomy.legs[1].ankle = 0;
    clip.footLeg = {0, 2};  // joint 1 is in legs[1]'s foot; the ankle itself is left out here
    CharacterState character;
    character.frame = 0.0F;
    const crowd::JointWorld straight = sampleJointWorld(std::span(&clip, 1), character, 1);
    character.footTwist = {0.3F, kHalfPi};  // legs[0]'s twist must not reach it
    const crowd::JointWorld ankle = sampleJointWorld(std::span(&clip, 1), character, 0);
    const crowd::JointWorld twisted = sampleJointWorld(std::span(&clip, 1), character, 1);
    const glm::vec3 before = straight.position - ankle.position, after = twisted.position - ankle.position;
    // A quarter turn: (x, z) -> (z, -x); the height and the distance to the ankle stay.
    EXPECT_NEAR(after.x, before.z, kTolerance);
    EXPECT_NEAR(after.y, before.y, kTolerance);
    EXPECT_NEAR(after.z, -before.x, kTolerance);
    const glm::quat expected = glm::angleAxis(kHalfPi, glm::vec3(0.0F, 1.0F, 0.0F)) * straight.orientation;
    EXPECT_NEAR(std::abs(glm::dot(twisted.orientation, expected)), 1.0F, kTolerance);
    // The ankle (not a foot joint here) is where it was without a twist.
    character.footTwist = {0.0F, 0.0F};
    EXPECT_EQ(sampleJointWorld(std::span(&clip, 1), character, 0).position, ankle.position);
}

// A twist of exactly zero draws the clip as baked, to the bit (the golden images of group
// mode, where nothing twists, depend on it).
TEST(CharacterState, ZeroFootTwistChangesNoBits) {
    motion::BakedClip plain = handMadeClip();
    motion::BakedClip withFeet = plain;
    withFeet.anatomy.legs[0].ankle = 0;
    withFeet.footLeg = {1, 1};
    CharacterState character;
    character.frame = 0.37F;
    character.groundFrame = glm::vec4(1.5F, 0.0F, -2.0F, 0.7F);
    for (int joint = 0; joint < 2; ++joint) {
        EXPECT_EQ(sampleJointWorld(std::span(&withFeet, 1), character, joint).position, sampleJointWorld(std::span(&plain, 1), character, joint).position);
        EXPECT_EQ(sampleJointWorld(std::span(&withFeet, 1), character, joint).orientation, sampleJointWorld(std::span(&plain, 1), character, joint).orientation);
    }
}

}  // namespace

namespace {

// Two clips of one skeleton: the hand-made clip, and a copy with the arm's joint moved and
// turned, so a blend of them has a known answer.
TEST(SampleJointWorld, ABlendMixesTheTwoClipsAndATransitionMixesTheOutgoingOne) {
    const motion::BakedClip first = handMadeClip();
    motion::BakedClip second = first;
    for (std::size_t f = 0; f < 3; ++f) {
        second.poses[f * 2 + 1].translation += glm::vec3(0.0F, 1.0F, 0.0F);
        second.poses[f * 2 + 1].rotation = glm::quat(1.0F, 0.0F, 0.0F, 0.0F);
    }
    const std::vector<motion::BakedClip> clips{first, second};
    CharacterState c = character({0.0F, 0.0F, 0.0F}, 0.0F, 0.0F);
    c.blendClip = 1;
    c.blendFrame = 0.0F;
    c.blend = 0.25F;
    // Frame 0: the arm at (1, 2, 0) unrotated in the first clip, (1, 3, 0) in the second.
    expectNear(sampleJointWorld(clips, c, 1).position, {1.0F, 2.25F, 0.0F});
    // Frame 1 of the first (turned 90° about +Y) with frame 0 of the second: nlerp halfway
    // between identity and 90° is 45°.
    c.frame = 1.0F;
    c.blend = 0.5F;
    expectSameRotation(sampleJointWorld(clips, c, 1).orientation, aboutAxis(kHalfPi / 2.0F, {0.0F, 1.0F, 0.0F}));
    // A transition from the second clip at weight 1 shows the second clip alone.
    c.blend = 0.0F;
    c.fromClip = 1;
    c.fromFrame = 0.0F;
    c.fromWeight = 1.0F;
    expectNear(sampleJointWorld(clips, c, 1).position, {1.0F, 3.0F, 0.0F});
    // A weight of exactly 0 leaves the other clip's bits out: the same as the clip alone.
    c.fromWeight = 0.0F;
    c.blend = 0.0F;
    const crowd::JointWorld alone = sampleJointWorld(std::span(&first, 1), character({0.0F, 0.0F, 0.0F}, 0.0F, 1.0F), 1);
    EXPECT_EQ(sampleJointWorld(clips, c, 1).position, alone.position);
}

}  // namespace
