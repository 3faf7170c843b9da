#include "playback_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "throng/crowd/character_state.h"
#include "throng/motion/forward_kinematics.h"

namespace throng::quality {
namespace {

// The rotation that takes the file's up axis to +Y (right-handed, so a Z-up file's +Y, its
// forward, becomes −Z, as Blender's BVH import does).
glm::dvec3 toYUp(glm::dvec3 p, motion::UpAxis up) {
    switch (up) {
        case motion::UpAxis::PlusY: return p;
        case motion::UpAxis::MinusY: return {p.x, -p.y, -p.z};
        case motion::UpAxis::PlusZ: return {p.x, p.z, -p.y};
        case motion::UpAxis::MinusZ: return {p.x, -p.z, p.y};
        case motion::UpAxis::PlusX: return {-p.y, p.x, p.z};
        case motion::UpAxis::MinusX: return {p.y, -p.x, p.z};
    }
    return p;
}

double horizontal(glm::dvec3 a, glm::dvec3 b) { return std::hypot(a.x - b.x, a.z - b.z); }

// Inclusive frame range [first, last] clamped to `frames`; last < 0 means the end.
std::pair<int, int> frameRange(int frames, int first, int last) {
    const int lo = std::clamp(first, 0, std::max(frames - 1, 0));
    const int hi = last < 0 ? frames - 1 : std::clamp(last, lo, std::max(frames - 1, 0));
    return {lo, hi};
}

double quantileOf(std::vector<double> values, double quantile) {
    if (values.empty()) return 0.0;
    const auto index = static_cast<std::size_t>(std::clamp(quantile, 0.0, 1.0) * static_cast<double>(values.size() - 1) + 0.5);
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(index);
    std::nth_element(values.begin(), at, values.end());
    return *at;
}

// Keeps only runs of two or more planted frames: a single frame that passes the test is a
// foot passing through it, not a contact.
void dropSingleFrames(std::vector<char>& planted) {
    std::vector<char> kept = planted;
    for (std::size_t f = 0; f < planted.size(); ++f) {
        const bool before = f > 0 && planted[f - 1] != 0, after = f + 1 < planted.size() && planted[f + 1] != 0;
        if (!before && !after) kept[f] = 0;
    }
    planted = std::move(kept);
}

}  // namespace

std::vector<glm::dvec3> PointSeries::track(int point, int first, int last) const {
    const auto [lo, hi] = frameRange(frames, first, last);
    std::vector<glm::dvec3> out;
    for (int f = lo; f <= hi && frames > 0; ++f) out.push_back(at(f, point));
    return out;
}

PointSeries rawWorldPositions(const motion::RawMotion& motion, double metresPerUnit, motion::UpAxis up, bool endSites) {
    PointSeries out;
    out.frames = motion.frameCount;
    out.joints = motion.jointCount();
    out.points = out.joints + (endSites ? static_cast<int>(motion.endSites.size()) : 0);
    out.frameTime = motion.frameTime;
    out.parents = motion::parentIndices(motion);
    if (endSites)
        for (const motion::RawEndSite& site : motion.endSites) out.parents.push_back(site.parent);
    out.positions.reserve(static_cast<std::size_t>(out.frames) * static_cast<std::size_t>(out.points));
    for (int f = 0; f < motion.frameCount; ++f) {
        const std::vector<glm::dmat4> globals = motion::globalTransforms(motion, f, motion::PositionChannels::Replace);
        for (const glm::dmat4& g : globals) out.positions.push_back(toYUp(glm::dvec3(g[3]) * metresPerUnit, up));
        if (!endSites) continue;
        for (const motion::RawEndSite& site : motion.endSites) {
            const glm::dvec3 p(globals[static_cast<std::size_t>(site.parent)] * glm::dvec4(site.offset, 1.0));
            out.positions.push_back(toYUp(p * metresPerUnit, up));
        }
    }
    return out;
}

PointSeries withoutEndSites(const PointSeries& points) {
    PointSeries out{points.frames, points.joints, points.joints, points.frameTime, points.parents, {}};
    out.parents.resize(static_cast<std::size_t>(points.joints));
    out.positions.reserve(static_cast<std::size_t>(points.frames) * static_cast<std::size_t>(points.joints));
    for (int f = 0; f < points.frames; ++f)
        for (int j = 0; j < points.joints; ++j) out.positions.push_back(points.at(f, j));
    return out;
}

PointSeries bakedInPlacePositions(const motion::BakedClip& clip) {
    PointSeries out{clip.frameCount, clip.jointCount(), clip.jointCount(), clip.frameTime, clip.parents, {}};
    out.positions.reserve(clip.poses.size());
    for (const motion::JointPose& pose : clip.poses) out.positions.emplace_back(pose.translation);
    return out;
}

Result<Playback> playback(const motion::BakedClip& clip, crowd::Mode mode, double seconds, double dt, bool turning) {
    crowd::GroupSpec group;
    group.count = 1;
    group.clips = {0};
    group.region = {{0.0F, 0.0F}, {0.5F, 0.5F}};
    group.mode = mode;
    crowd::CrowdSetup setup;
    setup.groups = {group};
    setup.seed = 1;
    setup.threads = 1;  // one character: threads would only cost start-up time
    if (mode != crowd::Mode::Group) {
        // Waypoints, not random goals, so the course is the same for every clip: corners of a
        // square force 90° turns; two far points give a walk that never arrives, so never turns.
        setup.waypoints = turning ? std::vector<glm::vec2>{{3, 3}, {-3, 3}, {-3, -3}, {3, -3}}
                                  : std::vector<glm::vec2>{{0, 500}, {0, -500}};
    }
    const std::span<const motion::BakedClip> clips(&clip, 1);
    auto spawned = crowd::Crowd::spawn(clips, setup);
    if (!spawned) return spawned.error();
    crowd::Crowd& crowd = spawned.value();
    if (!(dt > 0)) dt = clip.frameTime;
    const int steps = std::max(1, static_cast<int>(std::lround(seconds / dt)));
    Playback out;
    out.scale = crowd.scale(0);
    out.joints = {steps + 1, clip.jointCount(), clip.jointCount(), dt, clip.parents, {}};
    out.joints.positions.reserve(static_cast<std::size_t>(steps + 1) * static_cast<std::size_t>(clip.jointCount()));
    std::vector<crowd::CharacterState> state(1);
    for (int s = 0; s <= steps; ++s) {
        if (s > 0) crowd.step(clips, dt);
        crowd.pack(state);
        out.ground.push_back(crowd.groundFrame(0));
        out.clipFrames.push_back(crowd.frame(0));
        for (int j = 0; j < clip.jointCount(); ++j)
            out.joints.positions.emplace_back(crowd::sampleJointWorld(std::span(&clip, 1), state[0], j).position);
    }
    return out;
}

std::vector<char> plantedFrames(std::span<const glm::dvec3> foot, double frameTime, double stature, const ContactRule& rule) {
    std::vector<char> planted(foot.size(), 0);
    if (foot.size() < 2 || !(frameTime > 0)) return planted;
    std::vector<double> heights;
    heights.reserve(foot.size());
    for (const glm::dvec3& p : foot) heights.push_back(p.y);
    std::sort(heights.begin(), heights.end());
    // The 5th percentile rather than the minimum: one frame of a toe dipping through the
    // floor must not move the band for the whole sequence.
    const double floor = heights[static_cast<std::size_t>(0.05 * static_cast<double>(heights.size() - 1))];
    // Speed over about 50 ms: at 120 Hz a millimetre of marker noise reads as 12 cm/s between
    // neighbouring frames, which would split contacts; at 24-30 Hz it is one frame either side.
    const auto reach = static_cast<std::size_t>(std::max(1L, std::lround(0.025 / frameTime)));
    const std::size_t last = foot.size() - 1;
    for (std::size_t f = 0; f <= last; ++f) {
        const std::size_t a = f > reach ? f - reach : 0, b = std::min(last, f + reach);
        const double speed = horizontal(foot[b], foot[a]) / (static_cast<double>(b - a) * frameTime);
        planted[f] = foot[f].y - floor <= rule.band * stature && speed <= rule.speed * stature ? 1 : 0;
    }
    dropSingleFrames(planted);
    return planted;
}

std::vector<char> plantedAtClipFrames(std::span<const char> clipPlanted, std::span<const double> clipFrames) {
    std::vector<char> planted(clipFrames.size(), 0);
    if (clipPlanted.empty()) return planted;
    const int last = static_cast<int>(clipPlanted.size()) - 1;
    // The nearest clip frame decides, so a contact keeps the length it has in the capture and
    // the playback's speed sample covers the same frames as the capture's. (Asking both frames
    // around the position would trim a frame off each contact, where a foot moves most, and
    // make playback look steadier than the capture it plays.)
    for (std::size_t s = 0; s < clipFrames.size(); ++s)
        planted[s] = clipPlanted[static_cast<std::size_t>(clampedFloor(clipFrames[s] + 0.5, 0, last))];
    dropSingleFrames(planted);
    return planted;
}

std::vector<double> plantedSpeeds(std::span<const glm::dvec3> foot, double frameTime, std::span<const char> planted) {
    std::vector<double> speeds(foot.size(), std::numeric_limits<double>::quiet_NaN());
    if (planted.size() != foot.size() || !(frameTime > 0)) return speeds;
    for (std::size_t f = 1; f + 1 < foot.size(); ++f)
        if (planted[f - 1] != 0 && planted[f] != 0 && planted[f + 1] != 0)
            speeds[f] = horizontal(foot[f + 1], foot[f - 1]) / (2.0 * frameTime);
    return speeds;
}

Slide slideOver(std::span<const glm::dvec3> foot, double frameTime, std::span<const char> planted, std::span<const char> include) {
    Slide out;
    if (foot.size() < 3 || planted.size() != foot.size() || !(frameTime > 0)) return out;
    const std::vector<double> speeds = plantedSpeeds(foot, frameTime, planted);
    double speedSum = 0.0, contactPath = 0.0;
    for (std::size_t f = 0; f < foot.size(); ++f) {
        if (planted[f] == 0) continue;
        ++out.plantedFrames;
        if (f == 0 || planted[f - 1] == 0) ++out.contacts;
        else contactPath += horizontal(foot[f], foot[f - 1]);
        if (std::isnan(speeds[f]) || (!include.empty() && include[f] == 0)) continue;
        speedSum += speeds[f];
        ++out.measuredFrames;
    }
    if (out.measuredFrames > 0) out.cmPerSecond = 100.0 * speedSum / out.measuredFrames;
    if (out.contacts > 0) out.cmPerContact = 100.0 * contactPath / out.contacts;
    return out;
}

Slide plantedSlide(std::span<const glm::dvec3> foot, double frameTime, double stature, std::span<const char> include,
                   const ContactRule& rule) {
    return slideOver(foot, frameTime, plantedFrames(foot, frameTime, stature, rule), include);
}

BoneSpread boneLengthSpread(const PointSeries& points, double stature) {
    BoneSpread worst;
    for (int p = 0; p < points.points; ++p) {
        const int parent = points.parents[static_cast<std::size_t>(p)];
        if (parent < 0 || points.frames < 1) continue;
        double lo = 1e300, hi = 0.0, sum = 0.0;
        for (int f = 0; f < points.frames; ++f) {
            const double length = glm::length(points.at(f, p) - points.at(f, parent));
            lo = std::min(lo, length), hi = std::max(hi, length), sum += length;
        }
        if (worst.point < 0 || hi - lo > worst.metres) worst.metres = hi - lo, worst.point = p;
        // Zero-length links (CMU's hip and neck joints) and finger stubs would make any
        // rounding look like stretch; bones under 2% of stature are left out of the ratio.
        const double mean = sum / points.frames;
        if (mean >= 0.02 * stature && (worst.relativePoint < 0 || (hi - lo) / mean > worst.relative))
            worst.relative = (hi - lo) / mean, worst.relativePoint = p;
    }
    worst.fraction = stature > 0 ? worst.metres / stature : 0.0;
    return worst;
}

double arcSpeed(std::span<const glm::dvec2> path, double frameTime, int first, int last) {
    const int frames = static_cast<int>(path.size());
    const auto [lo, hi] = frameRange(frames, first, last);
    if (hi - lo < 1 || !(frameTime > 0)) return 0.0;
    // The pelvis sways sideways within each step; a one-second centred average keeps the
    // course and drops the sway, which would otherwise add path length a walk doesn't cover.
    // Near the ends the window shrinks on both sides alike: a one-sided window would lag the
    // path and shorten it (on a 1 s clip, by half).
    const int half = std::max(0, static_cast<int>(std::lround(0.5 / frameTime)));
    std::vector<glm::dvec2> prefix(path.size() + 1, glm::dvec2(0.0));
    for (std::size_t f = 0; f < path.size(); ++f) prefix[f + 1] = prefix[f] + path[f];
    const auto smoothed = [&](int f) {
        const int reach = std::min({half, f, frames - 1 - f});
        const int a = f - reach, b = f + reach;
        return (prefix[static_cast<std::size_t>(b) + 1] - prefix[static_cast<std::size_t>(a)]) / static_cast<double>(b - a + 1);
    };
    double length = 0.0;
    for (int f = lo + 1; f <= hi; ++f) length += glm::length(smoothed(f) - smoothed(f - 1));
    return length / ((hi - lo) * frameTime);
}

std::vector<glm::dvec2> groundPath(const PointSeries& points, int point, int first, int last) {
    std::vector<glm::dvec2> path;
    for (const glm::dvec3& p : points.track(point, first, last)) path.emplace_back(p.x, p.z);
    return path;
}

double measuredStature(const PointSeries& withEndSites, const motion::Anatomy& anatomy, double quantile, int first, int last) {
    const auto [lo, hi] = frameRange(withEndSites.frames, first, last);
    const int top = anatomy.headEndSite >= 0 ? withEndSites.joints + anatomy.headEndSite : anatomy.head;
    std::vector<double> statures;
    for (int f = lo; f <= hi && withEndSites.frames > 0; ++f) {
        double low = 1e300, high = -1e300;
        if (anatomy.biped() && top >= 0 && top < withEndSites.points) {
            high = withEndSites.at(f, top).y;
            for (const motion::LegChain& leg : anatomy.legs)
                for (const auto& [joint, site] : leg.soles) {
                    const int point = site >= 0 ? withEndSites.joints + site : joint;
                    if (point < withEndSites.points) low = std::min(low, withEndSites.at(f, point).y);
                }
        } else {
            for (int p = 0; p < withEndSites.points; ++p)
                low = std::min(low, withEndSites.at(f, p).y), high = std::max(high, withEndSites.at(f, p).y);
        }
        if (high >= low) statures.push_back(high - low);
    }
    return quantileOf(std::move(statures), quantile);
}

double fractionBelow(const PointSeries& points, double height) {
    if (points.positions.empty()) return 0.0;
    const auto below = std::count_if(points.positions.begin(), points.positions.end(),
                                     [&](const glm::dvec3& p) { return p.y < height; });
    return static_cast<double>(below) / static_cast<double>(points.positions.size());
}

std::vector<char> turningFrames(std::span<const motion::GroundFrame> ground, double frameTime, double radiansPerSecond) {
    std::vector<char> turning(ground.size(), 0);
    for (std::size_t f = 1; f + 1 < ground.size(); ++f) {
        // Goals mode keeps its yaw wrapped; the wrapped difference is the turn either way.
        const double rate = std::abs(wrapAngle(ground[f + 1].yaw - ground[f - 1].yaw)) / (2.0 * frameTime);
        turning[f] = rate > radiansPerSecond ? 1 : 0;
    }
    return turning;
}

std::vector<int> footPoints(const motion::Anatomy& anatomy) {
    std::vector<int> feet;
    for (const motion::LegChain& leg : anatomy.legs)
        for (int joint : {leg.ankle, leg.toe})
            if (joint >= 0) feet.push_back(joint);
    return feet;
}

}  // namespace throng::quality
