// BVH parser robustness: hostile but valid input (very deep hierarchies, joint limits), a few
// error sanity checks of the Result API, and every truncation and single-byte corruption
// of a valid file, which must either parse or fail with a location. Never a crash.
#include "bvh_test_support.h"

namespace {

using namespace bvh_test;

// --- Hostile but valid input ------------------------------------------------------------

TEST(BvhParser, TwentyThousandNestedJointsParseWithoutRecursion) {
    constexpr int kDepth = 20000;
    std::string text = "HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 3 Xposition Yposition Zposition\n";
    for (int i = 1; i <= kDepth; ++i) text += "JOINT J" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 1 Zrotation\n";
    text += "End Site\n{\nOFFSET 0 1 0\n}\n";
    for (int i = 0; i <= kDepth; ++i) text += "}\n";
    text += "MOTION\nFrames: 1\nFrame Time: 0.1\n1 2 3";
    for (int i = 1; i <= kDepth; ++i) text += " 0";
    text += "\n";

    auto result = parseBvh(text, "deep.bvh");
    ASSERT_TRUE(result.ok()) << result.error().describe();
    const RawMotion& m = result.value();
    ASSERT_EQ(m.jointCount(), kDepth + 1);
    for (int i = 1; i <= kDepth; ++i) ASSERT_EQ(m.joints[static_cast<std::size_t>(i)].parent, i - 1);
    EXPECT_EQ(m.joints.back().name, "J" + std::to_string(kDepth));
    EXPECT_EQ(m.channelCount, 3 + kDepth);
    ASSERT_EQ(m.endSites.size(), 1U);
    EXPECT_EQ(m.endSites[0].parent, kDepth);

    // Forward kinematics over the whole chain: every joint sits one unit above its parent.
    const auto globals = throng::motion::globalTransforms(m, 0, throng::motion::PositionChannels::Replace);
    ASSERT_EQ(globals.size(), static_cast<std::size_t>(kDepth + 1));
    EXPECT_DOUBLE_EQ(globals[0][3][0], 1.0);
    EXPECT_DOUBLE_EQ(globals[0][3][1], 2.0);
    EXPECT_DOUBLE_EQ(globals.back()[3][0], 1.0);
    EXPECT_DOUBLE_EQ(globals.back()[3][1], 2.0 + kDepth);
    EXPECT_DOUBLE_EQ(globals.back()[3][2], 3.0);
}

TEST(BvhParser, JointLimitRefusesCleanly) {
    std::string text = "HIERARCHY\nROOT J0\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
    for (int i = 1; i <= 10; ++i) text += "JOINT J" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n";
    for (int i = 0; i <= 10; ++i) text += "}\n";
    text += "MOTION\nFrames: 0\nFrame Time: 0.1\n";
    EXPECT_TRUE(parseBvh(text, "limit.bvh").ok());
    throng::motion::BvhLimits limits;
    limits.maxJoints = 5;
    auto result = parseBvh(text, "limit.bvh", limits);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().kind, Error::Kind::BadInput);
    EXPECT_GE(result.error().location.line, 1);
}

// --- A few error sanity checks (the CLI tests cover malformed input exhaustively) ------

