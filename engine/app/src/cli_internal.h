#pragma once
// Internals of the command-line parser, shared by its translation units.
//
// Every command is a CLI11 App whose options write straight into the Command being built.
// Values go through the one set of validators below; a refused value throws
// CLI::ValidationError carrying the whole message, and parseCommandLine turns that into a
// usage Error naming the command's help. Nothing here keeps global state, and the only I/O is
// --bvh asking whether its argument names an existing file (see clip_spec.h).

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "throng/app/cli.h"

namespace throng::app::detail {

// --- Refusing a value -------------------------------------------------------------------

/// Refuses the value being parsed. `message` is the whole error line, without the help hint.
[[noreturn]] inline void refuse(const std::string& message) {
    throw CLI::ValidationError(message, CLI::ExitCodes::ValidationError);
}

/// "a, b or c": for help and error texts.
std::string orList(const std::vector<std::string>& names);
/// The locomotion modes' names ("group", "goals", "avoid").
std::vector<std::string> modeNames();
/// The render paths' names, in render::kRenderPaths order.
std::vector<std::string> renderPathNames();

// --- The number validators: every number on the command line goes through these --------

/// The number that is all of `text` (no spaces, no sign on unsigned types), or nullopt. A
/// floating-point number must be finite: NaN, infinities and overflow are refused.
template <typename T>
std::optional<T> parseNumber(std::string_view text) {
    static_assert(std::is_arithmetic_v<T>);
    T value{};
    const char* end = text.data() + text.size();
    const auto [stop, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || stop != end) return std::nullopt;
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) return std::nullopt;
    }
    return value;
}

/// What a numeric option accepts, inclusive, and how it says so when it refuses a value:
/// `complaint` reads like "--time takes seconds from 0 to 600"; ", not 'VALUE'" follows it.
template <typename T>
struct NumberRule {
    T min = std::numeric_limits<T>::lowest();
    T max = std::numeric_limits<T>::max();
    std::string complaint;
};

/// The smallest positive value of T: a lower bound that means "greater than zero".
template <typename T>
constexpr T kPositive = std::is_floating_point_v<T> ? std::numeric_limits<T>::denorm_min() : T{1};

/// The number in `text` when it is within [min, max], or nullopt.
template <typename T>
std::optional<T> parseBounded(std::string_view text, T min, T max) {
    const std::optional<T> value = parseNumber<T>(text);
    if (!value || *value < min || *value > max) return std::nullopt;
    return value;
}

/// The number in `text` under `rule`, or refuse().
template <typename T>
T checkedNumber(std::string_view text, const NumberRule<T>& rule) {
    const std::optional<T> value = parseBounded(text, rule.min, rule.max);
    if (!value) refuse(rule.complaint + ", not '" + std::string(text) + "'");
    return *value;
}

/// The items of a comma-separated list, empty ones included ("1,,2" has three).
std::vector<std::string_view> splitList(std::string_view text);

/// A comma-separated list of numbers, each under `rule`; a refusal quotes the whole list.
template <typename T>
std::vector<T> checkedList(std::string_view text, const NumberRule<T>& rule) {
    std::vector<T> values;
    for (const std::string_view item : splitList(text)) {
        const std::optional<T> value = parseBounded(item, rule.min, rule.max);
        if (!value) refuse(rule.complaint + ", not '" + std::string(text) + "'");
        values.push_back(*value);
    }
    return values;
}

