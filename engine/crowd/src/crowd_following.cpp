// Following trajectories (Mode::Follow): another tool decided where each person walks; the
// crowd only poses them. Everything a follower shows at a time is a function of that time
// (tables made once per track at spawn), so a render of frame 1000 needs no stepping through
// frames 0..999 and split renders agree with a whole one to the byte.
#include <algorithm>
#include <cmath>

#include "crowd_internal.h"
#include "throng/crowd/crowd.h"

namespace throng::crowd {
namespace {

// Half the window over which a track's direction and speed are smoothed, seconds: measured
// tracks wobble with each step, and a heading that followed the wobble would swing the body.
constexpr double kSmoothingHalfWindow = 0.25;
// Slower than this a person stands: the heading holds, and the gait time runs at its own rate
// instead of following distance (a stride of nearly nothing would make it race).
constexpr double kMovingSpeed = 0.1;  // m/s

double lerpAngle(double a, double b, double u) { return a + wrapAngle(b - a) * u; }

// How far the gait's ground frame at gait time `cycles` is turned from the direction its cycle
// travels (the chord from this cycle's left strike to the next): the clip's own sway of the
// body, which a planted foot turns with. A track gives the direction of travel; the body
// wobbles about it as the capture did, so its feet don't.
double swayYaw(std::span<const motion::BakedClip> clips, const motion::LocomotionClip& gait, double cycles) {
    if (!gait.gait) return 0.0;
    const motion::RootMotionTrack& root = clips[gait.clip].rootMotion;
    const double whole = std::floor(cycles);
    const glm::dvec2 chord = root.at(gait.gait->frameAt(whole + 1.0)).position - root.at(gait.gait->frameAt(whole)).position;
    if (!(glm::dot(chord, chord) > 1e-12)) return 0.0;
    return wrapAngle(root.at(gait.gait->frameAt(cycles)).yaw - std::atan2(chord.x, chord.y));
}

// The segment [k, k + 1] of `s` (two samples or more) that holds `time`, the first or last
// outside the track's span.
std::size_t segmentAt(const std::vector<TrackSample>& s, double time) {
    const auto after = std::upper_bound(s.begin(), s.end(), time, [](double t, const TrackSample& sample) { return t < sample.time; });
    return std::min(static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - s.begin() - 1, 0)), s.size() - 2);
}

// The cubic Hermite curve through `s` on segment k at `time` (inside the segment).
glm::dvec2 hermiteOn(const std::vector<TrackSample>& s, std::size_t k, double time) {
    // A sample's tangent: the velocity across its neighbours, no faster than 1.5 times the
    // slower of its two chords, so the curve never overshoots into a stop or past a sudden
    // move followed by a long gap (a straight, even stretch keeps its velocity exactly).
    const auto chordSpeed = [&](std::size_t a) { return glm::length(s[a + 1].position - s[a].position) / (s[a + 1].time - s[a].time); };
    const auto tangent = [&](std::size_t i) {
        const std::size_t lo = i == 0 ? 0 : i - 1, hi = std::min(i + 1, s.size() - 1);
        const glm::dvec2 velocity = (s[hi].position - s[lo].position) / (s[hi].time - s[lo].time);
        const double limit = 1.5 * std::min(i > 0 ? chordSpeed(i - 1) : INFINITY, i + 1 < s.size() ? chordSpeed(i) : INFINITY);
        const double speed = glm::length(velocity);
        return speed > limit ? velocity * (limit / speed) : velocity;
    };
    const double h = s[k + 1].time - s[k].time, u = (time - s[k].time) / h;
    const double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * s[k].position + (u3 - 2 * u2 + u) * h * tangent(k) + (-2 * u3 + 3 * u2) * s[k + 1].position +
           (u3 - u2) * h * tangent(k + 1);
}

}  // namespace

glm::dvec2 trackPosition(const Track& track, double time) {
    const std::vector<TrackSample>& s = track.samples;
    if (s.empty()) return glm::dvec2(0.0);
    if (!(time > s.front().time)) return s.front().position;
    if (!(time < s.back().time)) return s.back().position;
    return hermiteOn(s, segmentAt(s, time), time);
}

