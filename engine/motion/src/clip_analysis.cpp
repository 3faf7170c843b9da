#include "throng/motion/clip_analysis.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace throng::motion {
namespace {
constexpr double kTypicalHumanHeight = 1.7;  // metres
}

UnitGuess guessUnits(double heightInFileUnits) {
    static constexpr UnitGuess kUnits[] = {
        {1.0, "metres"}, {0.01, "centimetres"}, {0.001, "millimetres"}, {0.0254, "inches"},
        {0.056444, "CMU units"},  // (1/0.45)·2.54/100, from the CMU mocap FAQ
    };
    if (!(heightInFileUnits > 0)) return kUnits[0];
    UnitGuess best = kUnits[0];
    double bestScore = 1e300;
    for (const UnitGuess& unit : kUnits) {
        // Compare ratios, not differences: a factor of two off is equally wrong either way.
        const double score = std::abs(std::log(heightInFileUnits * unit.metresPerUnit / kTypicalHumanHeight));
        if (score < bestScore) {
            bestScore = score;
            best = unit;
        }
    }
    return best;
}

double poseDistance(const PoseSeries& poses, int a, int b) {
    const auto pa = poses.frame(a), pb = poses.frame(b);
    double sum = 0;
    for (int j = 0; j < poses.joints; ++j) {
        const glm::vec3 d = pa[static_cast<std::size_t>(j)] - pb[static_cast<std::size_t>(j)];
        sum += static_cast<double>(glm::dot(d, d));
    }
    return std::sqrt(sum / std::max(poses.joints, 1));
}

bool looksLikeSyntheticFirstFrame(const PoseSeries& poses) {
    if (poses.frames < 4) return false;
    std::vector<double> steps;
    for (int f = 1; f + 1 < poses.frames; ++f) steps.push_back(poseDistance(poses, f, f + 1));
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
    const double median = steps[steps.size() / 2];
    const double firstStep = poseDistance(poses, 0, 1);
    // Captured motion moves a little each frame; a converter's rest pose jumps by an order
    // of magnitude more than that. 8x the median step separates the two on every file seen.
    return firstStep > 8.0 * median && firstStep > 1e-4;
}

TravelMask travelMask(std::span<const glm::dvec2> ground, double frameTime, int firstFrame) {
    const int frames = static_cast<int>(ground.size());
    TravelMask mask;
    mask.moving.assign(ground.size(), 0);
    const int half = std::max(1, static_cast<int>(std::lround(0.25 / frameTime)));
    std::vector<double> speed(ground.size(), 0.0);
    for (int f = firstFrame; f < frames; ++f) {
        const int lo = std::max(firstFrame, f - half), hi = std::min(frames - 1, f + half);
        if (hi > lo)
            speed[static_cast<std::size_t>(f)] =
                glm::length(ground[static_cast<std::size_t>(hi)] - ground[static_cast<std::size_t>(lo)]) / ((hi - lo) * frameTime);
        mask.topSpeed = std::max(mask.topSpeed, speed[static_cast<std::size_t>(f)]);
    }
    mask.locomotion = mask.topSpeed >= 0.5;  // a slow walk is ~0.8 m/s; swaying in place stays below
    for (int f = firstFrame; f < frames; ++f)
        mask.moving[static_cast<std::size_t>(f)] =
            !mask.locomotion || speed[static_cast<std::size_t>(f)] >= 0.5 * mask.topSpeed ? 1 : 0;
    return mask;
}

