#pragma once
// Crowd state as a structure of arrays, seeded spawning, the per-frame step in three
// locomotion modes, and the packing of every character into the contiguous CharacterState
// array the GPU reads.

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "throng/core/error.h"
#include "throng/core/parallel.h"
#include "throng/core/rng.h"
#include "throng/crowd/character_state.h"
#include "throng/crowd/orca.h"
#include "throng/crowd/spatial_hash.h"
#include "throng/crowd/trajectories.h"
#include "throng/motion/baked_clip.h"
#include "throng/motion/locomotion_set.h"

namespace throng::crowd {

/// How a character decides where to walk.
enum class Mode : std::uint8_t {
    Group,  ///< The paper's: a shared orientation M_o, moved by the clip's own root motion.
    Goals,  ///< Walks to its own goal, turning at a bounded rate, then picks the next.
    Avoid,  ///< Goals, plus reciprocal collision avoidance (ORCA) with its neighbours.
    /// Follows a track of CrowdSetup::trajectories (another tool's people): placed where the
    /// track is at each time, facing along it, posed by its locomotion set at the track's
    /// speed. Not a --mode: a crowd read from trajectories is made of these.
    Follow,
};
[[nodiscard]] const char* modeName(Mode mode);
[[nodiscard]] std::optional<Mode> modeFromName(std::string_view name);

/// An axis-aligned rectangle on the ground, metres: x from centre.x ± size.x/2, z likewise.
struct Region {
    glm::vec2 centre{0.0F};
    glm::vec2 size{20.0F, 20.0F};
};

/// A group of characters that spawn together and share a mode.
struct GroupSpec {
    int count = 1;                       ///< Characters, >= 1.
    std::vector<std::uint32_t> clips;    ///< Clip indices, taken in turn; empty means every clip.
    Region region;                       ///< Spawn area.
    Mode mode = Mode::Group;
    glm::vec2 speedRange{1.0F, 1.0F};    ///< Playback-speed multiplier, drawn per character (1 = the clip's pace); not with a set.
    float heading = 0.0F;                ///< Radians; group mode's shared M_o (0 walks toward +Z).
    /// Index into CrowdSetup::locomotion: the group's characters blend that set's clips by speed
    /// (and `clips` is not read). nullopt: each plays one clip, the paper's way.
    std::optional<std::uint32_t> locomotion;
    /// With a set: desired ground speed in m/s, drawn per character and clamped into the set's
    /// range (motion::LocomotionSet::slowest..fastest times the character's scale). Group mode
    /// keeps it; goals and avoid cruise at it.
    glm::vec2 groundSpeed{1.0F, 1.6F};
    /// With a set that has an idle, in goals and avoid modes: seconds a character stands at a
    /// goal before it sets off for the next, drawn per arrival (min <= max).
    glm::vec2 pause{0.0F, 3.0F};
    /// What errors call the group; empty: "group N", its index in CrowdSetup::groups.
    std::string name{};
};

/// Something a group starts doing at a time: play another clip or blend another set, with a
/// crossfade, and/or walk at other speeds.
struct CrowdEvent {
    double time = 0.0;                          ///< Seconds since spawn.
    std::uint32_t group = 0;                    ///< Index into CrowdSetup::groups.
    std::optional<std::uint32_t> clip;          ///< Play this clip alone (the paper's way) ...
    std::optional<std::uint32_t> locomotion;    ///< ... or blend this set (CrowdSetup::locomotion) by speed.
    std::optional<glm::vec2> groundSpeed;       ///< New desired speeds, m/s, drawn per character (with a set).
    float fade = 0.3F;                          ///< Crossfade seconds, 0..kLongestFade (0 cuts).
    static constexpr float kLongestFade = 10.0F;
};

/// Everything that shapes a crowd.
struct CrowdSetup {
    std::vector<GroupSpec> groups;
    std::vector<motion::LocomotionSet> locomotion;  ///< Sets the groups may blend (GroupSpec::locomotion).
    std::vector<CrowdEvent> events;      ///< Applied in time order as the crowd steps (stable for equal times).
    std::vector<glm::vec2> waypoints;    ///< Goals visited in turn from a random start; empty: random goals.
    Region area;                         ///< Where random goals are drawn.
    std::uint64_t seed = 1;              ///< Same seed (and clips), same crowd and same motion.
    unsigned threads = 0;                ///< Worker threads for step(); 0 = the machine's cores.
    /// Tracks for Mode::Follow groups: their characters take the tracks in order, the first
    /// such group from track 0. Each needs the group's locomotion set.
    std::shared_ptr<const Trajectories> trajectories;
};

/// Tuning of goals and avoidance. Defaults suit walking humans.
struct LocomotionParameters {
    float turnRate = 2.6F;              ///< Largest steering turn rate, radians per second (~150°/s), on top of the clip's own turning.
    float turnAcceleration = 6.0F;      ///< Largest change of the steering turn rate, rad/s² (full rate in ~0.4 s).
    float arrivalRadius = 1.0F;         ///< Metres from the goal that count as arrived.
    float neighbourDistance = 2.0F;     ///< Metres within which neighbours are avoided.
    float timeHorizon = 1.5F;           ///< Seconds ahead for avoidance.
    float bodyRadiusPerHeight = 0.17F;  ///< Collision radius as a fraction of skeleton height (1.75 m -> 0.30 m).
    float minPlayback = 0.3F;           ///< Slowest playback when avoidance slows a character.
    float maxPlayback = 1.6F;           ///< Fastest playback.
    float acceleration = 1.5F;          ///< m/s²: how fast a character blending a set changes its speed (idle to run in ~2 s).
};

/// Move-only: a crowd owns its worker threads and per-character streams, and a copy would
/// silently share the one and fork the other.
class Crowd {
public:
    Crowd(const Crowd&) = delete;
    Crowd& operator=(const Crowd&) = delete;
    Crowd(Crowd&&) noexcept = default;
    Crowd& operator=(Crowd&&) noexcept = default;
    ~Crowd() = default;

