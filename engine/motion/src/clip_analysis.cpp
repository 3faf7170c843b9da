#include "throng/motion/clip_analysis.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace throng::motion {
namespace {
constexpr double kTypicalHumanHeight = 1.7;  // metres
// Joint distances the gait and loop searches may compute for one clip: they sample frames
// (and lags) so that long clips, high frame rates and wide skeletons all stay within it,
// which keeps baking linear in the clip's size. Ordinary clips (up to ~100 joints, 2400
// travelling frames, 280 fps) are searched exhaustively as before.
constexpr double kComparisonBudget = 2.88e8;
constexpr int kMaxLags = 512;  // lags tried per gait search before sampling them
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
    const int half = std::max(1, clampedFloor(0.25 / frameTime + 0.5, 0, std::max(frames, 1)));  // lround, bounded by the clip
    std::vector<double> speed(ground.size(), 0.0);
    for (int f = firstFrame; f < frames; ++f) {
        const int lo = std::max(firstFrame, f - half), hi = std::min(frames - 1, f + half);
        if (hi > lo)
            speed[static_cast<std::size_t>(f)] =
                glm::length(ground[static_cast<std::size_t>(hi)] - ground[static_cast<std::size_t>(lo)]) / ((hi - lo) * frameTime);
        mask.topSpeed = std::max(mask.topSpeed, speed[static_cast<std::size_t>(f)]);
    }
    // Locomotion travels on: over three seconds (or the whole clip, when shorter) a slow walk
    // still makes 0.3 m/s, while a dancer's bursts of 0.3 m/s come and go and add up to less.
    const int sustain = std::max(1, clampedFloor(1.5 / frameTime + 0.5, 0, std::max(frames, 1)));
    double sustained = 0.0;
    for (int f = firstFrame; f < frames; ++f) {
        const int lo = std::max(firstFrame, f - sustain), hi = std::min(frames - 1, f + sustain);
        if (hi > lo)
            sustained = std::max(sustained, glm::length(ground[static_cast<std::size_t>(hi)] - ground[static_cast<std::size_t>(lo)]) /
                                                ((hi - lo) * frameTime));
    }
    mask.locomotion = sustained >= 0.2;
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
    const int minLag = std::max(2, clampedFloor(std::ceil(0.35 / frameTime), 0, poses.frames));
    const int maxLag = std::min(clampedFloor(1.8 / frameTime, 0, poses.frames), usable - 2);
    if (maxLag <= minLag) return 0.0;
    // Lags are sampled at very high frame rates (and refined below); start frames are sampled
    // so that lags × starts × joints stays within the budget, which keeps this linear in frames.
    const int lagStep = std::max(1, (maxLag - minLag + 1) / kMaxLags);
    const double lagsTried = (maxLag - minLag) / lagStep + 1.0;
    const int starts = std::clamp(static_cast<int>(kComparisonBudget / (lagsTried * std::max(poses.joints, 1))), 16, 400);
    const int stride = std::max(1, usable / starts);
    const auto meanAt = [&](int lag) {  // -1 when no pair of travelling frames is that far apart
        double sum = 0;
        int count = 0;
        for (int i = firstFrame; i + lag < poses.frames; i += stride)
            if (isMoving(i) && isMoving(i + lag)) {
                sum += poseDistance(poses, i, i + lag);
                ++count;
            }
        return count == 0 ? -1.0 : sum / count;
    };
    std::vector<double> meanAtLag(static_cast<std::size_t>(maxLag + 1), 0.0);
    double largest = 0, smallest = 1e300;
    for (int lag = minLag; lag <= maxLag; lag += lagStep) {
        meanAtLag[static_cast<std::size_t>(lag)] = meanAt(lag);
        if (meanAtLag[static_cast<std::size_t>(lag)] < 0) return 0.0;
        largest = std::max(largest, meanAtLag[static_cast<std::size_t>(lag)]);
        smallest = std::min(smallest, meanAtLag[static_cast<std::size_t>(lag)]);
    }
    if (!(smallest < 0.6 * largest)) return 0.0;  // no clear repetition: not locomotion
    // The first local minimum close to the global one is the period; later ones are its multiples.
    for (int lag = minLag; lag <= maxLag; lag += lagStep) {
        const double value = meanAtLag[static_cast<std::size_t>(lag)];
        const bool localMinimum = (lag == minLag || value <= meanAtLag[static_cast<std::size_t>(lag - lagStep)]) &&
                                  (lag + lagStep > maxLag || value <= meanAtLag[static_cast<std::size_t>(lag + lagStep)]);
        if (!localMinimum || value > 1.2 * smallest) continue;
        // A minimum at the search's lower bound is no period found: the curve may still be
        // falling (a pirouette's fast spin), and the bound would pin a cycle that isn't there.
        if (lag == minLag) return 0.0;
        int best = lag;  // between sampled lags (none when every lag was tried), the best single one
        double bestValue = value;
        for (int near = std::max(minLag, lag - lagStep + 1); near < std::min(maxLag + 1, lag + lagStep); ++near) {
            const double mean = near == lag ? -1.0 : meanAt(near);
            if (mean >= 0 && mean < bestValue) {
                best = near;
                bestValue = mean;
            }
        }
        return best;
    }
    return 0.0;
}

