// VideoWriter::repeat (#15): the demo's recording holds a frame for as many video frames as it
// stays on screen. Frame files get byte-identical copies; an MP4 holds the frame without
// encoding it again and still lasts its full time (read back with FFmpeg's ffprobe).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "throng/render/video.h"

namespace throng::render {
namespace {

constexpr std::uint32_t kWidth = 32, kHeight = 16;

std::vector<std::uint8_t> solidFrame(std::uint8_t red) {
    std::vector<std::uint8_t> rgba(std::size_t{kWidth} * kHeight * 4, 255);
    for (std::size_t p = 0; p < rgba.size(); p += 4) rgba[p] = red;
    return rgba;
}

std::string bytesOf(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path scratch(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("throng_video_writer_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// What ffprobe prints for `entries` of the file's first video stream, one line.
std::string probe(const std::filesystem::path& file, const std::string& entries) {
    const std::string command = "ffprobe -v error -count_frames -select_streams v:0 -show_entries " + entries + " -of csv=p=0 '" + file.string() + "'";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) return "popen failed";
    std::array<char, 256> line{};
    std::string out = std::fgets(line.data(), static_cast<int>(line.size()), pipe) != nullptr ? line.data() : "";
    pclose(pipe);
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    return out;
}

TEST(VideoWriter, RepeatedFramesAreCopiesOfTheLastFile) {
    const std::filesystem::path folder = scratch("png");
    auto writer = VideoWriter::open({.path = (folder / "%02d.png").string(), .width = kWidth, .height = kHeight}).orThrow();
    ASSERT_TRUE(writer.repeat());  // nothing added yet: nothing to repeat
    EXPECT_TRUE(std::filesystem::is_empty(folder));
    const auto red = solidFrame(255), dark = solidFrame(10);
    ASSERT_TRUE(writer.add(red.data(), std::size_t{kWidth} * 4));
    ASSERT_TRUE(writer.repeat());
    ASSERT_TRUE(writer.repeat());
    ASSERT_TRUE(writer.add(dark.data(), std::size_t{kWidth} * 4));
    ASSERT_TRUE(writer.finish());
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"00.png", "01.png", "02.png", "03.png"}));
    EXPECT_EQ(bytesOf(folder / "01.png"), bytesOf(folder / "00.png"));
    EXPECT_EQ(bytesOf(folder / "02.png"), bytesOf(folder / "00.png"));
    EXPECT_NE(bytesOf(folder / "03.png"), bytesOf(folder / "00.png"));
}

TEST(VideoWriter, AHeldFrameLastsItsTimeInAnMp4WithoutBeingEncodedAgain) {
    const std::filesystem::path file = scratch("mp4") / "held.mp4";
    auto writer = VideoWriter::open({.path = file.string(), .width = kWidth, .height = kHeight, .framesPerSecond = 10}).orThrow();
    const auto red = solidFrame(255), dark = solidFrame(10);
    ASSERT_TRUE(writer.add(red.data(), std::size_t{kWidth} * 4));
    for (int i = 0; i < 9; ++i) ASSERT_TRUE(writer.repeat());
    ASSERT_TRUE(writer.add(dark.data(), std::size_t{kWidth} * 4));
    for (int i = 0; i < 9; ++i) ASSERT_TRUE(writer.repeat());
    ASSERT_TRUE(writer.finish());
    // Twenty frame times of 0.1 s: 2 s, from three encoded frames (the last one is sent again
    // at the end so that it shows for its whole second).
    const double seconds = std::stod(probe(file, "stream=duration"));
    EXPECT_NEAR(seconds, 2.0, 0.101);
    EXPECT_EQ(probe(file, "stream=nb_read_frames"), "3");
}

}  // namespace
}  // namespace throng::render