TEST(BvhParserErrors, MissingHierarchyKeyword) {
    const Error e = parseFails("HIERARCHX\nROOT Hips\n", "bad.bvh");
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    EXPECT_EQ(e.location.file, "bad.bvh");
    EXPECT_EQ(e.location.line, 1);
    EXPECT_EQ(e.location.column, 1);
    EXPECT_NE(e.message.find("HIERARCHY"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("HIERARCHX"), std::string::npos) << e.message;
}

TEST(BvhParserErrors, UnknownChannelNameHasLineAndColumn) {
    const std::string text = replaceAll(std::string(kSmall), "CHANNELS 3 Zrotation Xrotation Yrotation",
                                        "CHANNELS 3 Zrotation Wrotation Yrotation");
    const Error e = parseFails(text);
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    EXPECT_EQ(e.location.line, 9);
    EXPECT_EQ(e.location.column, 26);  // "    CHANNELS 3 Zrotation " is 25 bytes
    EXPECT_NE(e.message.find("Wrotation"), std::string::npos) << e.message;
}

TEST(BvhParserErrors, BadNumberInOffsetHasLineAndColumn) {
    const std::string text = replaceAll(std::string(kSmall), "OFFSET 2 -1 0.5", "OFFSET 2 -1 0.5.1");
    const Error e = parseFails(text);
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    EXPECT_EQ(e.location.line, 17);
    EXPECT_EQ(e.location.column, 17);  // "    OFFSET 2 -1 " is 16 bytes
    EXPECT_NE(e.message.find("0.5.1"), std::string::npos) << e.message;
}

TEST(BvhParserErrors, ShortFrameRowNamesItsLine) {
    // Long numbers, so the text left is enough for two rows and the row itself is blamed.
    const std::string text =
        replaceAll(std::string(kSmall), "13 14 15 16 17 18 19 20 21 22 23 24", "13.000000 14.000000 15.000000");
    const Error e = parseFails(text);
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    EXPECT_EQ(e.location.line, 29);
    EXPECT_NE(e.message.find("12"), std::string::npos) << e.message;
    EXPECT_NE(e.describe().find("bad.bvh:29"), std::string::npos) << e.describe();
}

// --- Robustness: every truncation and single-byte corruption of a valid file ------------

void checkRobust(std::string_view text, int lineCount) {
    auto result = parseBvh(text, "fuzz.bvh");
    if (result.ok()) {
        const RawMotion& m = result.value();
        ASSERT_EQ(m.values.size(),
                  static_cast<std::size_t>(m.frameCount) * static_cast<std::size_t>(m.channelCount));
        ASSERT_GE(m.jointCount(), 1);
        ASSERT_GT(m.frameTime, 0.0);
    } else {
        const Error& e = result.error();
        ASSERT_EQ(e.kind, Error::Kind::BadInput);
        ASSERT_GE(e.location.line, 1) << e.describe();
        ASSERT_LE(e.location.line, lineCount + 1) << e.describe();
        ASSERT_GE(e.location.column, 0) << e.describe();
        ASSERT_FALSE(e.message.empty());
        ASSERT_EQ(e.location.file, "fuzz.bvh");
    }
}

TEST(BvhParserRobustness, EveryTruncationSucceedsOrFailsCleanly) {
    const int lines = static_cast<int>(std::count(kSmall.begin(), kSmall.end(), '\n'));
    int succeeded = 0;
    for (std::size_t length = 0; length <= kSmall.size(); ++length) {
        SCOPED_TRACE("truncated at byte " + std::to_string(length));
        const std::string_view prefix = kSmall.substr(0, length);
        checkRobust(prefix, lines);
        if (HasFatalFailure()) return;
        if (parseBvh(prefix, "fuzz.bvh").ok()) ++succeeded;
    }
    // The full text parses; cutting inside the hierarchy never does.
    EXPECT_GE(succeeded, 1);
    EXPECT_FALSE(parseBvh(kSmall.substr(0, kSmall.find("MOTION")), "fuzz.bvh").ok());
    const std::string crlf = replaceAll(std::string(kSmall), "\n", "\r\n");
    for (std::size_t length = 0; length <= crlf.size(); ++length) {
        SCOPED_TRACE("CRLF truncated at byte " + std::to_string(length));
        checkRobust(std::string_view(crlf).substr(0, length), lines);
        if (HasFatalFailure()) return;
    }
}

TEST(BvhParserRobustness, EverySingleByteCorruptionSucceedsOrFailsCleanly) {
    const int lines = static_cast<int>(std::count(kSmall.begin(), kSmall.end(), '\n'));
    const std::string replacements{'{', '}', '\n', ' ', 'x', '-', '.', '9', '\0', '\xff'};
    for (std::size_t pos = 0; pos < kSmall.size(); ++pos) {
        for (char r : replacements) {
            std::string text(kSmall);
            text[pos] = r;
            SCOPED_TRACE("byte " + std::to_string(pos) + " -> " + std::to_string(static_cast<int>(r)));
            // A replaced byte may add a line.
            checkRobust(text, lines + 1);
            if (HasFatalFailure()) return;
        }
        std::string erased(kSmall);
        erased.erase(pos, 1);
        checkRobust(erased, lines);
        if (HasFatalFailure()) return;
    }
}

}  // namespace