    /// Spawns every group: random positions in its region with no two bodies overlapping,
    /// start frames random inside each clip's loop, seeded colour, scale (±5%) and speed.
    /// Fails (BadInput) on no clips, a bad clip index, a count < 1, or a region too small.
    static Result<Crowd> spawn(std::span<const motion::BakedClip> clips, const CrowdSetup& setup,
                               const LocomotionParameters& parameters = {});

    /// Advances every character by `seconds`. Each moves by the root-motion displacement of
    /// exactly the stretch of clip it played (group mode: rotated by M_o and the clip's own
    /// turning, the paper's update; goals/avoid: the clip's step and turn plus a ramped steering
    /// turn toward the goal, pivoting about the planted foot, with playback speed matching
    /// ground speed).
    void step(std::span<const motion::BakedClip> clips, double seconds);

    /// Writes one CharacterState per character into `out` (size() entries), on the step's
    /// threads from kParallelPackCharacters characters on.
    void pack(std::span<CharacterState> out) const { pack(0, out); }
    /// Writes characters first .. first + out.size() - 1 into `out` (a renderer's batch,
    /// straight into its GPU-visible memory), the same way. The run must lie within size().
    void pack(std::size_t first, std::span<CharacterState> out) const;
    static constexpr std::size_t kParallelPackCharacters = 65536;

