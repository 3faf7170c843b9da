#pragma once
// The flat, immutable runtime form of a clip: for every frame and joint, the joint's global
// transform relative to the character's ground frame ("in place"), in metres, as a rotation
// quaternion plus a translation (which interpolate well). The root's travel over the ground
// lives in a separate RootMotionTrack. This is the table the GPU palette is made from.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "throng/core/error.h"
#include "throng/motion/raw_motion.h"
#include "throng/motion/body_bones.h"
#include "throng/motion/root_motion.h"
#include "throng/motion/skeleton_anatomy.h"

namespace throng::motion {

/// One joint at one frame. 32 bytes, the layout the GPU palette uses.
struct JointPose {
    glm::quat rotation{1.0F, 0.0F, 0.0F, 0.0F};  ///< Global orientation in the ground frame; GLM stores it x, y, z, w.
    glm::vec3 translation{0.0F};                 ///< Global position in the ground frame, metres.
    float reserved = 0.0F;                       ///< Padding to 32 bytes; keep zero.
};
static_assert(sizeof(JointPose) == 32, "JointPose must stay 32 bytes (GPU palette layout)");

/// Which file axis points up. Throng is Y-up; a Z-up or X-up file is turned to Y-up at the bake.
enum class UpAxis : std::uint8_t { PlusY, MinusY, PlusZ, MinusZ, PlusX, MinusX };
[[nodiscard]] const char* upAxisName(UpAxis axis);  ///< "y", "-y", "z", "-z", "x", "-x"
[[nodiscard]] std::optional<UpAxis> upAxisFromName(std::string_view name);

/// How to bake a RawMotion. Defaults suit ordinary captures; every field that is a guess
/// by default (units, up axis, travel joint, loop, first frame) can be given instead.
struct BakeOptions {
    PositionChannels positionChannels = PositionChannels::Replace;  ///< See DESIGN.md §3.
    std::optional<double> metresPerUnit;  ///< Override the inferred unit scale (e.g. 0.01 for cm).
    std::optional<LoopRange> loop;        ///< Override loop detection (frame indices, last > first).
    /// Whether frame 0 is a synthetic T-pose to leave out of the loop: nullopt detects it.
    std::optional<bool> skipFirstFrame;
    /// Close the loop: real captures never end exactly where they started, so the seam's
    /// pose mismatch is spread evenly over the loop's frames (translations lerp, rotations
    /// slerp a correction), making frame `last` equal frame `first`. Each frame step changes
    /// by mismatch / loop length, which no one can see; the wrap itself then can't pop.
    bool closeLoop = true;
    /// The file's up axis; nullopt detects it from gravity (feet lowest, head highest).
    std::optional<UpAxis> upAxis;
    /// Name of the joint whose ground track is the character's travel; empty finds the
    /// pelvis by the skeleton's structure (falling back to the ROOT).
    std::string travelJoint;
    /// Take out the clip's own turning: the ground path becomes a straight line of the same
    /// arc length, so group mode walks straight. The pose keeps its lean.
    bool straighten = false;
    /// Foot lock: during each foot contact, the leg is bent (two-bone IK) so the planted foot
    /// holds its place on the ground over the loop, wrap included.
    bool footLock = true;
};

/// One contact of a foot with the ground over a clip's loop: `strike` is the first frame the
/// foot is down (the heel's strike, or the toe's when it lands first) and `lift` the first frame
/// it is in the air again (toe-off). Both are frames inside the loop; a contact that spans the
/// loop's seam has `lift` before `strike`.
struct FootContact {
    int strike = 0;
    int lift = 0;
};

struct BakedClip {
    std::string name;                  ///< Source file or label.
    std::vector<std::string> jointNames;
    std::vector<int> parents;          ///< Depth-first, -1 for the root.
    int frameCount = 0;
    double frameTime = 0.0;            ///< Seconds per frame.
    std::vector<JointPose> poses;      ///< frameCount × jointCount, frame-major.
    RootMotionTrack rootMotion;        ///< Ground frame per frame, with the loop.
    double metresPerUnit = 1.0;        ///< Scale applied to the file's lengths.
    std::string unitName;              ///< "metres", "centimetres", ... or "custom".
    bool unitInferred = true;          ///< False when BakeOptions gave the scale.
    UpAxis upAxis = UpAxis::PlusY;     ///< The file's up axis (turned to +Y in every pose).
    /// Height (m, after the up-axis turn) of the floor the capture was walked on: a low
    /// percentile of the soles. Poses are lowered by it, so feet meet Throng's ground, y = 0.
    double floorHeight = 0.0;
    bool upAxisInferred = true;        ///< False when BakeOptions gave it.
    int travelJoint = 0;               ///< Joint whose ground track is the travel (the pelvis, usually).
    Anatomy anatomy;                   ///< Body parts found by structure (anatomy.biped() may be false).
    /// Stature in metres: head-top minus sole as the body stands upright (the 90th percentile
    /// over frames; of the whole vertical extent when no biped was recognised). Units, body
    /// radius, sphere sizes and LOD use it.
    double stature = 0.0;
    /// Ground speed in m/s at playback 1: the arc length of the smoothed ground path over the
    /// loop, divided by the loop's duration (a curving walk is rated at the pace it walks).
    double speed = 0.0;
    /// The clip's own turning in rad/s over the loop (positive turns left, toward +X from +Z).
    double turnRate = 0.0;
    /// Per frame, the point (x, z in metres, ground frame) a steering turn pivots about: the
    /// ankle of the foot held more firmly (footHold), the origin when no foot is down.
    std::vector<glm::vec2> pivots;
    /// Per frame, how much steering turn the body can take without sliding a planted foot,
    /// 0..1: 1 with at most one leg's foot held (the body turns about its ankle and the foot is
    /// twisted back, CharacterState::footTwist), falling to 0 as the other foot is held too
    /// (double support): the cube of 1 − the weaker leg's footHold. Steering turns in these
    /// windows. Empty: free everywhere.
    std::vector<float> turnFreedom;
    /// turnFreedom's mean over the loop, set by the bake: the share of a cycle the body can turn
    /// in, which a steering turn is concentrated into (1 when there is no turnFreedom).
    double meanTurnFreedom = 1.0;
    /// Per frame, how firmly each leg's foot is held on the ground by the foot lock, heel or toe
    /// (x: legs[0], y: legs[1]; 0..1, ramped). A held foot takes the steering turn back as a
    /// twist about its ankle; a lifted one twists ahead of the turn (stanceTurnSeconds).
    /// Empty: no feet.
    std::vector<glm::vec2> footHold;
    /// Per frame, where each leg's ankle stands on the ground (x, z in metres, ground frame;
    /// legs as footHold's, the origin for a leg with no ankle): the poses' ankle positions in a
    /// table of 16 bytes a frame, which the crowd step reads for every blending character
    /// (instead of two pose rows a clip, 31 joints apart). Set by the bake from the final poses
    /// and anatomy: code that changes either afterwards must make it again
    /// (bake_steps::ankleGround), or clear it to have anklesAt read the poses.
    std::vector<std::array<glm::vec2, 2>> ankleGround;
    /// Per leg, the steering one stance of its foot takes back as twist, in seconds of the
    /// average steering rate at playback 1 (footHold × turnGainAt over the loop, per stance).
    /// A foot in the air turns ahead by that much, so it lands pointing where the body is
    /// turning and the stance takes that twist back before it lifts (the hold runs to
    /// toe-off, but the body hardly turns once the other foot is down): a foot that lifts
    /// twisted slides its toe as the heel comes up. 0 for a foot that never lifts.
    glm::dvec2 stanceTurnSeconds{0.0};
    /// Per joint, 0, or 1 + the leg (anatomy.legs) whose foot, the ankle and below, it is in:
    /// the joints a foot twist turns.
    std::vector<std::uint8_t> footLeg;
    /// Per leg (anatomy.legs), the foot's contacts over the loop, by strike frame: its gait
    /// events. Empty for a foot that never lifts, and without feet.
    std::array<std::vector<FootContact>, 2> footContacts;
    /// Which of anatomy.legs is the body's left (0 or 1; -1 without a biped): the one whose hip
    /// is further to the left of the ground frame's heading, whatever the joints are named.
    int leftLeg = -1;
    /// Per frame, bit i set when anatomy.legs[i]'s foot is planted.
    std::vector<std::uint8_t> contacts;
    /// Readings that were guessed or look suspicious, one line each (no trailing period),
    /// for stderr and `bvh info --json`.
    std::vector<std::string> warnings;
    bool firstFrameSkipped = false;    ///< Frame 0 recognised as a T-pose and kept out of the loop.
    double gaitPeriodFrames = 0.0;     ///< Estimated gait period in frames; 0 if none was found.
    bool locomotion = false;           ///< The clip travels (its body's top ground speed is a walk's or more).
    bool isStatic = false;             ///< Too short for a cycle: played as a pose with no root motion.
    double seamMismatch = 0.0;         ///< Largest joint distance (m) between frames first and last
                                       ///< before loop closing.
    /// Per joint, a sphere radius in metres that suits the skeleton (about a third of the
    /// shortest adjoining bone, clamped), so joint spheres look right at any scale.
    std::vector<float> jointRadius;
    /// Per joint, 1 when a distant character may leave it out (level of detail): another
    /// joint stands within 7% of the skeleton's height of it, so their spheres overlap (short
    /// hip, spine and neck links, the hand's small joints). Roots are always kept.
    std::vector<std::uint8_t> jointDetail;
    /// The body drawn by --body bones: a tapered capsule per bone, sized by its part.
    std::vector<BodyBone> body;

