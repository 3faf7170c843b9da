#pragma once
// Per-clip bake overrides. `--bvh FILE:key=value,...` (render, demo, bench) and the clip
// entries of a scene file take the same overrides, checked by the same rules here:
//
//   command line             scene file                    BakeOptions field
//   units=0.01               "units": 0.01                 metresPerUnit, 0 < units <= 1e6
//   up=z                     "up": "z"                     upAxis: y, -y, z, -z, x or -x
//   root=Hips                "root": "Hips"                travelJoint: a joint of the file
//   loop=10-50               "loop": [10, 50]              loop: frame indices, FIRST < LAST
//   straighten=1             "straighten": true            straighten
//   foot-lock=0              "foot_lock": false            footLock
//   position-channels=add    "position_channels": "add"    positionChannels: replace or add
//   keep-first-frame=1       "keep_first_frame": true      skipFirstFrame: false (0: detected)
//
// On the command line a boolean is 0/1, yes/no or true/false; values cannot hold ','. Whether
// a `root` joint exists is the bake's to say: only it has read the file.

#include <array>
#include <climits>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "throng/app/cli.h"

namespace throng::app {

/// The largest metres per file unit accepted (--units, units=, "units"): a 1e6 m unit is
/// already a thousand kilometres.
inline constexpr double kMaxMetresPerUnit = 1e6;

/// One override's names: on the command line and in a scene file.
struct ClipOverrideName {
    std::string_view key;    ///< `--bvh FILE:key=value`, e.g. "foot-lock".
    std::string_view field;  ///< The scene file's field, e.g. "foot_lock".
};
/// Every override, in the order messages and the help list them.
inline constexpr std::array<ClipOverrideName, 8> kClipOverrides{{{"units", "units"},
                                                                  {"up", "up"},
                                                                  {"root", "root"},
                                                                  {"loop", "loop"},
                                                                  {"straighten", "straighten"},
                                                                  {"foot-lock", "foot_lock"},
                                                                  {"position-channels", "position_channels"},
                                                                  {"keep-first-frame", "keep_first_frame"}}};

/// What --units, units= and "units" accept: 0 < value <= kMaxMetresPerUnit (false for NaN).
[[nodiscard]] bool acceptedMetresPerUnit(double value);
/// What a loop override accepts: frame indices 0 <= first < last <= INT_MAX.
[[nodiscard]] bool acceptedLoop(long long first, long long last);
/// "replace" or "add".
[[nodiscard]] std::optional<motion::PositionChannels> positionChannelsFromName(std::string_view name);
/// The up axes' names as a message lists them: "y, -y, z, -z, x or -x".
[[nodiscard]] std::string upAxisList();

/// Applies `key=value` in the command line's spelling to `bake`. Returns nullopt, or the
/// refusal: one line naming the key and what it takes, e.g. "up takes y, -y, z, -z, x or -x,
/// not 'w'".
[[nodiscard]] std::optional<std::string> applyClipOverride(std::string_view key, std::string_view value,
                                                           motion::BakeOptions& bake);

/// Reads a `--bvh` argument, FILE[:key=value,...]. A plain path never breaks:
///  - if all of `text` names an existing file (`exists`), it is the path, ':' and all;
///  - else the overrides follow the rightmost ':' whose remainder's first item has an '='
///    (an unknown key is then refused) or is a bare known key: in "walk.bvh:root=mixamorig:Hips" that is the first ':', since "Hips" is
///    neither (joint names with ':' are common: Mixamo writes "mixamorig:Hips");
///  - with no such ':', all of `text` is the path (the loader then reports a missing file).
/// Unknown keys, bad values, repeated keys and an empty FILE are refused with a message that
/// names the key and what it takes.
[[nodiscard]] Result<ClipSpec> parseClipArgument(std::string_view text, const std::function<bool(const std::string&)>& exists);

}  // namespace throng::app