double estimateGaitPeriod(const PoseSeries& poses, double frameTime, const TravelMask& mask) {
    if (!mask.locomotion) return 0.0;
    const auto isMoving = [&](int f) { return mask.moving[static_cast<std::size_t>(f)] != 0; };
    int firstFrame = 0;
    while (firstFrame < poses.frames && !isMoving(firstFrame)) ++firstFrame;
    int usable = 0;
    for (int f = 0; f < poses.frames; ++f) usable += isMoving(f) ? 1 : 0;
    const int minLag = std::max(2, static_cast<int>(std::ceil(0.35 / frameTime)));
    const int maxLag = std::min(static_cast<int>(std::floor(1.8 / frameTime)), usable - 2);
    if (maxLag <= minLag) return 0.0;
    // Sampling every `stride` start frames keeps this linear-ish on long clips.
    const int stride = std::max(1, usable / 400);
    std::vector<double> meanAtLag(static_cast<std::size_t>(maxLag + 1), 0.0);
    double largest = 0;
    for (int lag = minLag; lag <= maxLag; ++lag) {
        double sum = 0;
        int count = 0;
        for (int i = firstFrame; i + lag < poses.frames; i += stride)
            if (isMoving(i) && isMoving(i + lag)) {
                sum += poseDistance(poses, i, i + lag);
                ++count;
            }
        if (count == 0) return 0.0;
        meanAtLag[static_cast<std::size_t>(lag)] = sum / std::max(count, 1);
        largest = std::max(largest, meanAtLag[static_cast<std::size_t>(lag)]);
    }
    const auto begin = meanAtLag.begin() + minLag;
    const double smallest = *std::min_element(begin, meanAtLag.end());
    if (!(smallest < 0.6 * largest)) return 0.0;  // no clear repetition: not locomotion
    // The first local minimum close to the global one is the period; later ones are its multiples.
    for (int lag = minLag; lag <= maxLag; ++lag) {
        const double value = meanAtLag[static_cast<std::size_t>(lag)];
        const bool localMinimum = (lag == minLag || value <= meanAtLag[static_cast<std::size_t>(lag - 1)]) &&
                                  (lag == maxLag || value <= meanAtLag[static_cast<std::size_t>(lag + 1)]);
        if (localMinimum && value <= 1.2 * smallest) return lag;
    }
    return 0.0;
}

LoopRange detectLoop(const PoseSeries& poses, double gaitPeriod, int firstFrame, const TravelMask& mask) {
    const int lastCandidate = poses.frames - 2;  // j + 1 must exist to compare velocities
    // A loop must lie wholly in the travelling part: count still frames before each frame.
    std::vector<int> stillBefore(static_cast<std::size_t>(poses.frames) + 1, 0);
    for (int f = 0; f < poses.frames; ++f)
        stillBefore[static_cast<std::size_t>(f) + 1] = stillBefore[static_cast<std::size_t>(f)] +
                                                        (f >= firstFrame && mask.moving[static_cast<std::size_t>(f)] == 0 ? 1 : 0);
    const auto travels = [&](int i, int j) {
        return stillBefore[static_cast<std::size_t>(j) + 2] == stillBefore[static_cast<std::size_t>(i)];
    };
    int usable = 0;
    for (int f = firstFrame; f < poses.frames; ++f) usable += mask.moving[static_cast<std::size_t>(f)] != 0 ? 1 : 0;
    const int minGap = gaitPeriod > 0 ? std::max(2, static_cast<int>(std::floor(0.9 * gaitPeriod)))
                                      : std::max(2, usable / 3);
    const LoopRange whole{firstFrame, std::max(firstFrame, poses.frames - 1)};
    if (lastCandidate - firstFrame < minGap || usable < minGap + 2) return whole;

    // Matching the next frames too compares velocities, so a foot going up never joins one
    // coming down.
    auto cost = [&](int i, int j) {
        return travels(i, j) ? poseDistance(poses, i, j) + poseDistance(poses, i + 1, j + 1) : 1e300;
    };
    const int stride = std::max(1, usable / 1200);  // bounds the O(n²) scan on very long clips
    double best = 1e300;
    LoopRange bestRange = whole;
    for (int i = firstFrame; i + minGap <= lastCandidate; i += stride)
        for (int j = i + minGap; j <= lastCandidate; j += stride) {
            const double c = cost(i, j);
            if (c < best) {
                best = c;
                bestRange = {i, j};
            }
        }
    if (stride > 1) {  // refine around the coarse answer
        const LoopRange coarse = bestRange;
        for (int i = std::max(firstFrame, coarse.first - stride); i <= coarse.first + stride; ++i)
            for (int j = std::max(i + minGap, coarse.last - stride); j <= std::min(lastCandidate, coarse.last + stride); ++j) {
                const double c = cost(i, j);
                if (c < best) {
                    best = c;
                    bestRange = {i, j};
                }
            }
        return bestRange;
    }
    // Among near-ties prefer the longest loop: more of the capture, less visible repetition.
    // A seam difference under a tenth of the clip's typical frame step cannot be seen.
    std::vector<double> steps;
    for (int f = firstFrame; f + 1 < poses.frames; ++f) steps.push_back(poseDistance(poses, f, f + 1));
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
    const double acceptable = std::max(best * 1.25, best + 0.1 * steps[steps.size() / 2]);
    for (int i = firstFrame; i + minGap <= lastCandidate; ++i)
        for (int j = lastCandidate; j >= i + std::max(minGap, bestRange.length() + 1); --j)
            if (cost(i, j) <= acceptable) {
                bestRange = {i, j};
                break;
            }
    return bestRange;
}

}  // namespace throng::motion