/// How a default value reads in the help ("48", "1280", "0.5").
template <typename T>
std::string defaultText(const T& value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

/// Adds a numeric option that stores into `target` (a T or std::optional<T>) what `rule`
/// accepts. The help shows `target`'s current value as the default.
template <typename T, typename Target>
CLI::Option* addNumber(CLI::App& app, const std::string& names, Target& target, NumberRule<T> rule,
                       const std::string& description) {
    CLI::Option* option = app.add_option_function<std::string>(
        names, [&target, rule](const std::string& text) { target = checkedNumber(text, rule); }, description);
    option->type_name("N");
    if constexpr (std::is_same_v<Target, T>) option->default_str(defaultText(target));
    return option;
}

/// Adds an option that stores its text into `target` (a std::string or std::optional of one).
/// With `emptyComplaint` an empty value is refused with that message.
template <typename Target>
CLI::Option* addText(CLI::App& app, const std::string& names, Target& target, const std::string& typeName,
                     const std::string& description, const std::string& emptyComplaint = "") {
    return app
        .add_option_function<std::string>(
            names,
            [&target, emptyComplaint](const std::string& text) {
                if (text.empty() && !emptyComplaint.empty()) refuse(emptyComplaint);
                target = text;
            },
            description)
        ->type_name(typeName);
}

// --- Shared option rules ---------------------------------------------------------------

inline const NumberRule<int> kCharactersRule{1, kMaxCharacters,
                                             "--characters takes a count from 1 to " + std::to_string(kMaxCharacters)};
inline const NumberRule<unsigned> kThreadsRule{1, 256, "--threads takes 1 to 256"};
inline const NumberRule<float> kLodPixelsRule{0.0F, 100000.0F, "--lod-pixels takes 0 (off) or a height in pixels"};

/// Adds --width (-W) and --height (-H), 16..kMaxImageSide pixels.
void addImageSize(CLI::App& app, std::uint32_t& width, std::uint32_t& height, const std::string& what);
/// Adds --msaa: 1, 2, 4 or 8 samples.
void addMsaa(CLI::App& app, std::uint32_t& samples, const std::string& description);
/// Adds --bvh FILE[:key=value,...], repeatable: each clip with its bake overrides (clip_spec.h).
void addClipOption(CLI::App& app, std::vector<ClipSpec>& clips, const std::string& description);
/// Adds --locomotion FILE,FILE,... (one set, into `set`) and --speed MIN[:MAX] (m/s, 0 to
/// range::kLargestSpeed, into `speed`). `setDefault` ends --locomotion's help: what a crowd
/// blends without it.
void addLocomotionOptions(CLI::App& app, std::vector<ClipSpec>& set, std::optional<glm::vec2>& speed, const std::string& setDefault);
/// What --bvh, --locomotion and --speed refuse together: --bvh with a set, and --speed when
/// the crowd will blend no set (`blends` false); `howToBlend` follows "--speed needs a
/// locomotion set to blend " in that refusal.
std::optional<Error> locomotionConflicts(const CLI::App& app, const std::vector<ClipSpec>& clips, const std::vector<ClipSpec>& set,
                                         bool speedGiven, bool blends, const std::string& howToBlend);
/// Adds the options that decide the crowd and its motion, the one definition render, demo
/// and simulate share: --bvh, --locomotion, --speed, --characters, --mode, --area, --scene,
/// --seed and --threads.
void addCrowdShapeOptions(CLI::App& app, CrowdOptions& crowd);
/// render's --duration, --fps and --frames (cli_video.cpp), and what they can't go with.
void addVideoOptions(CLI::App& app, RenderCommand& command);
std::optional<Error> videoConflicts(const CLI::App& app, const RenderCommand& command);
/// --trajectories and how to read the file (cli_trajectories.cpp).
void addTrajectoryOptions(CLI::App& app, CrowdOptions& crowd);
/// `excludes`: the help's sentence on the options --trajectories can't go with.
void addTrajectoryOptions(CLI::App& app, std::optional<std::string>& file, crowd::TrajectoryOptions& reading, const std::string& excludes);
/// --trajectory-* given without --trajectories.
std::optional<Error> trajectoryReadingAlone(const CLI::App& app, bool fileGiven);
/// --trajectories with an option that would shape the crowd too, or --trajectory-* without it.
std::optional<Error> trajectoryConflicts(const CLI::App& app, const CrowdOptions& crowd);
/// Adds --time SECONDS, up to kMaxTimeSeconds: from 0, or (`positive`) more than 0.
CLI::Option* addTime(CLI::App& app, double& seconds, bool positive, const std::string& description);

// --- Commands -------------------------------------------------------------------------

/// What the command definitions share while one command line is parsed.
struct ParseState {
    const CLI::App* helpFor = nullptr;  ///< The command whose -h/--help was given, if any.
};

/// A command that runs something: its App, whose options fill a Command under construction,
/// and what turns that into the finished Command once every option is in.
struct CommandDefinition {
    CLI::App* app = nullptr;
    /// Checks that need several options at once; the finished command.
    std::function<Result<Command>()> finish;
    /// The message for a word that is not an option and has nowhere to go.
    std::function<std::string(const std::string& word)> stray;
};

/// Adds command `name` under `parent`, with -h/--help, extra words collected for the caller
/// to report (not thrown by CLI11), and the parent's formatter.
CLI::App* addCommand(CLI::App& parent, const std::string& name, const std::string& description, ParseState& state);

/// "bvh info": the command words that reach `app` ("" for throng itself).
std::string commandPath(const CLI::App& app);

/// A usage error (BadInput): `message`, then a pointer to `app`'s help, e.g.
/// "(see 'throng render --help')".
Error usage(const std::string& message, const CLI::App& app);

/// A usage error when --scene is given (`scene`) with any of `replaced`: options whose say
/// the scene file has instead.
std::optional<Error> sceneConflicts(const CLI::App& app, bool scene, const std::vector<std::string>& replaced);
/// A usage error for crowd options that contradict each other: --scene with the options it
/// replaces, --bvh with --locomotion, --speed without a set.
std::optional<Error> crowdConflicts(const CLI::App& app, const CrowdOptions& crowd);
/// The message for a stray word given to command `name`, which takes options only.
std::function<std::string(const std::string&)> optionsOnly(const std::string& name);

/// The definitions of the commands, each added under `parent`.
std::vector<CommandDefinition> defineBvhCommands(CLI::App& bvh, ParseState& state);
CommandDefinition defineRender(CLI::App& parent, ParseState& state);
CommandDefinition defineDemo(CLI::App& parent, ParseState& state);
CommandDefinition defineDevices(CLI::App& parent, ParseState& state);
CommandDefinition defineBench(CLI::App& parent, ParseState& state);
CommandDefinition defineSimulate(CLI::App& parent, ParseState& state);

}  // namespace throng::app::detail
