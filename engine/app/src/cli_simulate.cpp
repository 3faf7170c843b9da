// `throng simulate`: its options and checks. The crowd-shaping options are render's own
// (addCrowdShapeOptions), so the same options give the same crowd.
#include <cmath>
#include <memory>

#include "cli_internal.h"

namespace throng::app {

std::int64_t SimulateCommand::lastFrame() const { return std::llround(time * static_cast<double>(fps)); }

namespace detail {
namespace {

const NumberRule<int> kFpsRule{1, kMaxSimulateFps, "--fps takes whole samples per second from 1 to " + std::to_string(kMaxSimulateFps)};

// The checks that need several options at once.
std::optional<Error> simulateProblems(const CLI::App& app, const SimulateCommand& command) {
    if (auto conflict = crowdConflicts(app, command.crowd)) return conflict;
    if (command.out.empty()) return usage("'simulate' needs --out FILE.csv", app);
    if (app.count("--time") == 0) return usage("'simulate' needs --time SECONDS", app);
    if (app.count("--fps") == 0) return usage("'simulate' needs --fps N (samples per second)", app);
    if (command.lastFrame() < 1)
        return usage("--time " + defaultText(command.time) + " is less than half a frame at --fps " + std::to_string(command.fps) +
                         ": nothing would be simulated",
                     app);
    return std::nullopt;
}

}  // namespace

CommandDefinition defineSimulate(CLI::App& parent, ParseState& state) {
    auto command = std::make_shared<SimulateCommand>();
    CLI::App* app = addCommand(parent, "simulate", "Step the crowd without rendering (no device) and write CSV.", state);
    app->footer("Writes frames 0 (the spawn, time 0) to round(time x fps), 1/fps s apart:\n"
                "  --out:        id,frame,time,x,y,z,heading,speed (--format csv)\n"
                "  --joints-out: id,frame,time,joint,name,x,y,z\n"
                "metres, seconds, radians (0 faces +Z), m/s; Y up, y = 0 on the ground.\n"
                "At most " + std::to_string(kMaxSimulateRows) + " rows per file. Files are written atomically:\n"
                "both or neither, and a failed or interrupted run leaves none behind.");
    addText(*app, "-o,--out", command->out, "FILE.csv",
            "Trajectories: one row per character and frame (required);\n- writes them to stdout",
            "--out needs a file name");
    app->add_option_function<std::string>(
           "--format",
           [command](const std::string& text) {
               if (text == "csv") command->format = SimulateCommand::Format::Csv;
               else if (text == "jupedsim") command->format = SimulateCommand::Format::JuPedSim;
               else refuse("--format takes csv or jupedsim, not '" + text + "'");
           },
           "What --out holds. csv: the columns below; jupedsim: the\n"
           "JuPedSim/PedPy text layout (#framerate, ID FR X Y Z; ids\n"
           "from 1; X, Y the ground with Y = -z), for PedPy and for\n"
           "--trajectories")
        ->type_name("FORMAT")
        ->default_str("csv");
    addText(*app, "--joints-out", command->jointsOut, "FILE.csv", "Also write every joint's world position per frame",
            "--joints-out needs a file name");
    addTime(*app, command->time, true,
            "Seconds to simulate (required), more than 0, at most " + std::to_string(static_cast<int>(kMaxTimeSeconds)))
        ->default_str("");
    addNumber(*app, "--fps", command->fps, kFpsRule,
              "Samples per second (required), 1 to " + std::to_string(kMaxSimulateFps) + "; the crowd\nsteps 1/N s between them")
        ->default_str("");
    addCrowdShapeOptions(*app, command->crowd);
    return {app,
            [app, command]() -> Result<Command> {
                if (auto problem = simulateProblems(*app, *command)) return *problem;
                return Command{*command};
            },
            optionsOnly("simulate")};
}

}  // namespace detail
}  // namespace throng::app
