#pragma once
// Shared by the BVH parser tests: a small reference file and helpers to parse it.

#include <gtest/gtest.h>
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>
#include "throng/core/error.h"
#include "throng/motion/bvh_parser.h"
#include "throng/motion/forward_kinematics.h"
#include "throng/motion/raw_motion.h"

namespace bvh_test {


using throng::Error;
using throng::motion::Channel;
using throng::motion::parseBvh;
using throng::motion::RawMotion;

// A small skeleton with two End Sites, a 6-channel root and two differently ordered
// 3-channel joints. Line numbers matter for the sourceLine checks below.
inline constexpr std::string_view kSmall =
    "HIERARCHY\n"                                                                 // 1
    "ROOT Hips\n"                                                                 // 2
    "{\n"                                                                         // 3
    "  OFFSET 0.5 -1 2\n"                                                         // 4
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"  // 5
    "  JOINT Spine\n"                                                             // 6
    "  {\n"                                                                       // 7
    "    OFFSET 0 10 0\n"                                                         // 8
    "    CHANNELS 3 Zrotation Xrotation Yrotation\n"                              // 9
    "    End Site\n"                                                              // 10
    "    {\n"                                                                     // 11
    "      OFFSET 0 5 0.25\n"                                                     // 12
    "    }\n"                                                                     // 13
    "  }\n"                                                                       // 14
    "  JOINT Leg\n"                                                               // 15
    "  {\n"                                                                       // 16
    "    OFFSET 2 -1 0.5\n"                                                       // 17
    "    CHANNELS 3 Xrotation Yrotation Zrotation\n"                              // 18
    "    End Site\n"                                                              // 19
    "    {\n"                                                                     // 20
    "      OFFSET 0 -8 0\n"                                                       // 21
    "    }\n"                                                                     // 22
    "  }\n"                                                                       // 23
    "}\n"                                                                         // 24
    "MOTION\n"                                                                    // 25
    "Frames: 2\n"                                                                 // 26
    "Frame Time: 0.0333333\n"                                                     // 27
    "1 2 3 4 5 6 7 8 9 10 11 12\n"                                                // 28
    "13 14 15 16 17 18 19 20 21 22 23 24\n";                                      // 29

inline RawMotion parseOk(std::string_view text, std::string_view name = "test.bvh") {
    auto result = parseBvh(text, name);
    if (!result.ok()) {
        ADD_FAILURE() << "parse failed: " << result.error().describe();
        return {};
    }
    return std::move(result).value();
}

inline Error parseFails(std::string_view text, std::string_view name = "bad.bvh") {
    auto result = parseBvh(text, name);
    if (result.ok()) {
        ADD_FAILURE() << "parse unexpectedly succeeded";
        return {};
    }
    return result.error();
}

inline std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            lines.emplace_back(text.substr(start));
            break;
        }
        lines.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

inline std::string replaceAll(std::string text, std::string_view from, std::string_view to) {
    std::size_t pos = 0;
    while ((pos = text.find(from, pos)) != std::string::npos) {
        text.replace(pos, from.size(), to);
        pos += to.size();
    }
    return text;
}

inline void expectSameMotion(const RawMotion& a, const RawMotion& b, bool compareSourceLines = true) {
    ASSERT_EQ(a.joints.size(), b.joints.size());
    for (std::size_t i = 0; i < a.joints.size(); ++i) {
        SCOPED_TRACE("joint " + std::to_string(i));
        EXPECT_EQ(a.joints[i].name, b.joints[i].name);
        EXPECT_EQ(a.joints[i].parent, b.joints[i].parent);
        EXPECT_EQ(a.joints[i].offset, b.joints[i].offset);
        EXPECT_EQ(a.joints[i].channels, b.joints[i].channels);
        EXPECT_EQ(a.joints[i].firstValue, b.joints[i].firstValue);
        if (compareSourceLines) {
            EXPECT_EQ(a.joints[i].sourceLine, b.joints[i].sourceLine);
        }
    }
    ASSERT_EQ(a.endSites.size(), b.endSites.size());
    for (std::size_t i = 0; i < a.endSites.size(); ++i) {
        EXPECT_EQ(a.endSites[i].parent, b.endSites[i].parent);
        EXPECT_EQ(a.endSites[i].offset, b.endSites[i].offset);
    }
    EXPECT_EQ(a.channelCount, b.channelCount);
    EXPECT_EQ(a.frameCount, b.frameCount);
    EXPECT_EQ(a.frameTime, b.frameTime);
    EXPECT_EQ(a.values, b.values);
}

}  // namespace bvh_test
