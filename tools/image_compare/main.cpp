// image_compare: the command-line face of the image-regression comparison, for scripts and
// ctest. Exit codes: 0 match, 1 differ (or size mismatch), 2 usage error or unusable file.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "image_compare.h"

namespace {

namespace ic = throng::imagecmp;

constexpr int kExitPass = 0;
constexpr int kExitDiffer = 1;
constexpr int kExitUsage = 2;

void printUsage(std::FILE* to) {
    std::fputs(
        "usage: image_compare RESULT.png REFERENCE.png [--exact | --tolerance N --max-fraction F]\n"
        "                     [--failure-dir DIR]\n"
        "\n"
        "Compares a rendered image with its reference.\n"
        "  --exact            every channel of every pixel must be equal (the default)\n"
        "  --tolerance N      a channel may differ by up to N (0..255)\n"
        "  --max-fraction F   up to this fraction (0..1) of pixels may differ\n"
        "                     (either fuzzy option also forgives one-pixel edge shifts: a pixel\n"
        "                     matched by a 3x3 neighbour in the other image, both ways)\n"
        "  --failure-dir DIR  where to write <stem>.result/.reference/.diff.png on failure\n"
        "                     (default: the directory holding RESULT)\n"
        "Exit status: 0 match, 1 differ or size mismatch, 2 usage error, unreadable file,\n"
        "or failure images that could not be written.\n",
        to);
}

int usageError(const std::string& message) {
    std::fprintf(stderr, "image_compare: error: %s (see --help)\n", message.c_str());
    return kExitUsage;
}

template <typename T>
bool parseNumber(std::string_view text, T& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

struct Arguments {
    std::vector<std::string> files;
    ic::CompareOptions options;
    std::string failureDir;
    bool failureDirGiven = false;
    bool help = false;
};

// Returns an empty string on success, else the usage error.
std::string parseArguments(int argc, char** argv, Arguments& args) {
    bool exact = false, fuzzy = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        const auto needValue = [&](std::string_view& value) {
            if (i + 1 >= argc) return false;
            value = argv[++i];
            return true;
        };
        std::string_view value;
        if (arg == "--help" || arg == "-h") {
            args.help = true;
        } else if (arg == "--exact") {
            exact = true;
        } else if (arg == "--tolerance") {
            if (!needValue(value)) return "--tolerance needs a value";
            if (!parseNumber(value, args.options.channelTolerance) || args.options.channelTolerance < 0 ||
                args.options.channelTolerance > 255)
                return "--tolerance must be an integer from 0 to 255, got '" + std::string(value) + "'";
            fuzzy = true;
        } else if (arg == "--max-fraction") {
            if (!needValue(value)) return "--max-fraction needs a value";
            double& f = args.options.maxDifferingFraction;
            if (!parseNumber(value, f) || !std::isfinite(f) || f < 0.0 || f > 1.0)
                return "--max-fraction must be a number from 0 to 1, got '" + std::string(value) + "'";
            fuzzy = true;
        } else if (arg == "--failure-dir") {
            if (!needValue(value)) return "--failure-dir needs a directory";
            if (value.empty()) return "--failure-dir must not be empty";
            args.failureDir = value;
            args.failureDirGiven = true;
        } else if (arg.size() > 1 && arg[0] == '-') {
            return "unknown option '" + std::string(arg) + "'";
        } else {
            args.files.emplace_back(arg);
        }
    }
    if (args.help) return {};
    if (exact && fuzzy) return "--exact cannot be combined with --tolerance or --max-fraction";
    if (args.files.size() != 2) return "expected RESULT.png and REFERENCE.png";
    if (!args.failureDirGiven) {
        // parent_path of a bare file name is empty; the failure images then go to ".".
        const std::filesystem::path parent = std::filesystem::path(args.files[0]).parent_path();
        args.failureDir = parent.empty() ? std::string(".") : parent.string();
    }
    return {};
}

}  // namespace

int main(int argc, char** argv) {
    Arguments args;
    if (const std::string problem = parseArguments(argc, argv, args); !problem.empty()) return usageError(problem);
    if (args.help) {
        printUsage(stdout);
        return kExitPass;
    }
    const std::string& resultPath = args.files[0];
    const std::string& referencePath = args.files[1];

    const throng::Result<ic::CompareReport> compared =
        ic::compareFiles(resultPath, referencePath, args.options, args.failureDir);
    if (!compared) {
        std::fprintf(stderr, "image_compare: %s\n", compared.error().describe().c_str());
        return kExitUsage;
    }
    const ic::CompareReport& report = compared.value();
    std::string size = std::to_string(report.width) + "x" + std::to_string(report.height);
    if (!report.sameSize)
        size += " reference_size=" + std::to_string(report.referenceWidth) + "x" +
                std::to_string(report.referenceHeight);
    std::printf("image_compare: %s result=%s reference=%s size=%s differing=%lld (%.4f%%) max_channel_diff=%d\n",
                report.passed ? "PASS" : "FAIL", resultPath.c_str(), referencePath.c_str(), size.c_str(),
                static_cast<long long>(report.differingPixels), report.differingFraction * 100.0,
                report.maxChannelDifference);
    if (report.passed) return kExitPass;

    const ic::FailureImages written = ic::failureImagePaths(resultPath, args.failureDir);
    std::printf("image_compare: wrote %s\nimage_compare: wrote %s\nimage_compare: wrote %s\n", written.result.c_str(),
                written.reference.c_str(), written.diff.c_str());
    return kExitDiffer;
}
