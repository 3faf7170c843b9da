#pragma once
// Image-regression comparison: decides whether a rendered image matches its reference,
// exactly or within a fuzzy tolerance, and produces a diff picture a person can read.
//
// The fuzzy rule follows the spirit of the Vulkan CTS fuzzy compare: rasterization may
// legitimately move an edge by one pixel between drivers, so a pixel whose value appears
// within tolerance somewhere in the 3x3 neighbourhood of the other image is not an error.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "throng/core/error.h"

namespace throng::imagecmp {

/// An 8-bit RGBA image, rows top to bottom, tightly packed (no row padding).
struct Image {
    int width = 0;                   ///< Pixels per row.
    int height = 0;                  ///< Number of rows.
    std::vector<std::uint8_t> rgba;  ///< width*height*4 bytes: R, G, B, A per pixel.
};

/// Reads a PNG file, converting any PNG colour type or bit depth to 8-bit RGBA.
/// Errors (BadInput) name the path: missing, unreadable, a directory, or not a valid PNG.
[[nodiscard]] Result<Image> loadPng(const std::string& path);

/// Writes `image` as an RGBA PNG, atomically (a failed write leaves no partial file).
/// Errors: BadInput for an empty or malformed image, Runtime for I/O failures.
[[nodiscard]] Result<bool> savePng(const std::string& path, const Image& image);

/// How strict a comparison is. Exact mode is both numbers zero (the default).
struct CompareOptions {
    /// Largest absolute per-channel difference (0..255) that still counts as equal.
    int channelTolerance = 0;
    /// Fraction (0..1) of pixels allowed to differ while the comparison still passes.
    double maxDifferingFraction = 0.0;
    /// Whether a pixel matched within tolerance by a 3x3 neighbour in the other image
    /// (checked both ways, see compare()) is forgiven. Unset means: on in fuzzy mode
    /// (either number above non-zero), off in exact mode; see neighbourShiftEnabled().
    std::optional<bool> allowNeighbourShift;
};

/// The effective neighbour-shift setting for `options` (resolves the unset default).
[[nodiscard]] bool neighbourShiftEnabled(const CompareOptions& options);

/// What a comparison found.
struct CompareReport {
    /// Both images have the same width and height (and well-formed pixel buffers).
    bool sameSize = false;
    /// The images match under the options: same size and differingFraction within bounds.
    bool passed = false;
    /// Pixels counted as differing. With different sizes the images are laid over each
    /// other top-left aligned, and every pixel present in only one of them differs.
    std::int64_t differingPixels = 0;
    /// differingPixels over the pixel count (of the larger canvas when sizes differ).
    double differingFraction = 0.0;
    /// Largest absolute channel difference at the same position, before tolerance and
    /// neighbour forgiveness; only pixels present in both images contribute.
    int maxChannelDifference = 0;
    int width = 0;            ///< Result image width (for reporting).
    int height = 0;           ///< Result image height.
    int referenceWidth = 0;   ///< Reference image width; differs from width on a size mismatch.
    int referenceHeight = 0;  ///< Reference image height.
};

/// Compares `result` against `reference`. A pixel differs when some channel differs by
/// more than channelTolerance and, with neighbour shift on, it is not forgiven. It is
/// forgiven only if BOTH the result pixel is matched within tolerance by one of the 3x3
/// reference pixels around its position AND the reference pixel is matched by one of the
/// 3x3 result pixels: one direction alone would forgive a thin line that vanished
/// (the result's background is found next to the line in the reference). A malformed
/// image (buffer size not width*height*4) never passes.
[[nodiscard]] CompareReport compare(const Image& result, const Image& reference, const CompareOptions& options);

/// A picture of where the images differ, on the larger of the two canvases. Differing
/// pixels are red-magenta (red = 8x the largest channel difference, at least 128 so small
/// errors stay visible; blue = half of red; green = 0); pixels present in only one image
/// are full magenta; everything else is the reference's luminance dimmed to a quarter,
/// grey (R = G = B), for orientation. Alpha is opaque. Empty if either image is malformed.
[[nodiscard]] Image diffImage(const Image& result, const Image& reference, const CompareOptions& options);

/// Where compareFiles() puts the images of a failed comparison.
struct FailureImages {
    std::string result;     ///< <failureDir>/<stem>.result.png
    std::string reference;  ///< <failureDir>/<stem>.reference.png
    std::string diff;       ///< <failureDir>/<stem>.diff.png
};

/// The failure image paths for `resultPath`; stem = its file name without the extension.
[[nodiscard]] FailureImages failureImagePaths(const std::string& resultPath, const std::string& failureDir);

/// Loads both PNGs and compares them. If the comparison fails and failureDir is not empty,
/// creates failureDir if needed and writes the three images of failureImagePaths() there
/// (re-encoded as 8-bit RGBA). Errors: a file that cannot be loaded, a failure image that
/// cannot be written, or a failure image path that is one of the inputs (BadInput; a
/// reference image must never be overwritten).
[[nodiscard]] Result<CompareReport> compareFiles(const std::string& resultPath, const std::string& referencePath,
                                                 const CompareOptions& options, const std::string& failureDir);

}  // namespace throng::imagecmp
