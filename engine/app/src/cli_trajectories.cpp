// --trajectories and its reading options, shared by render, demo and simulate: the crowd comes
// from another tool's tracks instead of being spawned and simulated.
#include "cli_internal.h"

namespace throng::app::detail {
namespace {

const std::vector<std::string> kReplaced{"--scene", "--bvh", "--characters", "--mode", "--area", "--speed"};
const std::vector<std::string> kReading{"--trajectory-axes", "--trajectory-units", "--trajectory-fps"};

}  // namespace

void addTrajectoryOptions(CLI::App& app, CrowdOptions& crowd) {
    addTrajectoryOptions(app, crowd.trajectories, crowd.trajectoryReading, "Excludes --scene, --bvh, --characters,\n--mode, --area and --speed");
}

void addTrajectoryOptions(CLI::App& app, std::optional<std::string>& file, crowd::TrajectoryOptions& reading, const std::string& excludes) {
    addText(app, "--trajectories", file, "FILE",
            "Follow another tool's tracks instead of simulating: one\n"
            "character per id, posed by the locomotion set at its speed.\n"
            "CSV with a header (id, frame or time, x, y[, z]) or the\n"
            "JuPedSim/PedPy text layout (# ID FR X Y Z); time 0 is the\n"
            "file's first sample. " + excludes,
            "--trajectories needs a file name");
    app.add_option_function<std::string>(
           "--trajectory-axes",
           [&reading](const std::string& text) {
               if (text == "xy") reading.axes = crowd::TrajectoryAxes::Xy;
               else if (text == "xz") reading.axes = crowd::TrajectoryAxes::Xz;
               else if (text == "auto") reading.axes = crowd::TrajectoryAxes::Auto;
               else refuse("--trajectory-axes takes xy, xz or auto, not '" + text + "'");
           },
           "The file's ground plane. xy: pedestrian tools (z is height;\n"
           "y is turned to -z so a plan is not mirrored); xz: Y up, as\n"
           "Throng writes. auto: xz for Throng's own CSV, else xy")
        ->type_name("AXES")
        ->default_str("auto");
    app.add_option_function<std::string>(
           "--trajectory-units",
           [&reading](const std::string& text) {
               if (text == "m") reading.metresPerUnit = 1.0;
               else if (text == "cm") reading.metresPerUnit = 0.01;
               else if (text == "mm") reading.metresPerUnit = 0.001;
               else refuse("--trajectory-units takes m, cm or mm, not '" + text + "'");
           },
           "Unit of the file's positions (default: what its header says,\nelse metres)")
        ->type_name("UNIT");
    const NumberRule<double> rate{crowd::kMinTrajectoryRate, crowd::kMaxTrajectoryRate,
                                  "--trajectory-fps takes samples per second from 1 to 1000"};
    addNumber(app, "--trajectory-fps", reading.framesPerSecond, rate,
              "Frame rate of a file that numbers frames (default: its\n'framerate' comment)")
        ->default_str("");
}

std::optional<Error> trajectoryReadingAlone(const CLI::App& app, bool fileGiven) {
    if (fileGiven) return std::nullopt;
    for (const std::string& name : kReading)
        if (app.count(name) > 0) return usage(name + " says how to read --trajectories: give that too", app);
    return std::nullopt;
}

std::optional<Error> trajectoryConflicts(const CLI::App& app, const CrowdOptions& crowd) {
    const auto given = [&](const std::vector<std::string>& names) {
        for (const std::string& name : names)
            if (app.count(name) > 0) return name;
        return std::string();
    };
    if (!crowd.trajectories) return trajectoryReadingAlone(app, false);
    if (const std::string option = given(kReplaced); !option.empty())
        return usage("--trajectories gives the characters and where they walk; don't combine it with " + option +
                         " (--locomotion picks the clips they are posed with)",
                     app);
    return std::nullopt;
}

}  // namespace throng::app::detail
