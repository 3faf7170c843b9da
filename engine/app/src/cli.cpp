// `throng`'s command line: the command tree (CLI11), its help texts and its usage errors.
// The commands' own options are defined in cli_bvh.cpp, cli_render.cpp, cli_simulate.cpp and
// cli_bench.cpp.
#include "throng/app/cli.h"

#include <filesystem>
#include <memory>
#include <sstream>
#include <system_error>

#include "cli_internal.h"
#include "clip_spec.h"

namespace throng::app {
namespace detail {

std::string orList(const std::vector<std::string>& names) {
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return list;
}

std::vector<std::string_view> splitList(std::string_view text) {
    std::vector<std::string_view> items;
    while (true) {
        const std::size_t comma = text.find(',');
        items.push_back(text.substr(0, comma));
        if (comma == std::string_view::npos) return items;
        text.remove_prefix(comma + 1);
    }
}

void addImageSize(CLI::App& app, std::uint32_t& width, std::uint32_t& height, const std::string& what) {
    const auto rule = [](const std::string& option) {
        return NumberRule<std::uint32_t>{16, kMaxImageSide,
                                         option + " takes pixels from 16 to " + std::to_string(kMaxImageSide)};
    };
    addNumber(app, "-W,--width", width, rule("--width"), what + " width in pixels, 16 to " + std::to_string(kMaxImageSide));
    addNumber(app, "-H,--height", height, rule("--height"), what + " height in pixels, 16 to " + std::to_string(kMaxImageSide));
}

void addMsaa(CLI::App& app, std::uint32_t& samples, const std::string& description) {
    app.add_option_function<std::string>(
           "--msaa",
           [&samples](const std::string& text) {
               const std::optional<std::uint32_t> n = parseNumber<std::uint32_t>(text);
               if (!n || (*n != 1 && *n != 2 && *n != 4 && *n != 8)) refuse("--msaa takes 1, 2, 4 or 8, not '" + text + "'");
               samples = *n;
           },
           description)
        ->type_name("N")
        ->default_str(defaultText(samples));
}

void addClipOption(CLI::App& app, std::vector<ClipSpec>& clips, const std::string& description) {
    const auto namesExistingFile = [](const std::string& path) {
        std::error_code ec;  // an unreadable or over-long name is no file: the loader says why
        return std::filesystem::exists(path, ec);
    };
    app.add_option_function<std::vector<std::string>>(
           "--bvh",
           [&clips, namesExistingFile](const std::vector<std::string>& texts) {
               for (const std::string& text : texts) {
                   auto clip = parseClipArgument(text, namesExistingFile);
                   if (!clip) refuse("--bvh " + text + ": " + clip.error().message);
                   clips.push_back(std::move(clip.value()));
               }
           },
           description +
               "\nFILE:key=value,... overrides how that clip bakes; keys:\n"
               "units, up, root, loop, straighten, foot-lock,\n"
               "position-channels, keep-first-frame (see README)")
        ->type_name("FILE[:KEY=VALUE,...]")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

namespace {

// --speed MIN[:MAX], metres per second.
glm::vec2 parseSpeed(const std::string& text) {
    const std::string_view all = text;
    const std::size_t colon = all.find(':');
    constexpr auto kLargest = static_cast<float>(range::kLargestSpeed);
    const std::optional<float> low = parseBounded(all.substr(0, colon), 0.0F, kLargest);
    const std::optional<float> high = colon == std::string_view::npos ? low : parseBounded(all.substr(colon + 1), 0.0F, kLargest);
    if (!low || !high || *high < *low)
        refuse("--speed takes MIN[:MAX] in m/s, 0 <= MIN <= MAX <= " + std::to_string(static_cast<int>(kLargest)) + " (e.g. 1.2:1.6), not '" +
               text + "'");
    return {*low, *high};
}

}  // namespace

void addLocomotionOptions(CLI::App& app, std::vector<ClipSpec>& set, std::optional<glm::vec2>& speed, const std::string& setDefault) {
    app.add_option_function<std::string>(
           "--locomotion",
           [&set](const std::string& text) {
               for (const std::string_view file : splitList(text)) set.push_back({std::string(file), {}});
               if (set.empty()) refuse("--locomotion takes a list of BVH files, FILE,FILE,...");
           },
           "A locomotion set: clips of one skeleton (an idle, walks,\n"
           "runs) that each character blends by its speed at a shared\n"
           "gait phase (" + setDefault + ")")
        ->type_name("FILE,FILE,...");
    app.add_option_function<std::string>(
           "--speed", [&speed](const std::string& text) { speed = parseSpeed(text); },
           "Desired ground speeds in m/s, drawn per character (needs a\n"
           "set). Group mode keeps it; goals and avoid cruise at it.\n"
           "Clamped into the set's range: 0 (with an idle, else 0.85x\n"
           "the slowest gait) to 1.2x the fastest (default 1.0:1.6)")
        ->type_name("MIN[:MAX]");
}

std::optional<Error> locomotionConflicts(const CLI::App& app, const std::vector<ClipSpec>& clips, const std::vector<ClipSpec>& set,
                                         bool speedGiven, bool blends, const std::string& howToBlend) {
    if (!clips.empty() && !set.empty())
        return usage("--bvh plays each clip as it is and --locomotion blends a set; give one or the other", app);
    if (speedGiven && !blends) return usage("--speed needs a locomotion set to blend " + howToBlend, app);
    return std::nullopt;
}

std::string commandPath(const CLI::App& app) {
    std::string path;
    for (const CLI::App* a = &app; a->get_parent() != nullptr; a = a->get_parent())
        path = a->get_name() + (path.empty() ? "" : " " + path);
    return path;
}

Error usage(const std::string& message, const CLI::App& app) {
    const std::string path = commandPath(app);
    return Error{Error::Kind::BadInput, message + " (see 'throng " + (path.empty() ? "" : path + " ") + "--help')", {}};
}

namespace {

// Takes over from CLI11's -h/--help so that help wins as soon as it is seen, before any
// value is checked; and keeps words CLI11 can't place for parseCommandLine to report.
void configureCommand(CLI::App& app, ParseState& state) {
    app.set_help_flag();
    app.allow_extras();
    app.add_flag_callback(
           "-h,--help",
           [&app, &state] {
               state.helpFor = &app;
               throw CLI::CallForHelp();
           },
           "Show this help and exit")
        ->trigger_on_parse();
}

}  // namespace

CLI::App* addCommand(CLI::App& parent, const std::string& name, const std::string& description, ParseState& state) {
    CLI::App* app = parent.add_subcommand(name, description);
    configureCommand(*app, state);
    return app;
}

}  // namespace detail

namespace {

using detail::usage;

std::vector<const CLI::App*> commandsUnder(const CLI::App* app) {
    return app->get_subcommands([](const CLI::App* sub) { return !sub->get_name().empty(); });
}

// CLI11's layout with: usage first, a command list that spells nested commands out
// ("bvh info"), and each option's default at the end of its description.
class HelpFormatter : public CLI::Formatter {
public:
    HelpFormatter() {
        column_width(32);
        label("OPTIONS", "options");
    }

