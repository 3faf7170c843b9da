#include "image_compare.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>

#include "throng/core/atomic_file.h"

// stb is third-party C written for looser warning settings than ours; silence it here only.
// The STATIC variants keep every stb symbol private to this file, so another module that
// also compiles stb (or links Debian's libstb) cannot collide with us at link time.
// PNG only and no stdio: we read files ourselves (better errors) and write atomically.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wpedantic"
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace throng::imagecmp {
namespace {

bool wellFormed(const Image& image) {
    return image.width >= 0 && image.height >= 0 &&
           image.rgba.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
}

bool contains(const Image& image, int x, int y) { return x >= 0 && y >= 0 && x < image.width && y < image.height; }

const std::uint8_t* pixel(const Image& image, int x, int y) {
    return image.rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + x) * 4;
}

int channelDistance(const std::uint8_t* a, const std::uint8_t* b) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int{a[c]} - int{b[c]}));
    return worst;
}

// True if `value` is within tolerance of some pixel of `other` in the 3x3 block around (x, y).
bool matchedNearby(const std::uint8_t* value, const Image& other, int x, int y, int tolerance) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (contains(other, x + dx, y + dy) && channelDistance(value, pixel(other, x + dx, y + dy)) <= tolerance)
                return true;
    return false;
}

struct Verdict {
    bool inBoth = false;  // the position exists in both images
    bool differs = false;
    int distance = 0;  // same-position channel distance; 0 when not inBoth
};

// The one place that decides about a pixel, so compare() and diffImage() cannot disagree.
Verdict classify(const Image& result, const Image& reference, int x, int y, int tolerance, bool shift) {
    Verdict v;
    v.inBoth = contains(result, x, y) && contains(reference, x, y);
    if (!v.inBoth) {
        v.differs = true;
        return v;
    }
    const std::uint8_t* r = pixel(result, x, y);
    const std::uint8_t* g = pixel(reference, x, y);
    v.distance = channelDistance(r, g);
    v.differs = v.distance > tolerance &&
                !(shift && matchedNearby(r, reference, x, y, tolerance) && matchedNearby(g, result, x, y, tolerance));
    return v;
}

int clampedTolerance(const CompareOptions& options) { return std::clamp(options.channelTolerance, 0, 255); }

Error badFile(const std::string& path, const std::string& message) {
    return Error{Error::Kind::BadInput, message, {path, 0, 0}};
}

void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

Result<Image> loadPng(const std::string& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) return badFile(path, "cannot open PNG file: no such file");
    if (std::filesystem::is_directory(status)) return badFile(path, "cannot read PNG file: it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) return badFile(path, "cannot open PNG file: permission denied or unreadable");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return badFile(path, "cannot read PNG file: read failed");
    // stb takes the length as an int.
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return badFile(path, "PNG file is too large to decode (over 2 GiB)");

    int width = 0, height = 0, channels = 0;
    stbi_uc* decoded = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                             static_cast<int>(bytes.size()), &width, &height, &channels, 4);
    if (decoded == nullptr)
        return badFile(path, std::string("not a valid PNG image (") + stbi_failure_reason() + ")");
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(decoded, decoded + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(decoded);
    return image;
}

Result<bool> savePng(const std::string& path, const Image& image) {
    if (!wellFormed(image) || image.width == 0 || image.height == 0)
        return badFile(path, "cannot write an empty or malformed image as PNG");
    // Encode into memory first so the file itself can be written atomically.
    std::string bytes;
    if (stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4, image.rgba.data(),
                               image.width * 4) == 0)
        return Error{Error::Kind::Runtime, "PNG encoding failed", {path, 0, 0}};
    return writeFileAtomically(path, bytes);
}

bool neighbourShiftEnabled(const CompareOptions& options) {
    if (options.allowNeighbourShift) return *options.allowNeighbourShift;
    return options.channelTolerance > 0 || options.maxDifferingFraction > 0.0;
}

