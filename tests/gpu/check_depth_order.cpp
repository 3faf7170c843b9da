// Depth where two characters' bodies overlap on screen (#13): which of the two is in front at
// each pixel, read off four renders per body (both characters, A alone, B alone, neither; the
// one left out moved behind the camera so everything else, seed included, stays the same) and
// compared with the same four rendered as the paper's joint spheres, whose ray-cast depth is
// the reference.
//   check_depth_order REFERENCE_PREFIX TEST_PREFIX [--min-overlap N] [--min-agreement F]
// A prefix P names P_both.png, P_a.png, P_b.png and P_none.png. A pixel is covered by A where
// P_a differs from P_none (likewise B); where both cover it, the character in front is the one
// P_both shows there (within a tolerance, matching one and not the other). Only pixels that
// overlap in both bodies are compared: spheres and capsules cover different pixels, and depth
// is only defined where both characters are drawn. At least --min-overlap such pixels (default
// 200) and --min-agreement of them (default 0.98) must name the same character in front.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "image_compare.h"

namespace {

using throng::imagecmp::Image;

constexpr int kCoverTolerance = 12;  // above the ground's own noise (none: same bytes) and dither
constexpr int kMatchTolerance = 6;   // P_both against P_a or P_b where one is in front

struct Renders {
    Image both, a, b, none;
};

std::optional<Renders> loadRenders(const std::string& prefix) {
    Renders renders;
    const std::array<std::pair<const char*, Image*>, 4> parts{
        {{"_both.png", &renders.both}, {"_a.png", &renders.a}, {"_b.png", &renders.b}, {"_none.png", &renders.none}}};
    for (const auto& [suffix, image] : parts) {
        auto loaded = throng::imagecmp::loadPng(prefix + suffix);
        if (!loaded) {
            std::fprintf(stderr, "check_depth_order: %s\n", loaded.error().describe().c_str());
            return std::nullopt;
        }
        *image = std::move(loaded.value());
    }
    const auto sameSize = [&](const Image& image) { return image.width == renders.both.width && image.height == renders.both.height; };
    if (!sameSize(renders.a) || !sameSize(renders.b) || !sameSize(renders.none)) {
        std::fprintf(stderr, "check_depth_order: %s_*.png differ in size\n", prefix.c_str());
        return std::nullopt;
    }
    return renders;
}

int pixelDistance(const Image& x, const Image& y, std::size_t pixel) {
    int largest = 0;
    for (std::size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int{x.rgba[pixel * 4 + c]} - int{y.rgba[pixel * 4 + c]}));
    return largest;
}

enum class Front { None, A, B, Unclear };

/// Whether P_both shows each character where only it covers a pixel, as P_a or P_b do: if
/// not, the characters are not where they were alone (the scenes' draws diverged) and no
/// pixel's order means anything. Returns the fraction of such pixels that disagree.
double lonePixelsDisagreeing(const Renders& r) {
    long lone = 0, disagree = 0;
    const std::size_t pixels = static_cast<std::size_t>(r.both.width) * static_cast<std::size_t>(r.both.height);
    for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
        const bool coverA = pixelDistance(r.a, r.none, pixel) > kCoverTolerance;
        const bool coverB = pixelDistance(r.b, r.none, pixel) > kCoverTolerance;
        if (coverA == coverB) continue;
        ++lone;
        if (pixelDistance(r.both, coverA ? r.a : r.b, pixel) > kMatchTolerance) ++disagree;
    }
    return lone > 0 ? static_cast<double>(disagree) / static_cast<double>(lone) : 1.0;
}

/// Which character is in front at `pixel`: None where they don't both cover it.
Front frontAt(const Renders& r, std::size_t pixel) {
    const bool coverA = pixelDistance(r.a, r.none, pixel) > kCoverTolerance;
    const bool coverB = pixelDistance(r.b, r.none, pixel) > kCoverTolerance;
    if (!coverA || !coverB) return Front::None;
    const bool showsA = pixelDistance(r.both, r.a, pixel) <= kMatchTolerance;
    const bool showsB = pixelDistance(r.both, r.b, pixel) <= kMatchTolerance;
    if (showsA == showsB) return Front::Unclear;  // same colour in both, or neither (a blend)
    return showsA ? Front::A : Front::B;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: check_depth_order REFERENCE_PREFIX TEST_PREFIX [--min-overlap N] [--min-agreement F]\n");
        return 2;
    }
    long minOverlap = 200;
    double minAgreement = 0.98;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--min-overlap") minOverlap = std::strtol(argv[i + 1], nullptr, 10);
        else if (flag == "--min-agreement") minAgreement = std::strtod(argv[i + 1], nullptr);
        else {
            std::fprintf(stderr, "check_depth_order: unknown option %s\n", flag.c_str());
            return 2;
        }
    }
    const auto reference = loadRenders(argv[1]);
    const auto tested = loadRenders(argv[2]);
    if (!reference || !tested) return 2;
    if (reference->both.width != tested->both.width || reference->both.height != tested->both.height) {
        std::fprintf(stderr, "check_depth_order: the reference and tested renders differ in size\n");
        return 2;
    }

    // Shadows on the ground may fall differently with both present; a character elsewhere
    // would disagree at most of its pixels.
    for (const auto& [name, renders] : std::array{std::pair{argv[1], &*reference}, std::pair{argv[2], &*tested}}) {
        const double off = lonePixelsDisagreeing(*renders);
        if (off > 0.02) {
            std::printf("check_depth_order: %s_both.png shows the characters elsewhere than %s_a.png and _b.png (%.1f%% of the pixels "
                        "only one covers differ): FAIL\n",
                        name, name, 100.0 * off);
            return 1;
        }
    }

    long overlap = 0, agree = 0, referenceA = 0;
    const std::size_t pixels = static_cast<std::size_t>(tested->both.width) * static_cast<std::size_t>(tested->both.height);
    for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
        const Front expected = frontAt(*reference, pixel);
        const Front got = frontAt(*tested, pixel);
        if (expected == Front::None || expected == Front::Unclear || got == Front::None || got == Front::Unclear) continue;
        ++overlap;
        if (expected == Front::A) ++referenceA;
        if (got == expected) ++agree;
    }
    const double agreement = overlap > 0 ? static_cast<double>(agree) / static_cast<double>(overlap) : 0.0;
    const bool pass = overlap >= minOverlap && agreement >= minAgreement;
    std::printf("check_depth_order: %s against %s: %ld pixels where both characters are drawn in both (at least %ld wanted; "
                "A in front in %ld of them in the reference), the same character in front at %.2f%% (at least %.2f%% wanted): %s\n",
                argv[2], argv[1], overlap, minOverlap, referenceA, 100.0 * agreement, 100.0 * minAgreement, pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
}