    [[nodiscard]] int size() const { return static_cast<int>(ground_.size()); }
    [[nodiscard]] const motion::GroundFrame& groundFrame(int i) const { return ground_[at(i)]; }
    [[nodiscard]] double frame(int i) const { return frame_[at(i)]; }
    [[nodiscard]] std::uint32_t clip(int i) const { return clip_[at(i)]; }
    [[nodiscard]] Mode mode(int i) const { return mode_[at(i)]; }
    [[nodiscard]] float radius(int i) const { return radius_[at(i)]; }
    [[nodiscard]] float playback(int i) const { return playback_[at(i)]; }
    [[nodiscard]] float scale(int i) const { return scale_[at(i)]; }
    [[nodiscard]] glm::vec2 goal(int i) const { return goal_[at(i)]; }
    /// With a set: the second clip of the blend, its frame position and its weight (0..1).
    [[nodiscard]] std::uint32_t blendClip(int i) const { return blendClip_[at(i)]; }
    [[nodiscard]] double blendFrame(int i) const { return blendFrame_[at(i)]; }
    [[nodiscard]] float blendWeight(int i) const { return blend_[at(i)]; }
    /// The ground speed the character's blend is walking at, m/s (0 without a set).
    [[nodiscard]] float speed(int i) const { return speed_[at(i)]; }
    /// The speed it wants: its cruise, m/s (0 without a set).
    [[nodiscard]] float desiredSpeed(int i) const { return desiredSpeed_[at(i)]; }
    /// Sets the cruising speed of a character of a set (m/s, clamped into the set's range at
    /// its scale); its blend follows at the bounded acceleration. No effect without a set.
    void setDesiredSpeed(int i, float metresPerSecond);
    /// Crossfades character i over `fade` seconds (0 cuts) from what it shows now to `clip`
    /// played alone at its own pace, or to blending set `set` (CrowdSetup::locomotion) by speed
    /// at the speed it walks now. A gait starts at the gait phase shown, and the outgoing clip
    /// keeps step with it, so the feet agree; a transition fades from
    /// the one clip shown. The GPU mixes at most three clips (a blend's two and one
    /// outgoing), so a fade asked for while the pose shows two or more waits: a blend first
    /// glides to the nearer of its clips (by speed, at the usual acceleration), a running fade
    /// ends, and then the fade starts from that one clip, with no jump. A cut (fade 0) starts
    /// at once; a later request replaces a waiting one; blending the set already blended
    /// changes nothing. Out-of-range indices change nothing.
    void playClip(std::span<const motion::BakedClip> clips, int i, std::uint32_t clip, float fade);
    void blendSet(std::span<const motion::BakedClip> clips, int i, std::uint32_t set, float fade);
    /// Whether a fade asked for waits for the pose to show one clip (see playClip).
    [[nodiscard]] bool transitionWaiting(int i) const { return waiting_[at(i)].kind != Waiting::Kind::None; }
    /// A transition's outgoing clip, its frame position and its weight (0: none runs).
    [[nodiscard]] std::uint32_t fromClip(int i) const { return fromClip_[at(i)]; }
    [[nodiscard]] double fromFrame(int i) const { return fromFrame_[at(i)]; }
    [[nodiscard]] float fromWeight(int i) const { return fromWeight_[at(i)]; }
    /// Seconds the character will still stand at the goal it reached (0 while it walks).
    [[nodiscard]] float pausing(int i) const { return std::max(pauseLeft_[at(i)], 0.0F); }
    /// Whether the character is in the scene now: false for a follower before its track
    /// starts or after it ends (packed with scale 0, which every render path draws as nothing).
    /// Both ends are in: a frame at a track's first or last sample shows the person. The clock
    /// is a sum of steps (thirty steps of 1/30 s fall short of 1 s by about 1e-16), so the ends
    /// reach out by kPresenceSlack, far less than samples' 1 ms apart, and whether a sample's
    /// own time shows its person does not depend on the frame rate it was reached at.
    [[nodiscard]] bool present(int i) const {
        if (track_.empty() || track_[at(i)] < 0) return true;
        const std::vector<TrackSample>& samples = followed_[static_cast<std::size_t>(track_[at(i)])].track->samples;
        return time_ >= samples.front().time - kPresenceSlack && time_ <= samples.back().time + kPresenceSlack;
    }
    static constexpr double kPresenceSlack = 1e-6;  ///< Seconds, see present().
    /// The id a follower's track has in its file (Track::id); nullopt for a character that
    /// doesn't follow one.
    [[nodiscard]] std::optional<std::int64_t> trackId(int i) const {
        if (track_.empty() || track_[at(i)] < 0) return std::nullopt;
        return followed_[static_cast<std::size_t>(track_[at(i)])].track->id;
    }
    /// The group the character spawned in.
    [[nodiscard]] std::uint32_t group(int i) const { return group_[at(i)]; }
    /// Seconds simulated since spawn.
    [[nodiscard]] double time() const { return time_; }
    /// A group's locomotion set and ground speeds: BadInput when they don't make sense.
    [[nodiscard]] static std::optional<Error> checkLocomotion(const GroupSpec& group, const std::string& which,
                                                              std::span<const motion::BakedClip> clips, const CrowdSetup& setup);
    /// The set the character blends, or nullptr when it plays one clip.
    [[nodiscard]] const motion::LocomotionSet* locomotion(int i) const {
        return set_[at(i)] < 0 ? nullptr : &sets_[static_cast<std::size_t>(set_[at(i)])];
    }
    /// Ground speed the clip gives at playback 1 and scale 1, m/s: BakedClip::speed, the arc
    /// length of its ground path over the loop per second.
    [[nodiscard]] static double clipSpeed(const motion::BakedClip& clip);
    [[nodiscard]] unsigned threadCount() const { return pool_->threadCount(); }

private:
    Crowd() = default;  // only spawn() makes one
    [[nodiscard]] static std::size_t at(int i) { return static_cast<std::size_t>(i); }
    void pickGoal(std::size_t i);
    /// Character i's velocity with nobody about (to desired_) and, if it avoids, the fastest
    /// it may go (to fastest_, else -1).
    void preferVelocity(std::span<const motion::BakedClip> clips, std::size_t i);
    /// ORCA for everyone who avoids, visiting cellOrdered_ (this step's grid) in order.
    void avoidInCellOrder(float seconds);
    /// Character i's nearest neighbours within parameters_.neighbourDistance of `position`
    /// (itself excluded), nearest first (ties in cell order): their places in cellOrdered_ go
    /// to `nearest`; returns how many.
    std::size_t nearestNeighbours(std::size_t i, glm::vec2 position, std::array<std::uint32_t, kMaxOrcaNeighbours>& nearest) const;
    void integrate(std::span<const motion::BakedClip> clips, double seconds, std::size_t i);
    /// What one step played: the root motion (unscaled, in the ground frame at the step's
    /// start) and the clip and frame that time the feet (the blend's heavier clip).
    struct Played {
        motion::GroundFrame delta;
        std::uint32_t clip = 0;
        double frame = 0.0;
        double cycles = -1.0;  ///< Gait cycles the heavier motion advanced (-1: it has no gait).
    };
    /// Advances the character's clip (at playback_) or, with a set, its blend toward
    /// `targetSpeed` (m/s; crowd_blending.cpp), and returns what it played.
    Played advance(std::span<const motion::BakedClip> clips, double seconds, std::size_t i, double targetSpeed);
    Played advanceBlend(std::span<const motion::BakedClip> clips, double seconds, std::size_t i, double targetSpeed);
    /// Appends character ground_.size()'s clip, speed, blend, transition and pause state (spawn).
    void appendMotion(std::span<const motion::BakedClip> clips, const CrowdSetup& setup, std::size_t g, std::uint32_t clip, float scale, Rng& rng);
    /// Shows `blend` on character i: its two clips at these frame positions, its weight and playback.
    void showBlend(std::size_t i, const motion::SpeedBlend& blend, double lowerFrame, double upperFrame);
    /// Starts a character of a set at its speed, at gait phase `phase` (0..1).
    void startBlend(std::span<const motion::BakedClip> clips, std::size_t i, double phase);
    /// The clips a character shows and their weights in the pose (up to three, summing to 1).
    struct PoseMix {
        std::array<std::uint32_t, 3> clip{};
        std::array<double, 3> frame{};
        std::array<double, 3> weight{};
        int count = 0;
    };
    [[nodiscard]] PoseMix poseMix(std::size_t i) const;
    /// How far a held foot would slide as the weights change from `before` to `after` (ground
    /// frame, unscaled): taken off the step's root motion, so the foot stays planted.
    [[nodiscard]] static glm::dvec2 heldFootSlide(std::span<const motion::BakedClip> clips, const PoseMix& before, const PoseMix& after);
    /// The clip or set a fade waits to start to (see playClip).
    struct Waiting {
        enum class Kind : std::uint8_t { None, Clip, Set } kind = Kind::None;
        std::uint32_t target = 0;
        float fade = 0.0F;
        float groundSpeed = -1.0F;  ///< The event's desired speed for the set, m/s, once it starts (< 0: none).
        float glideTo = -1.0F;      ///< The speed the blend glides to, chosen once (< 0: not yet).
    };
    /// Whether the pose shows one clip (others weigh next to nothing), so a fade can start.
    [[nodiscard]] bool showsOneClip(std::size_t i) const;
    /// Starts character i's transition to a clip or set now (playClip and blendSet, checked).
    void startClip(std::span<const motion::BakedClip> clips, std::size_t i, std::uint32_t clip, float fade);
    void startSet(std::span<const motion::BakedClip> clips, std::size_t i, std::uint32_t set, float fade);
    /// Starts a waiting transition if the pose now shows one clip (before the step's playback
    /// is chosen, so the clip it starts plays at that).
    void startWaitingTransition(std::span<const motion::BakedClip> clips, std::size_t i);
    /// While a transition waits on a blend: the speed that brings the blend onto its clip
    /// nearer `targetSpeed`, chosen once so it moves one way; else `targetSpeed`.
    double glideForWaitingTransition(std::size_t i, double targetSpeed);
    /// Fades the transition's outgoing clip by one step and mixes its root motion into `played`.
    void crossfade(std::span<const motion::BakedClip> clips, double seconds, std::size_t i, Played& played);
    /// Hands what the character shows now to the transition's outgoing slot; returns the gait
    /// phase shown (-1 without one).
    double beginTransition(std::size_t i, float fade);
    /// The setup's groups, events and followers: BadInput for the first that doesn't make sense.
    [[nodiscard]] static std::optional<Error> checkSetup(std::span<const motion::BakedClip> clips, const CrowdSetup& setup);
    /// The setup's events: BadInput when one names what doesn't exist or can't be shown.
    [[nodiscard]] static std::optional<Error> checkEvents(std::span<const motion::BakedClip> clips, const CrowdSetup& setup);
    /// Plays the character's one clip on at playback_ (the paper's way).
    Played advanceClip(std::span<const motion::BakedClip> clips, double seconds, std::size_t i);
    /// Applies the events due by time_ (CrowdSetup::events).
    void applyEvents(std::span<const motion::BakedClip> clips);
    /// The speed a character of a set cruises at toward a goal `distance` metres away, its
    /// heading `headingError` radians off: slowing to stand at the goal (with an idle) and
    /// while it turns sharply; 0 while it pauses.
    [[nodiscard]] float approachSpeed(std::size_t i, float distance, float headingError) const;
    /// Precomputes character i's track (Mode::Follow): heading, speed and gait cycles per sample.
    void prepareFollowing(std::size_t i, const Track& track, double phase);
    /// After spawning: every follower placed and posed at time 0.
    void startFollowing(std::span<const motion::BakedClip> clips);
    /// Places and poses follower i at `time` (seconds since spawn), a function of time alone,
    /// so any frame can be rendered without stepping through the ones before it.
    void follow(std::span<const motion::BakedClip> clips, std::size_t i, double time);
    /// Arrival at the goal: a character of a set with an idle stands for a pause first.
    void arrive(std::size_t i, double seconds);
    /// The steering turn (radians) for this step toward `wanted` more than the clip turns itself.
    double steering(std::size_t i, double wanted, double seconds);
    /// Twists held feet back by the body's `turn` (at clip `frame`) and turns lifted ones toward
    /// the twist their next stance will take back (`remaining`: the heading still wanted before
    /// this step's turn). Returns the turn the feet can take: `turn`, less what would twist a
    /// leg too far.
    double twistFeet(std::size_t i, const motion::BakedClip& clip, double frame, double turn, double remaining, double seconds);
    /// The steering turn `steer` concentrated into the gait's turning windows
    /// (BakedClip::turnGainAt) at `frame`, never past `remaining`.
    [[nodiscard]] static double gaitTimedTurn(const motion::BakedClip& clip, double frame, double steer, double remaining);

