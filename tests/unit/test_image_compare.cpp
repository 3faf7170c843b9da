// The image comparison decides whether a rendering regressed, so its rules must be exact:
// what counts as differing, what fuzzy mode forgives, and what it writes on failure.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "image_compare.h"
#include "throng/core/atomic_file.h"

namespace {

namespace ic = throng::imagecmp;
namespace fs = std::filesystem;

ic::Image solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    ic::Image image;
    image.width = width;
    image.height = height;
    for (int i = 0; i < width * height; ++i) image.rgba.insert(image.rgba.end(), {r, g, b, 255});
    return image;
}

std::uint8_t* at(ic::Image& image, int x, int y) {
    return image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
}

void setPixel(ic::Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::uint8_t* p = at(image, x, y);
    p[0] = r, p[1] = g, p[2] = b;
}

// Black left of column `edge`, white from it on: a vertical boundary as a rasterizer draws it.
ic::Image verticalEdge(int width, int height, int edge) {
    ic::Image image = solid(width, height, 0, 0, 0);
    for (int y = 0; y < height; ++y)
        for (int x = edge; x < width; ++x) setPixel(image, x, y, 255, 255, 255);
    return image;
}

// A fresh, empty directory per test, under GoogleTest's temp dir.
fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(::testing::TempDir()) / ("throng_image_compare_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

const ic::CompareOptions kExact{};

TEST(ImageCompare, IdenticalImagesPassExact) {
    const ic::Image a = verticalEdge(16, 8, 5);
    const ic::CompareReport report = ic::compare(a, a, kExact);
    EXPECT_TRUE(report.sameSize);
    EXPECT_TRUE(report.passed);
    EXPECT_EQ(report.differingPixels, 0);
    EXPECT_EQ(report.differingFraction, 0.0);
    EXPECT_EQ(report.maxChannelDifference, 0);
}

TEST(ImageCompare, OneChangedPixelFailsExactButPassesWithFractionOfOnePixel) {
    const ic::Image reference = solid(7, 9, 40, 80, 120);
    ic::Image result = reference;
    setPixel(result, 3, 4, 40, 200, 120);
    const int pixels = 7 * 9;

    const ic::CompareReport exact = ic::compare(result, reference, kExact);
    EXPECT_FALSE(exact.passed);
    EXPECT_EQ(exact.differingPixels, 1);
    EXPECT_DOUBLE_EQ(exact.differingFraction, 1.0 / pixels);
    EXPECT_EQ(exact.maxChannelDifference, 120);

    ic::CompareOptions loose;
    loose.maxDifferingFraction = 1.0 / pixels;
    EXPECT_TRUE(ic::compare(result, reference, loose).passed);
    loose.maxDifferingFraction = 0.5 / pixels;
    EXPECT_FALSE(ic::compare(result, reference, loose).passed);
}

TEST(ImageCompare, ChannelToleranceIsInclusive) {
    const ic::Image reference = solid(5, 5, 100, 100, 100);
    ic::Image result = reference;
    setPixel(result, 2, 2, 100, 103, 100);

    ic::CompareOptions options;
    options.channelTolerance = 3;
    const ic::CompareReport within = ic::compare(result, reference, options);
    EXPECT_TRUE(within.passed);
    EXPECT_EQ(within.maxChannelDifference, 3);
    options.channelTolerance = 2;
    EXPECT_FALSE(ic::compare(result, reference, options).passed);
}

TEST(ImageCompare, OnePixelEdgeShiftFailsExactButPassesFuzzy) {
    const ic::Image reference = verticalEdge(12, 6, 5);
    const ic::Image result = verticalEdge(12, 6, 6);  // the boundary moved one column right

    const ic::CompareReport exact = ic::compare(result, reference, kExact);
    EXPECT_FALSE(exact.passed);
    EXPECT_EQ(exact.differingPixels, 6);  // the whole of column 5

    ic::CompareOptions fuzzy;
    fuzzy.channelTolerance = 1;
    EXPECT_TRUE(ic::neighbourShiftEnabled(fuzzy));
    EXPECT_TRUE(ic::compare(result, reference, fuzzy).passed);

    // The forgiveness comes from the neighbour rule, not from the tolerance.
    fuzzy.allowNeighbourShift = false;
    EXPECT_FALSE(ic::compare(result, reference, fuzzy).passed);
}

TEST(ImageCompare, TwoPixelShiftIsNotForgiven) {
    const ic::CompareReport report =
        ic::compare(verticalEdge(12, 6, 7), verticalEdge(12, 6, 5), ic::CompareOptions{1, 0.0, std::nullopt});
    EXPECT_FALSE(report.passed);
    EXPECT_EQ(report.differingPixels, 12);  // columns 5 and 6: each fails one of the two directions
}

TEST(ImageCompare, VanishedThinLineIsNotForgiven) {
    // One direction alone would forgive this: the result's black is next to the line in the
    // reference. The reference's white line, however, appears nowhere near in the result.
    ic::Image reference = solid(9, 5, 0, 0, 0);
    for (int y = 0; y < 5; ++y) setPixel(reference, 4, y, 255, 255, 255);
    const ic::Image result = solid(9, 5, 0, 0, 0);
    const ic::CompareReport report = ic::compare(result, reference, ic::CompareOptions{2, 0.0, std::nullopt});
    EXPECT_FALSE(report.passed);
    EXPECT_EQ(report.differingPixels, 5);
}

TEST(ImageCompare, NeighbourShiftDefaultsOffInExactMode) {
    EXPECT_FALSE(ic::neighbourShiftEnabled(kExact));
    ic::CompareOptions options;
    options.maxDifferingFraction = 0.01;
    EXPECT_TRUE(ic::neighbourShiftEnabled(options));
    options.allowNeighbourShift = false;
    EXPECT_FALSE(ic::neighbourShiftEnabled(options));
}

TEST(ImageCompare, SizeMismatchFails) {
    const ic::Image result = solid(8, 8, 10, 10, 10);
    const ic::Image reference = solid(8, 7, 10, 10, 10);
    ic::CompareOptions lenient;
    lenient.channelTolerance = 255;
    lenient.maxDifferingFraction = 1.0;
    const ic::CompareReport report = ic::compare(result, reference, lenient);
    EXPECT_FALSE(report.sameSize);
    EXPECT_FALSE(report.passed);
    EXPECT_EQ(report.differingPixels, 8);  // the row only the result has
    EXPECT_EQ(report.referenceHeight, 7);
}

TEST(ImageCompare, MalformedImageNeverPasses) {
    ic::Image broken = solid(4, 4, 0, 0, 0);
    broken.rgba.pop_back();
    EXPECT_FALSE(ic::compare(broken, broken, kExact).passed);
}

TEST(ImageCompare, DiffImageMarksExactlyTheDifferingPixels) {
    const ic::Image reference = verticalEdge(10, 6, 4);
    ic::Image result = reference;
    setPixel(result, 1, 1, 0, 7, 0);        // small error: must still be clearly visible
    setPixel(result, 7, 3, 0, 0, 0);        // large error
    setPixel(result, 8, 5, 255, 255, 250);  // within the tolerance used below
    ic::CompareOptions options;
    options.channelTolerance = 5;
    options.allowNeighbourShift = false;

    ic::Image diff = ic::diffImage(result, reference, options);
    ASSERT_EQ(diff.width, 10);
    ASSERT_EQ(diff.height, 6);
    for (int y = 0; y < diff.height; ++y)
        for (int x = 0; x < diff.width; ++x) {
            const std::uint8_t* p = at(diff, x, y);
            const bool marked = p[0] != p[1];  // unmarked pixels are grey: R == G == B
            const bool expected = (x == 1 && y == 1) || (x == 7 && y == 3);
            EXPECT_EQ(marked, expected) << "at " << x << "," << y;
            EXPECT_EQ(p[3], 255);
            if (marked) EXPECT_GE(p[0], 128);
            else EXPECT_LE(p[0], 64);  // dimmed so the marks stand out
        }
    EXPECT_EQ(at(diff, 7, 3)[0], 255);  // 255 * 8 clamps
    EXPECT_EQ(ic::compare(result, reference, options).differingPixels, 2);
}

TEST(ImageCompare, PngRoundTripPreservesPixels) {
    ic::Image image = verticalEdge(13, 7, 6);
    setPixel(image, 2, 3, 12, 34, 56);
    at(image, 9, 1)[3] = 77;  // alpha must survive too
    const std::string path = (freshDir("roundtrip") / "image.png").string();
    const throng::Result<bool> saved = ic::savePng(path, image);
    ASSERT_TRUE(saved.ok()) << saved.error().describe();
    const throng::Result<ic::Image> loaded = ic::loadPng(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().describe();
    EXPECT_EQ(loaded.value().width, 13);
    EXPECT_EQ(loaded.value().height, 7);
    EXPECT_EQ(loaded.value().rgba, image.rgba);
}

TEST(ImageCompare, CompareFilesWritesFailureImagesOnlyOnFailure) {
    const fs::path dir = freshDir("files");
    const fs::path failures = dir / "failures" / "nested";
    const ic::Image reference = verticalEdge(8, 8, 4);
    ic::Image different = reference;
    setPixel(different, 0, 0, 255, 0, 0);
    ASSERT_TRUE(ic::savePng((dir / "same.png").string(), reference).ok());
    ASSERT_TRUE(ic::savePng((dir / "frame.png").string(), different).ok());
    ASSERT_TRUE(ic::savePng((dir / "reference.png").string(), reference).ok());

    const auto same = ic::compareFiles((dir / "same.png").string(), (dir / "reference.png").string(), kExact,
                                       failures.string());
    ASSERT_TRUE(same.ok()) << same.error().describe();
    EXPECT_TRUE(same.value().passed);
    EXPECT_FALSE(fs::exists(failures));

    const auto differ = ic::compareFiles((dir / "frame.png").string(), (dir / "reference.png").string(), kExact,
                                         failures.string());
    ASSERT_TRUE(differ.ok()) << differ.error().describe();
    EXPECT_FALSE(differ.value().passed);
    EXPECT_EQ(differ.value().differingPixels, 1);
    const ic::FailureImages written = ic::failureImagePaths((dir / "frame.png").string(), failures.string());
    EXPECT_EQ(written.diff, (failures / "frame.diff.png").string());
    const auto result = ic::loadPng(written.result);
    const auto ref = ic::loadPng(written.reference);
    const auto diff = ic::loadPng(written.diff);
    ASSERT_TRUE(result.ok() && ref.ok() && diff.ok());
    EXPECT_EQ(result.value().rgba, different.rgba);
    EXPECT_EQ(ref.value().rgba, reference.rgba);
    EXPECT_EQ(diff.value().width, 8);
    EXPECT_EQ(std::distance(fs::directory_iterator(failures), fs::directory_iterator()), 3);
}

TEST(ImageCompare, CompareFilesNeverOverwritesTheReference) {
    // <stem>.reference.png beside the result is exactly where a reference might live.
    const fs::path dir = freshDir("overwrite");
    const ic::Image reference = solid(4, 4, 1, 2, 3);
    ASSERT_TRUE(ic::savePng((dir / "a.png").string(), solid(4, 4, 9, 9, 9)).ok());
    ASSERT_TRUE(ic::savePng((dir / "a.reference.png").string(), reference).ok());
    const auto compared =
        ic::compareFiles((dir / "a.png").string(), (dir / "a.reference.png").string(), kExact, dir.string());
    ASSERT_FALSE(compared.ok());
    EXPECT_NE(compared.error().message.find("overwrite"), std::string::npos);
}

TEST(ImageCompare, LoadingAMissingFileNamesIt) {
    const std::string path = (freshDir("missing") / "nowhere.png").string();
    const throng::Result<ic::Image> loaded = ic::loadPng(path);
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().describe().find(path), std::string::npos) << loaded.error().describe();
}

TEST(ImageCompare, LoadingANonPngFails) {
    const fs::path path = freshDir("notpng") / "text.png";
    ASSERT_TRUE(throng::writeFileAtomically(path.string(), "not an image").ok());
    const throng::Result<ic::Image> loaded = ic::loadPng(path.string());
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().describe().find(path.string()), std::string::npos);
}

}  // namespace