    std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
        if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
        std::string out = make_usage(app, name);
        if (!app->get_description().empty()) out += "\n" + app->get_description() + "\n";
        out += make_positionals(app) + make_groups(app, mode) + make_subcommands(app, mode);
        if (!app->get_footer().empty()) out += "\n" + app->get_footer() + "\n";
        return out;
    }

    std::string make_usage(const CLI::App* app, std::string name) const override {
        if (commandsUnder(app).empty()) return CLI::Formatter::make_usage(app, std::move(name));
        return get_label("Usage") + ": " + name + " <command> [" + get_label("OPTIONS") + "]\n";
    }

    std::string make_subcommands(const CLI::App* app, CLI::AppFormatMode) const override {
        const std::vector<const CLI::App*> commands = commandsUnder(app);
        if (commands.empty()) return {};
        std::ostringstream out;
        out << "\nCommands:\n";
        for (const CLI::App* command : commands) {
            const std::vector<const CLI::App*> nested = commandsUnder(command);
            if (nested.empty()) CLI::detail::format_help(out, command->get_name(), command->get_description(), column_width_);
            for (const CLI::App* sub : nested)
                CLI::detail::format_help(out, command->get_name() + " " + sub->get_name(), sub->get_description(), column_width_);
        }
        return out.str();
    }

    std::string make_option_opts(const CLI::Option* option) const override {
        if (option->get_type_size() == 0 || option->get_type_name().empty()) return {};
        return " " + option->get_type_name();
    }

