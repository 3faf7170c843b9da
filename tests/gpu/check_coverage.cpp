// How much of a rendered frame shows characters: the fraction of pixels that are neither the
// ground nor the sky. Those are near grey (the checker, the fog, the sky's pale blue); the
// characters' clothing and skin are coloured (chroma, the largest channel less the smallest,
// of 30 or more out of 255) or dark (trousers, shoes and hair: every channel under 60). A lower
// bound, then: grey clothing in the light counts as ground.
//   check_coverage IMAGE.png --at-least FRACTION
#include <algorithm>
#include <cstdio>
#include <string>

#include "image_compare.h"

int main(int argc, char** argv) {
    if (argc != 4 || std::string(argv[2]) != "--at-least") {
        std::fprintf(stderr, "usage: check_coverage IMAGE.png --at-least FRACTION\n");
        return 2;
    }
    const auto image = throng::imagecmp::loadPng(argv[1]);
    if (!image) {
        std::fprintf(stderr, "check_coverage: %s\n", image.error().describe().c_str());
        return 2;
    }
    const double wanted = std::stod(argv[3]);
    const auto& rgba = image.value().rgba;
    std::size_t characters = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        const int r = rgba[i], g = rgba[i + 1], b = rgba[i + 2];
        const int chroma = std::max({r, g, b}) - std::min({r, g, b});
        if (chroma >= 30 || std::max({r, g, b}) < 60) ++characters;
    }
    const double fraction = static_cast<double>(characters) / static_cast<double>(rgba.size() / 4);
    const bool pass = fraction >= wanted;
    std::printf("check_coverage: %s: %.1f%% of the pixels show characters (at least %.1f%% wanted): %s\n", argv[1], 100.0 * fraction,
                100.0 * wanted, pass ? "PASS" : "FAIL");
    return pass ? 0 : 1;
}