CompareReport compare(const Image& result, const Image& reference, const CompareOptions& options) {
    CompareReport report;
    report.width = result.width;
    report.height = result.height;
    report.referenceWidth = reference.width;
    report.referenceHeight = reference.height;
    if (!wellFormed(result) || !wellFormed(reference)) return report;
    report.sameSize = result.width == reference.width && result.height == reference.height;

    const int tolerance = clampedTolerance(options);
    const bool shift = neighbourShiftEnabled(options);
    const int width = std::max(result.width, reference.width);
    const int height = std::max(result.height, reference.height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Verdict v = classify(result, reference, x, y, tolerance, shift);
            report.maxChannelDifference = std::max(report.maxChannelDifference, v.distance);
            if (v.differs) ++report.differingPixels;
        }
    const auto total = static_cast<double>(width) * static_cast<double>(height);
    report.differingFraction = total > 0 ? static_cast<double>(report.differingPixels) / total : 0.0;
    // Compare counts rather than fractions, with a little slack, so that a limit written as
    // k/N admits exactly k pixels despite rounding in the division.
    const double allowed = std::max(options.maxDifferingFraction, 0.0) * total;
    report.passed = report.sameSize && static_cast<double>(report.differingPixels) <= allowed + 1e-6;
    return report;
}

Image diffImage(const Image& result, const Image& reference, const CompareOptions& options) {
    Image out;
    if (!wellFormed(result) || !wellFormed(reference)) return out;
    out.width = std::max(result.width, reference.width);
    out.height = std::max(result.height, reference.height);
    out.rgba.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);

    const int tolerance = clampedTolerance(options);
    const bool shift = neighbourShiftEnabled(options);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const Verdict v = classify(result, reference, x, y, tolerance, shift);
            std::uint8_t* o = out.rgba.data() + (static_cast<std::size_t>(y) * out.width + x) * 4;
            if (!v.inBoth) {
                o[0] = 255, o[1] = 0, o[2] = 255;
            } else if (v.differs) {
                const int red = std::clamp(v.distance * 8, 128, 255);
                o[0] = static_cast<std::uint8_t>(red), o[1] = 0, o[2] = static_cast<std::uint8_t>(red / 2);
            } else {
                // Integer Rec. 601 luma; a quarter of it keeps the picture readable but dark,
                // so the red marks stand out.
                const std::uint8_t* g = pixel(reference, x, y);
                const int luma = (77 * g[0] + 150 * g[1] + 29 * g[2]) >> 8;
                o[0] = o[1] = o[2] = static_cast<std::uint8_t>(luma / 4);
            }
            o[3] = 255;
        }
    return out;
}

FailureImages failureImagePaths(const std::string& resultPath, const std::string& failureDir) {
    const std::filesystem::path dir(failureDir);
    const std::string stem = std::filesystem::path(resultPath).stem().string();
    return {(dir / (stem + ".result.png")).string(), (dir / (stem + ".reference.png")).string(),
            (dir / (stem + ".diff.png")).string()};
}

Result<CompareReport> compareFiles(const std::string& resultPath, const std::string& referencePath,
                                   const CompareOptions& options, const std::string& failureDir) {
    Result<Image> result = loadPng(resultPath);
    if (!result) return result.error();
    Result<Image> reference = loadPng(referencePath);
    if (!reference) return reference.error();
    const CompareReport report = compare(result.value(), reference.value(), options);
    if (report.passed || failureDir.empty()) return report;

    std::error_code ec;
    std::filesystem::create_directories(failureDir, ec);
    if (ec)
        return Error{Error::Kind::Runtime, "cannot create failure directory: " + ec.message(), {failureDir, 0, 0}};

    const FailureImages paths = failureImagePaths(resultPath, failureDir);
    // Writing next to the inputs is allowed, but never over one of them: the reference is the
    // ground truth, and re-encoding it as 8-bit RGBA could lose information.
    for (const std::string* out : {&paths.result, &paths.reference, &paths.diff})
        for (const std::string* in : {&resultPath, &referencePath})
            if (std::filesystem::equivalent(*out, *in, ec))
                return badFile(*out, "failure image would overwrite input " + *in + "; choose another failure directory");

    const Image diff = diffImage(result.value(), reference.value(), options);
    using Output = std::pair<const std::string*, const Image*>;
    for (const Output& out : {Output{&paths.result, &result.value()}, Output{&paths.reference, &reference.value()},
                              Output{&paths.diff, &diff}}) {
        const Result<bool> saved = savePng(*out.first, *out.second);
        if (!saved) return saved.error();
    }
    return report;
}

}  // namespace throng::imagecmp