    std::string make_option_desc(const CLI::Option* option) const override {
        const std::string& shown = option->get_default_str();
        return option->get_description() + (shown.empty() ? "" : " (default " + shown + ")");
    }
};

std::string helpText(const CLI::App& app) {
    const std::string path = detail::commandPath(app);
    return app.get_formatter()->make_help(&app, path.empty() ? "throng" : "throng " + path, CLI::AppFormatMode::Normal);
}

/// The commands given, from the root down to the one the command line is for.
std::vector<const CLI::App*> givenChain(const CLI::App& root) {
    std::vector<const CLI::App*> chain{&root};
    while (!chain.back()->get_subcommands().empty()) chain.push_back(chain.back()->get_subcommands().front());
    return chain;
}

/// The words CLI11 could not place, reported for the first command that has any.
std::optional<Error> strayWords(const std::vector<const CLI::App*>& chain,
                                const std::vector<detail::CommandDefinition>& definitions) {
    for (const CLI::App* app : chain) {
        const std::vector<std::string> words = app->remaining();
        if (words.empty()) continue;
        const std::string& word = words.front();
        if (app->get_parent() == nullptr) return usage("unknown command '" + word + "'", *app);
        if (word.size() > 1 && word[0] == '-')
            return usage("unknown option '" + word + "' for '" + detail::commandPath(*app) + "'", *app);
        for (const detail::CommandDefinition& definition : definitions)
            if (definition.app == app) return usage(definition.stray(word), *app);
        return usage("unknown '" + detail::commandPath(*app) + "' subcommand '" + word + "'", *app);
    }
    return std::nullopt;
}

/// `throng help [COMMAND...]`.
Result<Command> helpFor(const CLI::App& root, const std::vector<std::string>& topic) {
    const CLI::App* app = &root;
    std::string asked;
    for (const std::string& word : topic) {
        asked += (asked.empty() ? "" : " ") + word;
        const auto found = app->get_subcommands([&word](const CLI::App* sub) { return sub->get_name() == word; });
        if (found.empty()) return usage("unknown command '" + asked + "'", root);
        app = found.front();
    }
    return Command{HelpCommand{helpText(*app)}};
}

/// The message for an option left without its value. CLI11 gives an option every next
/// argument, whatever it looks like, so the option is the last argument.
std::string missingValue(std::span<const std::string> args, const CLI::ArgumentMismatch& e) {
    if (args.empty() || args.back().size() < 2 || args.back()[0] != '-') return e.what();
    const std::string& last = args.back();
    return "option " + last.substr(0, last.find('=')) + " needs a value";
}

}  // namespace

Result<Command> parseCommandLine(std::span<const std::string> args) {
    detail::ParseState state;
    CLI::App root("throng - GPU crowd animation from motion capture", "throng");
    root.formatter(std::make_shared<HelpFormatter>());
    root.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    root.require_subcommand(0, 1);
    detail::configureCommand(root, state);
    bool version = false;
    root.add_flag("--version", version, "Print the version and exit");

    CLI::App* bvh = detail::addCommand(root, "bvh", "Read, check and bake BVH motion capture.", state);
    std::vector<detail::CommandDefinition> definitions = detail::defineBvhCommands(*bvh, state);
    for (auto* define :
         {&detail::defineRender, &detail::defineDemo, &detail::defineSimulate, &detail::defineDevices, &detail::defineBench})
        definitions.push_back(define(root, state));
    CLI::App* help = detail::addCommand(root, "help", "Show this help, or the help of COMMAND.", state);
    std::vector<std::string> topic;
    help->add_option("COMMAND", topic, "A command, e.g. 'render' or 'bvh info'")->type_name("");
    root.footer("Every command takes -h/--help; 'throng help COMMAND' shows the same text.\n"
                "Options take their value as '--name value' or '--name=value'.\n"
                "Exit codes: 0 success, 1 runtime failure, 2 bad usage or bad input.");

    std::vector<std::string> reversed(args.rbegin(), args.rend());
    try {
        root.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        return Command{HelpCommand{helpText(*state.helpFor)}};
    } catch (const CLI::ArgumentMismatch& e) {
        return usage(missingValue(args, e), *givenChain(root).back());
    } catch (const CLI::ParseError& e) {
        return usage(e.what(), *givenChain(root).back());
    }

    const std::vector<const CLI::App*> chain = givenChain(root);
    if (auto stray = strayWords(chain, definitions)) return *stray;
    const CLI::App* command = chain.back();
    if (command == &root)
        return version ? Command{VersionCommand{}} : Command{HelpCommand{helpText(root)}};
    if (command == help) return helpFor(root, topic);
    for (const detail::CommandDefinition& definition : definitions)
        if (definition.app == command) return definition.finish();
    std::vector<std::string> names;
    for (const CLI::App* sub : commandsUnder(command)) names.push_back(sub->get_name());
    return usage("'" + detail::commandPath(*command) + "' needs a subcommand: " + detail::orList(names), *command);
}

}  // namespace throng::app
