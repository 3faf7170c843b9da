// BVH parser: every valid form real exporters write must parse to the same RawMotion, the
// shared real captures must parse with their documented sizes, and hostile input (very deep
// hierarchies, truncated text) must never crash. Exhaustive malformed-input checks live in
// the CLI tests; here there are only a few sanity checks of the Result error API.
#include "bvh_test_support.h"

namespace {

using namespace bvh_test;

// --- The reference file, field by field -------------------------------------------------

TEST(BvhParser, SmallFileParsesCompletely) {
    const RawMotion m = parseOk(kSmall, "small.bvh");
    EXPECT_EQ(m.sourceName, "small.bvh");
    ASSERT_EQ(m.jointCount(), 3);

    EXPECT_EQ(m.joints[0].name, "Hips");
    EXPECT_EQ(m.joints[0].parent, -1);
    EXPECT_EQ(m.joints[0].offset, glm::dvec3(0.5, -1.0, 2.0));
    EXPECT_EQ(m.joints[0].channels,
              (std::vector<Channel>{Channel::Xposition, Channel::Yposition, Channel::Zposition, Channel::Zrotation,
                                    Channel::Xrotation, Channel::Yrotation}));
    EXPECT_EQ(m.joints[0].firstValue, 0);
    EXPECT_EQ(m.joints[0].sourceLine, 2);

    EXPECT_EQ(m.joints[1].name, "Spine");
    EXPECT_EQ(m.joints[1].parent, 0);
    EXPECT_EQ(m.joints[1].offset, glm::dvec3(0.0, 10.0, 0.0));
    EXPECT_EQ(m.joints[1].channels,
              (std::vector<Channel>{Channel::Zrotation, Channel::Xrotation, Channel::Yrotation}));
    EXPECT_EQ(m.joints[1].firstValue, 6);
    EXPECT_EQ(m.joints[1].sourceLine, 6);

    EXPECT_EQ(m.joints[2].name, "Leg");
    EXPECT_EQ(m.joints[2].parent, 0);
    EXPECT_EQ(m.joints[2].offset, glm::dvec3(2.0, -1.0, 0.5));
    EXPECT_EQ(m.joints[2].channels,
              (std::vector<Channel>{Channel::Xrotation, Channel::Yrotation, Channel::Zrotation}));
    EXPECT_EQ(m.joints[2].firstValue, 9);
    EXPECT_EQ(m.joints[2].sourceLine, 15);

    ASSERT_EQ(m.endSites.size(), 2U);
    EXPECT_EQ(m.endSites[0].parent, 1);
    EXPECT_EQ(m.endSites[0].offset, glm::dvec3(0.0, 5.0, 0.25));
    EXPECT_EQ(m.endSites[1].parent, 2);
    EXPECT_EQ(m.endSites[1].offset, glm::dvec3(0.0, -8.0, 0.0));

    EXPECT_EQ(m.channelCount, 12);
    EXPECT_EQ(m.frameCount, 2);
    EXPECT_DOUBLE_EQ(m.frameTime, 0.0333333);
}

TEST(BvhParser, FrameValuesAreRowMajor) {
    const RawMotion m = parseOk(kSmall);
    ASSERT_EQ(m.values.size(), 24U);
    for (std::size_t i = 0; i < m.values.size(); ++i) EXPECT_EQ(m.values[i], static_cast<double>(i + 1));
    const auto row0 = m.frame(0);
    const auto row1 = m.frame(1);
    ASSERT_EQ(row0.size(), 12U);
    ASSERT_EQ(row1.size(), 12U);
    EXPECT_EQ(row0[0], 1.0);
    EXPECT_EQ(row0[11], 12.0);
    EXPECT_EQ(row1[0], 13.0);
    EXPECT_EQ(row1[11], 24.0);
    // The Leg joint's values start at firstValue within the row.
    const auto& leg = m.joints[2];
    EXPECT_EQ(row1[static_cast<std::size_t>(leg.firstValue)], 22.0);
}

// --- Whitespace and line endings --------------------------------------------------------

TEST(BvhParser, LfCrlfAndMixedLineEndingsGiveIdenticalMotion) {
    const RawMotion lf = parseOk(kSmall);
    const std::string crlf = replaceAll(std::string(kSmall), "\n", "\r\n");
    std::string mixed;
    int n = 0;
    for (const std::string& line : splitLines(kSmall)) mixed += line + (n++ % 2 == 0 ? "\r\n" : "\n");
    std::string crlfNoFinalNewline = crlf.substr(0, crlf.size() - 2);

    expectSameMotion(lf, parseOk(crlf));
    expectSameMotion(lf, parseOk(mixed));
    expectSameMotion(lf, parseOk(crlfNoFinalNewline));
}

TEST(BvhParser, ClassicMacCarriageReturnEndings) {
    const RawMotion lf = parseOk(kSmall);
    expectSameMotion(lf, parseOk(replaceAll(std::string(kSmall), "\n", "\r")));
}

TEST(BvhParser, TabsAndBlankLinesAnywhere) {
    const RawMotion reference = parseOk(kSmall);

    // Every space becomes a tab, plus leading and trailing tabs/spaces on every line.
    std::string tabbed;
    for (const std::string& line : splitLines(kSmall)) tabbed += "\t \t" + replaceAll(line, " ", "\t") + " \t\n";
    expectSameMotion(reference, parseOk(tabbed));

    // Blank (and whitespace-only) lines before, between and after every line, CRLF included.
    std::string spaced = "\n\r\n";
    for (const std::string& line : splitLines(kSmall)) spaced += line + "\n\n \t \n\r\n";
    spaced += "\n\n";
    expectSameMotion(reference, parseOk(spaced), /*compareSourceLines=*/false);

    // Joint lines move down: sourceLine tracks the real line of the keyword.
    const RawMotion moved = parseOk(spaced);
    ASSERT_EQ(moved.jointCount(), 3);
    EXPECT_EQ(moved.joints[0].sourceLine, 2 + 1 + 4 * 1);  // two leading blank lines, then 4 lines per line
    EXPECT_GT(moved.joints[1].sourceLine, moved.joints[0].sourceLine);
}

TEST(BvhParser, Utf8ByteOrderMarkIsAccepted) {
    const RawMotion reference = parseOk(kSmall);
    const std::string withBom = "\xEF\xBB\xBF" + std::string(kSmall);
    expectSameMotion(reference, parseOk(withBom));
}

// --- Numbers ----------------------------------------------------------------------------

TEST(BvhParser, EveryDecimalForm) {
    const std::string text =
        "HIERARCHY\n"
        "ROOT R\n"
        "{\n"
        "  OFFSET +1 .5 5.\n"
        "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
        "  JOINT J\n"
        "  {\n"
        "    OFFSET 1E-3 -2e+2 -.25\n"
        "    CHANNELS 3 Zrotation Xrotation Yrotation\n"
        "    End Site\n"
        "    {\n"
        "      OFFSET 0 -0 007\n"
        "    }\n"
        "  }\n"
        "}\n"
        "MOTION\n"
        "Frames: 1\n"
        "Frame Time: .04\n"
        "+1 .5 5. 1E-3 -2e+2 -0.0 1e0 -.75 2.5E+1\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 2);
    EXPECT_EQ(m.joints[0].offset, glm::dvec3(1.0, 0.5, 5.0));
    EXPECT_EQ(m.joints[1].offset, glm::dvec3(0.001, -200.0, -0.25));
    ASSERT_EQ(m.endSites.size(), 1U);
    EXPECT_EQ(m.endSites[0].offset, glm::dvec3(0.0, 0.0, 7.0));
    EXPECT_DOUBLE_EQ(m.frameTime, 0.04);
    const std::vector<double> expected{1.0, 0.5, 5.0, 0.001, -200.0, 0.0, 1.0, -0.75, 25.0};
    EXPECT_EQ(m.values, expected);
}

// --- Channels ---------------------------------------------------------------------------

TEST(BvhParser, ChannelCountsZeroToSixInAnyOrderOnAnyJoint) {
    const std::string text =
        "HIERARCHY\n"
        "ROOT Root\n"
        "{\n"
        "  OFFSET 0 0 0\n"
        "  CHANNELS 2 Yrotation Xposition\n"
        "  JOINT Six\n"  // a non-root joint with all six channels, interleaved
        "  {\n"
        "    OFFSET 1 0 0\n"
        "    CHANNELS 6 Zrotation Yposition Xrotation Zposition Yrotation Xposition\n"
        "    JOINT None\n"  // no channels at all
        "    {\n"
        "      OFFSET 0 1 0\n"
        "      CHANNELS 0\n"
        "      JOINT PosOnly\n"  // only position channels, out of order
        "      {\n"
        "        OFFSET 0 0 1\n"
        "        CHANNELS 3 Zposition Xposition Yposition\n"
        "        End Site\n"
        "        {\n"
        "          OFFSET 0 0 1\n"
        "        }\n"
        "      }\n"
        "    }\n"
        "  }\n"
        "  JOINT One\n"
        "  {\n"
        "    OFFSET -1 0 0\n"
        "    CHANNELS 1 Xrotation\n"
        "    JOINT Four\n"
        "    {\n"
        "      OFFSET -1 0 0\n"
        "      CHANNELS 4 Yposition Zrotation Xposition Yrotation\n"
        "      JOINT Five\n"
        "      {\n"
        "        OFFSET -1 0 0\n"
        "        CHANNELS 5 Xrotation Zposition Yrotation Zrotation Xposition\n"
        "        End Site\n"
        "        {\n"
        "          OFFSET -1 0 0\n"
        "        }\n"
        "      }\n"
        "    }\n"
        "  }\n"
        "}\n"
        "MOTION\n"
        "Frames: 2\n"
        "Frame Time: 0.01\n"
        "0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20\n"
        "100 101 102 103 104 105 106 107 108 109 110 111 112 113 114 115 116 117 118 119 120\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 7);

    struct Expect {
        const char* name;
        int parent;
        std::vector<Channel> channels;
        int firstValue;
    };
    using C = Channel;
    const std::vector<Expect> expected{
        {"Root", -1, {C::Yrotation, C::Xposition}, 0},
        {"Six", 0, {C::Zrotation, C::Yposition, C::Xrotation, C::Zposition, C::Yrotation, C::Xposition}, 2},
        {"None", 1, {}, 8},
        {"PosOnly", 2, {C::Zposition, C::Xposition, C::Yposition}, 8},
        {"One", 0, {C::Xrotation}, 11},
        {"Four", 4, {C::Yposition, C::Zrotation, C::Xposition, C::Yrotation}, 12},
        {"Five", 5, {C::Xrotation, C::Zposition, C::Yrotation, C::Zrotation, C::Xposition}, 16},
    };
    for (std::size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE(expected[i].name);
        EXPECT_EQ(m.joints[i].name, expected[i].name);
        EXPECT_EQ(m.joints[i].parent, expected[i].parent);
        EXPECT_EQ(m.joints[i].channels, expected[i].channels);
        EXPECT_EQ(m.joints[i].firstValue, expected[i].firstValue);
    }
    EXPECT_EQ(m.channelCount, 21);
    EXPECT_EQ(m.frameCount, 2);
    ASSERT_EQ(m.values.size(), 42U);
    // Each joint's values are the channelCount consecutive numbers from its firstValue.
    const auto row1 = m.frame(1);
    for (const auto& joint : m.joints)
        for (std::size_t c = 0; c < joint.channels.size(); ++c)
            EXPECT_EQ(row1[static_cast<std::size_t>(joint.firstValue) + c],
                      100.0 + static_cast<double>(joint.firstValue) + static_cast<double>(c));

    ASSERT_EQ(m.endSites.size(), 2U);
    EXPECT_EQ(m.endSites[0].parent, 3);
    EXPECT_EQ(m.endSites[0].offset, glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(m.endSites[1].parent, 6);
    EXPECT_EQ(m.endSites[1].offset, glm::dvec3(-1.0, 0.0, 0.0));
}

TEST(BvhParser, LowercaseAndUppercaseChannelNames) {
    const std::string text =
        "HIERARCHY\n"
        "ROOT Hips\n"
        "{\n"
        "  OFFSET 0 0 0\n"
        "  CHANNELS 6 xposition YPOSITION zPosition zrotation XROTATION yRotation\n"
        "}\n"
        "MOTION\n"
        "Frames: 1\n"
        "Frame Time: 0.1\n"
        "1 2 3 4 5 6\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 1);
    EXPECT_EQ(m.joints[0].channels,
              (std::vector<Channel>{Channel::Xposition, Channel::Yposition, Channel::Zposition, Channel::Zrotation,
                                    Channel::Xrotation, Channel::Yrotation}));
    EXPECT_TRUE(m.endSites.empty());
}

TEST(BvhParser, ChannelNamesAndHelpers) {
    EXPECT_STREQ(throng::motion::channelName(Channel::Xposition), "Xposition");
    EXPECT_STREQ(throng::motion::channelName(Channel::Yposition), "Yposition");
    EXPECT_STREQ(throng::motion::channelName(Channel::Zposition), "Zposition");
    EXPECT_STREQ(throng::motion::channelName(Channel::Xrotation), "Xrotation");
    EXPECT_STREQ(throng::motion::channelName(Channel::Yrotation), "Yrotation");
    EXPECT_STREQ(throng::motion::channelName(Channel::Zrotation), "Zrotation");
    EXPECT_FALSE(throng::motion::isRotation(Channel::Zposition));
    EXPECT_TRUE(throng::motion::isRotation(Channel::Xrotation));
    EXPECT_EQ(throng::motion::channelAxis(Channel::Yposition), 1);
    EXPECT_EQ(throng::motion::channelAxis(Channel::Zrotation), 2);
}

// --- Names and headers ------------------------------------------------------------------

TEST(BvhParser, JointNamesAreRecordedVerbatim) {
    const std::string text =
        "HIERARCHY\n"
        "ROOT mixamorig:Hips\n"
        "{\n"
        "  OFFSET 0 0 0\n"
        "  CHANNELS 3 Xposition Yposition Zposition\n"
        "  JOINT L_Hand.001\n"
        "  {\n"
        "    OFFSET 1 0 0\n"
        "    CHANNELS 0\n"
        "    JOINT\tRightUpLeg_2\t\n"
        "    {\n"
        "      OFFSET 0 -1 0\n"
        "      CHANNELS 0\n"
        "      End Site\n"
        "      {\n"
        "        OFFSET 0 -1 0\n"
        "      }\n"
        "    }\n"
        "  }\n"
        "}\n"
        "MOTION\n"
        "Frames: 1\n"
        "Frame Time: 0.1\n"
        "0 0 0\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 3);
    EXPECT_EQ(m.joints[0].name, "mixamorig:Hips");
    EXPECT_EQ(m.joints[1].name, "L_Hand.001");
    EXPECT_EQ(m.joints[2].name, "RightUpLeg_2");
}

TEST(BvhParser, OpeningBraceOnTheNameLine) {
    const std::string text =
        "HIERARCHY\n"
        "ROOT Hips {\n"
        "  OFFSET 0 0 0\n"
        "  CHANNELS 1 Yrotation\n"
        "  JOINT Spine{\n"
        "    OFFSET 0 1 0\n"
        "    CHANNELS 1 Zrotation\n"
        "    End Site {\n"
        "      OFFSET 0 1 0\n"
        "    }\n"
        "  }\n"
        "}\n"
        "MOTION\n"
        "Frames: 1\n"
        "Frame Time: 0.1\n"
        "10 20\n";
    const RawMotion m = parseOk(text);
    ASSERT_EQ(m.jointCount(), 2);
    EXPECT_EQ(m.joints[0].name, "Hips");
    EXPECT_EQ(m.joints[1].name, "Spine");
    EXPECT_EQ(m.endSites.size(), 1U);
    EXPECT_EQ(m.values, (std::vector<double>{10.0, 20.0}));
}

TEST(BvhParser, FramesHeaderSpacingVariants) {
    const std::string head =
        "HIERARCHY\n"
        "ROOT Hips\n"
        "{\n"
        "  OFFSET 0 0 0\n"
        "  CHANNELS 2 Xposition Zrotation\n"
        "}\n"
        "MOTION\n";
    const std::string body = "1 2\n3 4\n";
    for (const char* frames : {"Frames: 2", "Frames:2", "Frames:\t2", "Frames: \t 2", "\tFrames:2\t"}) {
        for (const char* time : {"Frame Time: 0.5", "Frame Time:0.5", "Frame\tTime:\t0.5", "Frame  Time: 0.5 "}) {
            SCOPED_TRACE(std::string(frames) + " / " + time);
            const RawMotion m = parseOk(head + frames + "\n" + time + "\n" + body);
            EXPECT_EQ(m.frameCount, 2);
            EXPECT_EQ(m.frameTime, 0.5);
            EXPECT_EQ(m.values, (std::vector<double>{1.0, 2.0, 3.0, 4.0}));
        }
    }
    // Twelve frames with no space after the colon.
    std::string twelve = head + "Frames:12\nFrame Time: 0.1\n";
    for (int i = 0; i < 12; ++i) twelve += std::to_string(i) + " " + std::to_string(-i) + "\n";
    const RawMotion m = parseOk(twelve);
    EXPECT_EQ(m.frameCount, 12);
    ASSERT_EQ(m.values.size(), 24U);
    EXPECT_EQ(m.frame(11)[0], 11.0);
    EXPECT_EQ(m.frame(11)[1], -11.0);
}

// --- Real captures ----------------------------------------------------------------------

struct CaptureCase {
    const char* file;
    int joints;
    int endSites;
    int frames;
};

class SharedMocap : public ::testing::TestWithParam<CaptureCase> {};

TEST_P(SharedMocap, ParsesWithDocumentedCounts) {
    const CaptureCase& c = GetParam();
    if (!std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) GTEST_SKIP() << "no shared mocap directory";
    const std::string path = std::string(THRONG_SHARED_MOCAP_DIR) + "/" + c.file;
    auto result = throng::motion::loadBvhFile(path);
    ASSERT_TRUE(result.ok()) << result.error().describe();
    const RawMotion& m = result.value();
    EXPECT_EQ(m.sourceName, path);
    EXPECT_EQ(m.jointCount(), c.joints);
    EXPECT_EQ(static_cast<int>(m.endSites.size()), c.endSites);
    EXPECT_EQ(m.frameCount, c.frames);
    EXPECT_GT(m.frameTime, 0.0);
    // Every file: root with 6 channels, every other joint with 3 rotations.
    EXPECT_EQ(m.channelCount, 6 + 3 * (c.joints - 1));
    EXPECT_EQ(m.values.size(), static_cast<std::size_t>(m.frameCount) * static_cast<std::size_t>(m.channelCount));
    int firstValue = 0;
    for (int i = 0; i < m.jointCount(); ++i) {
        const auto& joint = m.joints[static_cast<std::size_t>(i)];
        EXPECT_LT(joint.parent, i);
        EXPECT_EQ(joint.parent < 0, i == 0);
        EXPECT_EQ(joint.firstValue, firstValue);
        EXPECT_FALSE(joint.name.empty());
        EXPECT_GE(joint.sourceLine, 2);
        firstValue += static_cast<int>(joint.channels.size());
    }
    for (const auto& site : m.endSites) {
        EXPECT_GE(site.parent, 0);
        EXPECT_LT(site.parent, m.jointCount());
    }
}

INSTANTIATE_TEST_SUITE_P(
    Files, SharedMocap,
    ::testing::Values(CaptureCase{"biovision_example_2frames.bvh", 18, 5, 2},
                      CaptureCase{"bvhtoolbox_walk01_19j_zxy_24fps.bvh", 19, 5, 101},
                      CaptureCase{"cmu_02_01_walk.bvh", 31, 7, 344},
                      CaptureCase{"cmu_07_01_walk.bvh", 31, 7, 317},
                      CaptureCase{"cmu_131_01_walk_3dsmax.bvh", 31, 7, 994},
                      CaptureCase{"cmu_131_02_walk_3dsmax_scaled_m.bvh", 31, 7, 1248},
                      CaptureCase{"cmu_16_45_run.bvh", 31, 7, 136},
                      CaptureCase{"mocapbank_19j_zxy_crlf.bvh", 19, 5, 455}),
    [](const ::testing::TestParamInfo<CaptureCase>& param) {
        std::string name = param.param.file;
        name = name.substr(0, name.find('.'));
        return name;
    });

TEST(BvhParser, EveryCaptureInTheSharedDirectoryParses) {
    const std::filesystem::path dir(THRONG_SHARED_MOCAP_DIR);
    if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no shared mocap directory: " << dir;
    int parsed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".bvh") continue;
        auto result = throng::motion::loadBvhFile(entry.path().string());
        EXPECT_TRUE(result.ok()) << entry.path() << ": " << result.error().describe();
        ++parsed;
    }
    EXPECT_GE(parsed, 8);
}