void Crowd::prepareFollowing(std::size_t i, const Track& track, double phase) {
    const std::vector<TrackSample>& samples = track.samples;
    const std::size_t n = samples.size();
    FollowedTrack followed;
    followed.track = &track;
    followed.heading.assign(n, 0.0);
    followed.speed.assign(n, 0.0);
    followed.cycles.assign(n, 0.0);
    // Direction and speed from the path over a window around each sample (clamped to the track).
    const double first = samples.front().time, last = samples.back().time;
    std::optional<double> heading;
    for (std::size_t k = 0; k < n; ++k) {
        const double lo = std::max(first, samples[k].time - kSmoothingHalfWindow);
        const double hi = std::min(last, samples[k].time + kSmoothingHalfWindow);
        const glm::dvec2 velocity = (trackPosition(track, hi) - trackPosition(track, lo)) / std::max(hi - lo, 1e-9);
        followed.speed[k] = glm::length(velocity);
        if (followed.speed[k] > kMovingSpeed) heading = std::atan2(velocity.x, velocity.y);
        followed.heading[k] = heading.value_or(0.0);
    }
    // A track that starts standing faces where it will first walk.
    const auto moving = std::find_if(followed.speed.begin(), followed.speed.end(), [](double s) { return s > kMovingSpeed; });
    if (moving != followed.speed.end())
        std::fill(followed.heading.begin(), followed.heading.begin() + (moving - followed.speed.begin()),
                  followed.heading[static_cast<std::size_t>(moving - followed.speed.begin())]);
    // Gait time advanced by distance travelled over the blend's stride at that speed (the bake
    // smooths a clip's ground path, so its root moves evenly through the cycle): feet land where
    // the track goes, whatever the speed (past the set's fastest too, where playback alone
    // could not keep up). Standing, the gait time runs at the blend's cadence.
    const motion::LocomotionSet& set = sets_[static_cast<std::size_t>(set_[i])];
    const double scale = scale_[i];
    followed.cycles[0] = phase;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const double seconds = samples[k + 1].time - samples[k].time;
        const double distance = glm::length(samples[k + 1].position - samples[k].position) / scale;
        const double speed = 0.5 * (followed.speed[k] + followed.speed[k + 1]) / scale;
        const double shown = std::clamp(speed, set.slowest(), set.fastest());
        const motion::SpeedBlend blend = motion::blendForSpeed(set, shown);
        const bool walks = shown > kMovingSpeed && blend.cyclesPerSecond > 0;
        followed.cycles[k + 1] = followed.cycles[k] + (walks ? distance * blend.cyclesPerSecond / shown : seconds * blend.cyclesPerSecond);
    }
    followed.idleOffset = phase;
    track_.resize(i + 1, -1);
    track_[i] = static_cast<std::int32_t>(followed_.size());
    followed_.push_back(std::move(followed));
}

void Crowd::follow(std::span<const motion::BakedClip> clips, std::size_t i, double time) {
    const FollowedTrack& followed = followed_[static_cast<std::size_t>(track_[i])];
    const std::vector<TrackSample>& samples = followed.track->samples;
    const double first = samples.front().time, last = samples.back().time;
    const double at = std::clamp(time, first, last);
    const std::size_t k = segmentAt(samples, at);
    const double u = std::clamp((at - samples[k].time) / (samples[k + 1].time - samples[k].time), 0.0, 1.0);
    const glm::dvec2 position = hermiteOn(samples, k, at);
    velocity_[i] = time > time_ ? glm::vec2((position - ground_[i].position) / (time - time_)) : glm::vec2(0.0F);
    ground_[i] = {position, lerpAngle(followed.heading[k], followed.heading[k + 1], u)};
    const double speed = followed.speed[k] + (followed.speed[k + 1] - followed.speed[k]) * u;
    const double cycles = followed.cycles[k] + (followed.cycles[k + 1] - followed.cycles[k]) * u;
    const motion::LocomotionSet& set = sets_[static_cast<std::size_t>(set_[i])];
    const motion::SpeedBlend blend = motion::blendForSpeed(set, speed / scale_[i]);
    // Both gaits at the same gait time (so the same phase); the idle keeps its own time.
    const auto frameOf = [&](const motion::LocomotionClip& member) {
        const motion::BakedClip& clip = clips[member.clip];
        if (member.gait) return clip.rootMotion.wrap(member.gait->frameAt(cycles));
        const motion::LoopRange loop = clip.loop();
        const double frames = std::max(loop.length(), 1);
        return loop.first + std::fmod((at + followed.idleOffset * frames * clip.frameTime) / clip.frameTime, frames);
    };
    const double sway = blend.lower == blend.upper ? swayYaw(clips, *blend.upper, cycles)
                                                   : (1.0 - blend.weight) * swayYaw(clips, *blend.lower, cycles) +
                                                         blend.weight * swayYaw(clips, *blend.upper, cycles);
    ground_[i].yaw = wrapAngle(ground_[i].yaw + sway);
    showBlend(i, blend, frameOf(*blend.lower), frameOf(*blend.upper));
    speed_[i] = static_cast<float>(speed);
    desiredSpeed_[i] = speed_[i];
}

}  // namespace throng::crowd