    // Per character, one entry each.
    std::vector<motion::GroundFrame> ground_;  ///< World ground frame: position (x, z) and yaw.
    std::vector<double> frame_;                ///< Frame position, wrapped into the clip's loop.
    std::vector<std::uint32_t> clip_;
    std::vector<Mode> mode_;
    std::vector<float> baseSpeed_;             ///< Playback multiplier drawn at spawn.
    std::vector<float> playback_;              ///< Current playback speed.
    std::vector<float> scale_;
    std::vector<float> radius_;                ///< Collision radius, metres.
    std::vector<std::uint32_t> color_;
    std::vector<glm::vec2> goal_;
    std::vector<std::uint32_t> waypoint_;      ///< Index of the current waypoint.
    std::vector<glm::vec2> velocity_;          ///< Realised velocity of the last step, m/s.
    std::vector<float> turnVelocity_;          ///< Steering turn rate, rad/s (ramped).
    std::vector<glm::vec2> footTwist_;         ///< Per leg, the foot's twist about its ankle, radians (CharacterState::footTwist).
    std::vector<Rng> rng_;                     ///< Per-character stream: goals don't depend on order.
    // Speed blending (a set's characters; the others keep set_ -1 and weight 0).
    std::vector<std::int32_t> set_;            ///< Index into sets_, or -1.
    std::vector<float> desiredSpeed_;          ///< Cruising ground speed, m/s.
    std::vector<float> speed_;                 ///< Speed the blend walks at, m/s, following the wanted one at a bounded acceleration.
    std::vector<std::uint32_t> blendClip_;     ///< The blend's faster clip (clip_ holds the slower).
    std::vector<double> blendFrame_;
    std::vector<float> blend_;                 ///< Weight of blendClip_.
    // Transitions (CharacterState::fromClip): the outgoing clip fades at fadeRate_ per second.
    std::vector<std::uint32_t> fromClip_;
    std::vector<double> fromFrame_;
    std::vector<float> fromWeight_;
    std::vector<float> fadeRate_;
    std::vector<float> fromPlayback_;          ///< The outgoing clip's playback when it has no gait to keep step by.
    std::vector<Waiting> waiting_;             ///< A fade asked for while the pose showed two clips or more.
    // Starting and stopping.
    std::vector<std::uint32_t> group_;
    std::vector<float> pauseLeft_;             ///< Seconds still to stand at the goal; <= 0 while walking.