TEST(BvhParser, Cmu131MixesRotationOrdersPerJoint) {
    if (!std::filesystem::is_directory(THRONG_SHARED_MOCAP_DIR)) GTEST_SKIP() << "no shared mocap directory";
    const std::string path = std::string(THRONG_SHARED_MOCAP_DIR) + "/cmu_131_01_walk_3dsmax.bvh";
    auto result = throng::motion::loadBvhFile(path);
    ASSERT_TRUE(result.ok()) << result.error().describe();
    const RawMotion& m = result.value();
    const std::vector<Channel> zxy{Channel::Zrotation, Channel::Xrotation, Channel::Yrotation};
    const std::vector<Channel> zyx{Channel::Zrotation, Channel::Yrotation, Channel::Xrotation};
    const std::set<std::string> arms{"LeftShoulder",  "LeftElbow",  "LeftWrist",  "lhand", "LFingers", "LThumb",
                                     "RightShoulder", "RightElbow", "RightWrist", "rhand", "RFingers", "RThumb"};
    int armCount = 0;
    for (const auto& joint : m.joints) {
        SCOPED_TRACE(joint.name);
        std::vector<Channel> rotations;
        for (Channel c : joint.channels)
            if (throng::motion::isRotation(c)) rotations.push_back(c);
        if (arms.contains(joint.name)) {
            ++armCount;
            EXPECT_EQ(rotations, zxy);
        } else {
            EXPECT_EQ(rotations, zyx);
        }
    }
    EXPECT_EQ(armCount, 12);
    EXPECT_EQ(m.joints[0].channels.size(), 6U);
}

}  // namespace
