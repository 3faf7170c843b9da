// check_screenshot: sanity checks on a screenshot of `throng demo`, for the window tests.
//
// The demo's picture changes with the crowd, the window size and the driver, so it is not
// compared with a reference image; instead three properties that any correct frame has:
//   (a) not blank:      the luminance varies (a cleared or black frame has stddev ~ 0);
//   (b) crowd visible:  enough strongly coloured pixels outside the HUD region (the character
//                       spheres are the only saturated things in the scene: the ground is
//                       grey, the sky pale; the HUD's blue buttons and title bar are
//                       saturated too, hence the HUD region is left out);
//   (c) HUD visible:    the top-left holds a dark ImGui panel, and the bottom-right (ground
//                       and characters, no HUD) does not look like one.
// The HUD region is the top-left 35% x 45% of the frame, at least 480 x 360 pixels (the
// panel's size is fixed in pixels); see the constants below.
//
// Prints one line on stdout:
//   check_screenshot: WxH stddev=S saturated=N hud_dark=P% corner_dark=Q% PASS|FAIL
// and, for each failed check, one line on stderr saying why.
// Exit status: 0 pass, 1 a check failed, 2 usage error or unreadable file.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "image_compare.h"

namespace {

namespace ic = throng::imagecmp;

constexpr int kExitPass = 0;
constexpr int kExitFail = 1;
constexpr int kExitUsage = 2;

// (a) A blank frame (only the clear colour, or all black) has a luminance standard
// deviation near 0; ground checker and characters give ~12 on their own (a headless 640x400
// `throng render`), the demo's frames with the HUD panel ~25-60.
constexpr double kMinLuminanceStdDev = 10.0;

// (b) A pixel is "saturated" when its channels spread by more than this. The ground is grey
// (spread ~0), the sky pale blue-grey (~205,218,229: spread ~24), so in the scene only the
// coloured character spheres pass it. ImGui's blue title bar, buttons and plot pass it too
// (spread ~70-100), so pixels in the HUD region (see (c)) are not counted.
constexpr int kSaturationSpread = 60;
// A few hundred characters cover thousands of pixels at any window size the tests use (300
// characters outside the HUD region: ~19000 at 1280x720, ~3400 at 760x480); 200 leaves room for a far-away or partly hidden crowd
// while ruling out stray edge pixels.
constexpr long kMinSaturatedPixels = 200;

// (c) ImGui's default dark style draws window backgrounds at (0.06,0.06,0.06) with 94%
// alpha: about (15-30) per channel over any scene colour. Nothing else in the scene is that
// dark in all three channels (the ground is mid-grey, the spheres are lit with an ambient
// term), so "dark" pixels mark the HUD panel.
constexpr int kDarkChannelLimit = 60;  // dark: every channel below this
// The HUD region: the top-left 35% x 45% of the frame, but at least 520 x 420 pixels. The
// panel has a fixed size in pixels (about 480 x 395 at ImGui's default font, with its body,
// pace and blend lines and "visibility, auto path, ..."), so in a small frame
// (--script-resize can end at 760x480) it outgrows any fixed fraction; the pixel minimum
// keeps it, blue buttons included, inside the region.
constexpr double kHudRegionWidthFraction = 0.35;
constexpr double kHudRegionHeightFraction = 0.45;
constexpr int kHudRegionMinWidth = 520;
constexpr int kHudRegionMinHeight = 420;
// The panel must cover at least this share of that region (a small panel of a few lines of
// text covers ~10%; 2% still rules out stray dark pixels such as sphere silhouettes).
constexpr double kMinHudDarkFraction = 0.02;
// The bottom-right quarter, less the HUD region, shows ground and characters only: it must
// stay almost free of dark pixels, or the frame is dark everywhere and (c) proves nothing
// about a HUD. The demo frames the crowd beside the HUD, so the characters fill that quarter:
// their shaded sphere rims measure about 2% dark there; a dark frame or a panel is over 90%.
constexpr double kMaxCornerDarkFraction = 0.05;

struct Figures {
    double luminanceStdDev = 0.0;
    long saturatedPixels = 0;         // outside the HUD region
    double hudDarkFraction = 0.0;     // of the HUD region
    double cornerDarkFraction = 0.0;  // of the bottom-right quarter less the HUD region
    long cornerPixels = 0;            // how many pixels that is
};

bool isDark(const std::uint8_t* p) {
    return p[0] < kDarkChannelLimit && p[1] < kDarkChannelLimit && p[2] < kDarkChannelLimit;
}

Figures measure(const ic::Image& image) {
    const int hudWidth =
        std::min(image.width, std::max(kHudRegionMinWidth, static_cast<int>(image.width * kHudRegionWidthFraction)));
    const int hudHeight = std::min(
        image.height, std::max(kHudRegionMinHeight, static_cast<int>(image.height * kHudRegionHeightFraction)));
    Figures f;
    double sum = 0.0, sumSquares = 0.0;
    long hudPixels = 0, hudDark = 0, cornerDark = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
            // Rec. 709 luma weights on the stored (sRGB-encoded) values; alpha is ignored.
            const double luminance = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            sum += luminance;
            sumSquares += luminance * luminance;
            const int spread = std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
            const bool inHud = x < hudWidth && y < hudHeight;
            const bool inCorner = !inHud && x >= image.width / 2 && y >= image.height / 2;
            if (inHud) {
                ++hudPixels;
                hudDark += isDark(p) ? 1 : 0;
            } else if (spread > kSaturationSpread) {
                ++f.saturatedPixels;
            }
            if (inCorner) {
                ++f.cornerPixels;
                cornerDark += isDark(p) ? 1 : 0;
            }
        }
    }
    const double pixels = static_cast<double>(image.width) * image.height;
    const double mean = sum / pixels;
    f.luminanceStdDev = std::sqrt(std::max(0.0, sumSquares / pixels - mean * mean));
    f.hudDarkFraction = static_cast<double>(hudDark) / static_cast<double>(std::max(1L, hudPixels));
    f.cornerDarkFraction = static_cast<double>(cornerDark) / static_cast<double>(std::max(1L, f.cornerPixels));
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 || std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h") {
        std::fputs("usage: check_screenshot SCREENSHOT.png\n"
                   "Checks a `throng demo` screenshot: not blank, crowd visible, HUD visible.\n"
                   "Exit status: 0 pass, 1 a check failed, 2 usage error or unreadable file.\n",
                   argc == 2 ? stdout : stderr);
        return argc == 2 ? kExitPass : kExitUsage;
    }
    const std::string path = argv[1];
    auto loaded = ic::loadPng(path);
    if (!loaded) {
        std::fprintf(stderr, "check_screenshot: %s\n", loaded.error().describe().c_str());
        return kExitUsage;
    }
    const ic::Image& image = loaded.value();
    if (image.width < 2 || image.height < 2 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
        std::fprintf(stderr, "check_screenshot: error: %s: image too small or malformed (%dx%d)\n", path.c_str(),
                     image.width, image.height);
        return kExitUsage;
    }

    const Figures f = measure(image);
    bool pass = true;
    if (!(f.luminanceStdDev > kMinLuminanceStdDev)) {
        std::fprintf(stderr, "check_screenshot: blank frame: luminance stddev %.2f, need > %.1f\n",
                     f.luminanceStdDev, kMinLuminanceStdDev);
        pass = false;
    }
    if (f.saturatedPixels < kMinSaturatedPixels) {
        std::fprintf(stderr,
                     "check_screenshot: no crowd: %ld saturated pixels (channel spread > %d) outside the HUD "
                     "region, need >= %ld\n",
                     f.saturatedPixels, kSaturationSpread, kMinSaturatedPixels);
        pass = false;
    }
    if (f.hudDarkFraction < kMinHudDarkFraction) {
        std::fprintf(stderr,
                     "check_screenshot: no HUD: %.2f%% dark pixels (all channels < %d) in the top-left "
                     "%.0f%% x %.0f%% (at least %d x %d px), need >= %.1f%%\n",
                     100.0 * f.hudDarkFraction, kDarkChannelLimit, 100.0 * kHudRegionWidthFraction,
                     100.0 * kHudRegionHeightFraction, kHudRegionMinWidth, kHudRegionMinHeight,
                     100.0 * kMinHudDarkFraction);
        pass = false;
    }
    if (f.cornerPixels == 0) {
        std::fprintf(stderr, "check_screenshot: frame too small to tell the HUD from the scene (%dx%d)\n",
                     image.width, image.height);
        pass = false;
    } else if (f.cornerDarkFraction >= kMaxCornerDarkFraction) {
        std::fprintf(stderr,
                     "check_screenshot: frame dark outside the HUD: %.2f%% dark pixels in the bottom-right "
                     "quarter, need < %.1f%%\n",
                     100.0 * f.cornerDarkFraction, 100.0 * kMaxCornerDarkFraction);
        pass = false;
    }
    std::printf("check_screenshot: %dx%d stddev=%.2f saturated=%ld hud_dark=%.2f%% corner_dark=%.2f%% %s\n",
                image.width, image.height, f.luminanceStdDev, f.saturatedPixels, 100.0 * f.hudDarkFraction,
                100.0 * f.cornerDarkFraction, pass ? "PASS" : "FAIL");
    return pass ? kExitPass : kExitFail;
}