    // Following trajectories (Mode::Follow): per character an index into followed_, or -1.
    struct FollowedTrack {
        const Track* track = nullptr;     ///< In trajectories_.
        std::vector<double> heading;      ///< Per sample: yaw of the smoothed direction (held while standing).
        std::vector<double> speed;        ///< Per sample: smoothed ground speed, m/s.
        std::vector<double> cycles;       ///< Per sample: gait cycles walked since spawn (phase = fraction).
        double idleOffset = 0.0;          ///< Seconds into the idle's loop at time 0.
    };
    std::shared_ptr<const Trajectories> trajectories_;
    std::vector<FollowedTrack> followed_;
    std::vector<std::int32_t> track_;          ///< Empty when nobody follows.

    // Scratch, reused every step.
    std::vector<glm::vec2> positions_;         ///< float copy of ground_ positions for the hash
    std::vector<glm::vec2> desired_;           ///< Velocity each character chose this step
    struct Neighbour {
        float x, y, vx, vy, radius;
        std::uint32_t index;
    };
    std::vector<Neighbour> cellOrdered_;       ///< Everyone in the hash's cell order, for sequential scans
    std::vector<float> fastest_;               ///< Per character: the speed ORCA may choose up to, or -1 when it doesn't avoid
    struct Wish {
        glm::vec2 preferred;
        float fastest;
    };
    std::vector<Wish> wishes_;                 ///< desired_ (as preferred) and fastest_ in cellOrdered_'s order
    SpatialHash hash_;

    std::vector<glm::vec2> waypoints_;
    std::vector<motion::LocomotionSet> sets_;
    std::vector<std::optional<motion::GaitClock>> clocks_;  ///< Per clip of the table: its gait, if any.
    std::vector<GroupSpec> groups_;
    std::vector<CrowdEvent> events_;           ///< Sorted by time.
    std::size_t nextEvent_ = 0;
    double time_ = 0.0;
    Region area_;
    LocomotionParameters parameters_;
    std::shared_ptr<ThreadPool> pool_;         ///< Shared so a Crowd stays movable.
};

}  // namespace throng::crowd