    [[nodiscard]] int jointCount() const { return static_cast<int>(parents.size()); }
    [[nodiscard]] const LoopRange& loop() const { return rootMotion.loop(); }
    [[nodiscard]] const JointPose& pose(int frame, int joint) const {
        return poses[static_cast<std::size_t>(frame) * parents.size() + static_cast<std::size_t>(joint)];
    }
    /// The in-place global transform of `joint` at `frame` as a 4×4 matrix.
    [[nodiscard]] glm::mat4 matrix(int frame, int joint) const;
    /// In-place pose at a fractional frame inside [0, frameCount-1]: nlerp of rotations and
    /// lerp of translations between the neighbouring frames (the GPU does the same).
    [[nodiscard]] JointPose sample(double frame, int joint) const;
    /// sample(frame, joint).translation alone, without the rotation's blend (the crowd step's
    /// foot checks read only where a joint is).
    [[nodiscard]] glm::vec3 positionAt(double frame, int joint) const;
    /// World-space position of `joint` for a character whose ground frame is `ground` at
    /// wrapped frame position `frame`.
    [[nodiscard]] glm::dvec3 worldPosition(const GroundFrame& ground, double frame, int joint) const;
    /// The stance pivot (ground-frame x, z) at a fractional frame, interpolated like poses.
    [[nodiscard]] glm::dvec2 pivotAt(double frame) const;
    /// turnFreedom at a fractional frame, interpolated like poses (1 when there is none).
    [[nodiscard]] double turnFreedomAt(double frame) const;
    /// footHold at a fractional frame, interpolated like poses (0 when there is none).
    [[nodiscard]] glm::dvec2 footHoldAt(double frame) const;
    /// Both legs' ankles on the ground at a fractional frame: positionAt's x and z for
    /// anatomy.legs' ankles, to the bit, from ankleGround (or the poses where the bake left none).
    [[nodiscard]] std::array<glm::dvec2, 2> anklesAt(double frame) const;
    /// How many times the average steering rate the body turns at `frame`: turnFreedom over its
    /// mean, at most 3, so a steering turn happens in the gait's turning windows. 1 throughout
    /// for a clip rarely free (mean under 0.1: a shuffle, a stance on both feet), which turns
    /// evenly rather than hardly at all.
    [[nodiscard]] double turnGainAt(double frame) const;
    /// The gait phase at a frame position inside the loop, 0..1: 0 at the left foot's strike,
    /// rising evenly to 1 at its next strike (across the loop's seam when that comes first).
    /// A loop of several cycles restarts at each left strike. -1 when the left foot never
    /// strikes (no gait to time: a stance, a dance on one foot, no biped).
    [[nodiscard]] double gaitPhaseAt(double frame) const;
};

/// Bakes forward kinematics, root motion, loop range and scale. Fails (BadInput) on a clip
/// with no frames or on an invalid override.
[[nodiscard]] Result<BakedClip> bake(const RawMotion& motion, const BakeOptions& options = {});

}  // namespace throng::motion