namespace {

// Where a loop may end: for a start frame f, the loop [f, j] must not contain a still frame
// up to j + 1 (its velocity is compared too), so j + 1 < end[f], the first still frame >= f.
std::vector<int> travellingRunEnds(const PoseSeries& poses, int firstFrame, const TravelMask& mask) {
    std::vector<int> end(static_cast<std::size_t>(poses.frames) + 1, poses.frames);
    for (int f = poses.frames - 1; f >= 0; --f)
        end[static_cast<std::size_t>(f)] =
            f >= firstFrame && mask.moving[static_cast<std::size_t>(f)] == 0 ? f : end[static_cast<std::size_t>(f) + 1];
    return end;
}

// The search for the best loop: pose costs of frame pairs inside travelling runs.
struct LoopSearch {
    const PoseSeries& poses;
    std::vector<int> runEnd;
    int firstFrame, lastCandidate, minGap;
    double best = 1e300;
    LoopRange bestRange;

    [[nodiscard]] int lastEnd(int i) const { return std::min(lastCandidate, runEnd[static_cast<std::size_t>(i)] - 2); }
    [[nodiscard]] bool valid(int i, int j) const { return i >= firstFrame && j >= i + minGap && j <= lastEnd(i); }
    // Matching the next frames too compares velocities, so a foot going up never joins one
    // coming down.
    [[nodiscard]] double cost(int i, int j) const { return poseDistance(poses, i, j) + poseDistance(poses, i + 1, j + 1); }
    void consider(int i, int j) {
        const double c = cost(i, j);
        if (c < best) {
            best = c;
            bestRange = {i, j};
        }
    }
    // Every `stride`-th pair over the clip: at most (usable / stride)² / 2 pairs.
    void scan(int stride) {
        for (int i = firstFrame; i + minGap <= lastCandidate; i += stride)
            for (int j = i + minGap; j <= lastEnd(i); j += stride) consider(i, j);
    }
    // Around the coarse answer: every pair within `stride`, when that fits the budget, else
    // coarse to fine, halving the step around the best pair.
    void refine(int stride) {
        const LoopRange coarse = bestRange;
        const double pairs = (2.0 * stride + 1) * (2.0 * stride + 1);
        if (pairs * 2.0 * poses.joints <= kComparisonBudget) {
            for (int i = std::max(firstFrame, coarse.first - stride); i <= coarse.first + stride; ++i)
                for (int j = std::max(i + minGap, coarse.last - stride); j <= std::min(lastEnd(i), coarse.last + stride); ++j)
                    consider(i, j);
            return;
        }
        for (int step = stride; step >= 1; step /= 2) {
            const LoopRange centre = bestRange;
            for (int di = -2; di <= 2; ++di)
                for (int dj = -2; dj <= 2; ++dj)
                    if (valid(centre.first + di * step, centre.last + dj * step)) consider(centre.first + di * step, centre.last + dj * step);
        }
    }
};

}  // namespace

LoopRange detectLoop(const PoseSeries& poses, double gaitPeriod, int firstFrame, const TravelMask& mask) {
    const int lastCandidate = poses.frames - 2;  // j + 1 must exist to compare velocities
    int usable = 0;
    for (int f = firstFrame; f < poses.frames; ++f) usable += mask.moving[static_cast<std::size_t>(f)] != 0 ? 1 : 0;
    // Without a gait the loop is the longest good match: over half the clip when it is not
    // locomotion (a dance repeats best over most of its length), a third when it travels.
    const int minGap = gaitPeriod > 0       ? std::max(2, clampedFloor(0.9 * gaitPeriod, 0, poses.frames))
                       : mask.locomotion ? std::max(2, usable / 3)
                                         : std::max(2, usable / 2 + 1);
    const LoopRange whole{firstFrame, std::max(firstFrame, poses.frames - 1)};
    if (lastCandidate - firstFrame < minGap || usable < minGap + 2) return whole;

    // A loop lies wholly in one travelling run, so only pairs inside runs are compared, and
    // sampling every `stride`-th frame bounds the pairs (fewer samples for wide skeletons).
    LoopSearch search{poses, travellingRunEnds(poses, firstFrame, mask), firstFrame, lastCandidate, minGap, 1e300, whole};
    const int samples = std::clamp(static_cast<int>(std::sqrt(kComparisonBudget / (2.0 * std::max(poses.joints, 1)))), 32, 1200);
    const int stride = std::max(1, usable / samples);
    search.scan(stride);
    if (stride > 1) {
        search.refine(stride);
        return search.bestRange;
    }
    // Among near-ties prefer the longest loop: more of the capture, less visible repetition.
    // A seam difference under a tenth of the clip's typical frame step cannot be seen.
    std::vector<double> steps;
    for (int f = firstFrame; f + 1 < poses.frames; ++f) steps.push_back(poseDistance(poses, f, f + 1));
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
    const double acceptable = std::max(search.best * 1.25, search.best + 0.1 * steps[steps.size() / 2]);
    LoopRange bestRange = search.bestRange;
    for (int i = firstFrame; i + minGap <= lastCandidate; ++i)
        for (int j = search.lastEnd(i); j >= i + std::max(minGap, bestRange.length() + 1); --j)
            if (search.cost(i, j) <= acceptable) {
                bestRange = {i, j};
                break;
            }
    return bestRange;
}

}  // namespace throng::motion
