// `throng simulate`: the crowd `throng render` would draw (crowd_scene.h: the same options and
// seed give the same crowd), stepped on the CPU at 1/F s and written as CSV. Rows stream
// through temporaries that are renamed into place at the end (StreamedOutputs): memory stays a
// few MiB however long the run, and an error or a signal leaves no partial file.
#include "simulate_command.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "crowd_scene.h"
#include "output.h"
#include "throng/core/atomic_file.h"
#include "throng/core/log.h"
#include "throng/crowd/character_state.h"

namespace throng::app {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kChunkBytes = std::size_t{4} << 20;  // rows handed to a file at a time
constexpr double kQuietSeconds = 1.0;                       // a run shorter than this prints no progress
constexpr std::string_view kTrajectoryHeader = "id,frame,time,x,y,z,heading,speed\n";
constexpr std::string_view kJointsHeader = "id,frame,time,joint,name,x,y,z\n";

void appendWhole(std::string& out, std::int64_t value, char after) {
    char text[24];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    out.append(text, ec == std::errc() ? end : text);
    out += after;
}

// One output's rows, handed to its file a chunk at a time. A write error throws (the caller's
// StreamedOutputs then removes every temporary as it unwinds).
class CsvSink {
public:
    CsvSink(StreamedOutputs& files, std::size_t index, std::string_view header) : files_(files), index_(index) {
        rows_.reserve(kChunkBytes + 4096);
        rows_ += header;
    }
    std::string& rows() { return rows_; }
    void rowDone() {
        ++count_;
        if (rows_.size() >= kChunkBytes) flush();
    }
    void flush() {
        files_.append(index_, rows_).orThrow();
        rows_.clear();
    }
    [[nodiscard]] std::int64_t count() const { return count_; }

private:
    StreamedOutputs& files_;
    std::size_t index_;
    std::string rows_;
    std::int64_t count_ = 0;
};

struct FrameStamp {
    std::int64_t index = 0;
    double time = 0.0;  // seconds
    double step = 0.0;  // seconds since the previous frame
};

// The JuPedSim/PedPy text layout's header: what PedPy reads (the frame rate, the unit) and
// the column line. Positions are metres ("in metres").
std::string jupedsimHeader(int fps, int characters, bool following) {
    return "#description: throng simulate\n#agents: " + std::to_string(characters) + "\n#framerate: " + std::to_string(fps) +
           (following ? "\n#ID: the agent ID (its id in the trajectory file)" : "\n#ID: the agent ID (Throng's character index + 1)") +
           "\n#FR: the current frame\n"
           "#X,Y,Z: the agents' coordinates (in metres; X, Y the ground, Y = -z of Throng's world; Z = 0)\n\n#ID\tFR\tX\tY\tZ\n";
}

// The id a row gives character `i`: a follower's id in its trajectory file, so a round trip
// keeps the user's ids; else the character's index, plus `firstIndex` (the text layout counts
// from 1).
std::int64_t rowId(const crowd::Crowd& crowd, int i, std::int64_t firstIndex) {
    return crowd.trackId(i).value_or(i + firstIndex);
}

// ID FR X Y Z for every character present, tab-separated, positions with six decimals.
void writeJuPedSim(CsvSink& sink, const crowd::Crowd& crowd, const FrameStamp& frame) {
    for (int i = 0; i < crowd.size(); ++i) {
        if (!crowd.present(i)) continue;
        const motion::GroundFrame& ground = crowd.groundFrame(i);
        std::string& row = sink.rows();
        appendWhole(row, rowId(crowd, i, 1), '\t');
        appendWhole(row, frame.index, '\t');
        appendFixed6(row, ground.position.x, '\t');
        appendFixed6(row, -ground.position.y, '\t');
        appendFixed6(row, 0.0, '\n');
        sink.rowDone();
    }
}

// What a character's previous row said, for the next one's speed and heading.
struct PreviousRow {
    glm::dvec2 position{0.0};
    double heading = 0.0;
};

// id,frame,time,x,y,z,heading,speed for every character present, numbers with six decimals
// (metres, seconds, radians, m/s); `previous` holds each one's position and written heading at
// the frame before (and is updated, absent or not). The crowd keeps some yaws in (-pi, pi]: the
// heading written is unwrapped, the previous one plus the turn since, so it stays continuous
// through turns (a plot or a derivative of it has no 2 pi jumps).
void writeTrajectories(CsvSink& sink, const crowd::Crowd& crowd, std::vector<PreviousRow>& previous, const FrameStamp& frame) {
    for (int i = 0; i < crowd.size(); ++i) {
        const motion::GroundFrame& ground = crowd.groundFrame(i);
        PreviousRow& before = previous[static_cast<std::size_t>(i)];
        const double speed = frame.index == 0 ? 0.0 : glm::length(ground.position - before.position) / frame.step;
        const double heading = frame.index == 0 ? ground.yaw : before.heading + wrapAngle(ground.yaw - before.heading);
        before = {ground.position, heading};
        if (!crowd.present(i)) continue;
        std::string& row = sink.rows();
        appendWhole(row, rowId(crowd, i, 0), ',');
        appendWhole(row, frame.index, ',');
        appendFixed6(row, frame.time, ',');
        appendFixed6(row, ground.position.x, ',');
        appendFixed6(row, 0.0, ',');
        appendFixed6(row, ground.position.y, ',');
        appendFixed6(row, heading, ',');
        appendFixed6(row, speed, '\n');
        sink.rowDone();
    }
}

// id,frame,time,joint,name,x,y,z for every joint of every character present, sampled from its
// packed state by crowd::sampleJointWorld, as the GPU samples it. `names`: per clip, its
// joints' names as CSV fields.
void writeJoints(CsvSink& sink, const CrowdScene& scene, const std::vector<std::vector<std::string>>& names, const FrameStamp& frame) {
    const std::span<const motion::BakedClip> clips = scene.clipSpan();
    const std::span<const crowd::CharacterState> packed = scene.packed();
    const crowd::Crowd& crowd = *scene.crowd;
    for (std::size_t i = 0; i < packed.size(); ++i) {
        if (!crowd.present(static_cast<int>(i))) continue;
        const crowd::CharacterState& character = packed[i];
        const std::vector<std::string>& joints = names[character.clip];
        const std::int64_t id = rowId(crowd, static_cast<int>(i), 0);
        for (std::size_t j = 0; j < joints.size(); ++j) {
            const glm::vec3 position = crowd::sampleJointWorld(clips, character, static_cast<int>(j)).position;
            std::string& row = sink.rows();
            appendWhole(row, id, ',');
            appendWhole(row, frame.index, ',');
            appendFixed6(row, frame.time, ',');
            appendWhole(row, static_cast<std::int64_t>(j), ',');
            row += joints[j];
            row += ',';
            appendFixed6(row, position.x, ',');
            appendFixed6(row, position.y, ',');
            appendFixed6(row, position.z, '\n');
            sink.rowDone();
        }
    }
}

// A line on stderr at each tenth of the frames, once the run has taken a second (a short run
// prints none).
class Progress {
public:
    explicit Progress(std::int64_t lastFrame) : last_(lastFrame) {}
    void update(std::int64_t frame) {
        const auto tenth = static_cast<int>(frame * 10 / last_);
        if (tenth <= shown_ || frame == last_ || seconds() < kQuietSeconds) return;
        shown_ = tenth;
        char line[160];
        std::snprintf(line, sizeof line, "simulate: %d%% (frame %lld of %lld) in %.1f s, about %.0f s left",
                      static_cast<int>(frame * 100 / last_),
                      static_cast<long long>(frame), static_cast<long long>(last_), seconds(),
                      seconds() * static_cast<double>(last_ - frame) / static_cast<double>(frame));
        log::report(line);
    }
    [[nodiscard]] double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
    std::int64_t last_;
    Clock::time_point start_ = Clock::now();
    int shown_ = 0;
};

struct RowCounts {
    std::int64_t trajectories = 0, joints = 0;
};

// Frames 0 (the spawn) to the last, stepping 1/fps s between them; every row to its file.
RowCounts simulate(const SimulateCommand& command, CrowdScene& scene, StreamedOutputs& files, Progress& progress) {
    std::vector<std::vector<std::string>> names;
    for (const motion::BakedClip& clip : scene.clipSpan()) {
        names.emplace_back();
        for (const std::string& name : clip.jointNames) names.back().push_back(csvField(name));
    }
    const bool jupedsim = command.format == SimulateCommand::Format::JuPedSim;
    CsvSink trajectories(files, 0, jupedsim ? jupedsimHeader(command.fps, scene.size(), command.crowd.trajectories.has_value()) : std::string(kTrajectoryHeader));
    std::optional<CsvSink> joints;
    if (command.jointsOut) joints.emplace(files, 1, kJointsHeader);
    std::vector<PreviousRow> previous(static_cast<std::size_t>(scene.size()));
    const double step = 1.0 / static_cast<double>(command.fps);
    for (std::int64_t frame = 0; frame <= command.lastFrame(); ++frame) {
        if (frame > 0) scene.step(step);
        const FrameStamp stamp{frame, static_cast<double>(frame) / static_cast<double>(command.fps), step};
        if (jupedsim) writeJuPedSim(trajectories, *scene.crowd, stamp);
        else writeTrajectories(trajectories, *scene.crowd, previous, stamp);
        if (joints) writeJoints(*joints, scene, names, stamp);
        progress.update(frame);
    }
    trajectories.flush();
    if (joints) joints->flush();
    return {trajectories.count(), joints ? joints->count() : 0};
}

std::optional<Error> checkOutputs(const SimulateCommand& command) {
    if (auto problem = checkOutputPath(command.out, "--out")) return problem;
    if (!command.jointsOut) return std::nullopt;
    if (auto problem = checkOutputPath(*command.jointsOut, "--joints-out")) return problem;
    if (sameFile(command.out, *command.jointsOut))
        return Error{Error::Kind::BadInput, "--out and --joints-out name the same file", {command.out, 0, 0}};
    return std::nullopt;
}

// Refuses, before anything is spawned, a run whose files would pass kMaxSimulateRows rows
// (--joints-out counted at the largest joint count of any clip). Counted in double: a scene's
// crowd times frames times joints can pass 64 bits.
std::optional<Error> checkRowCounts(const SimulateCommand& command, const CrowdScene& scene) {
    const std::string frames = std::to_string(scene.plannedCharacters()) + " characters x " + std::to_string(command.lastFrame() + 1) + " frames";
    const double rows = static_cast<double>(scene.plannedCharacters()) * static_cast<double>(command.lastFrame() + 1);
    const auto refuse = [](const std::string& what, double count, const char* option) -> std::optional<Error> {
        if (count <= static_cast<double>(kMaxSimulateRows)) return std::nullopt;
        char total[64];
        std::snprintf(total, sizeof total, "%.0f", count);
        return Error{Error::Kind::BadInput,
                     what + " make " + total + " rows for " + option + ", more than the " + std::to_string(kMaxSimulateRows) +
                         " a file may hold: shorten --time, lower --fps or simulate fewer characters (see 'throng simulate --help')",
                     {}};
    };
    if (auto problem = refuse(frames, rows, "--out")) return problem;
    if (!command.jointsOut) return std::nullopt;
    const std::uint32_t joints = scene.jointsPerCharacter();
    return refuse(frames + " x " + std::to_string(joints) + " joints", rows * joints, "--joints-out");
}

std::string summary(const SimulateCommand& command, const RowCounts& rows, int characters, double seconds) {
    const auto name = [](const std::string& path) { return path == "-" ? std::string("stdout") : path; };
    // A follower has rows only while its track lasts.
    const bool everyone = rows.trajectories == static_cast<std::int64_t>(characters) * (command.lastFrame() + 1);
    std::string text = "wrote " + name(command.out) + ": " + std::to_string(rows.trajectories) + " rows (" + std::to_string(characters) +
                       (characters == 1 ? " character x " : " characters x ") + std::to_string(command.lastFrame() + 1) + " frames" +
                       (everyone ? ")" : ", each while its track lasts)");
    if (command.jointsOut) text += " and " + name(*command.jointsOut) + ": " + std::to_string(rows.joints) + " rows";
    char timing[128];
    std::snprintf(timing, sizeof timing, "; %g s simulated at %d fps in %.2f s", command.time, command.fps, seconds);
    return text + timing;
}

}  // namespace

int runSimulate(const SimulateCommand& command) {
    if (auto problem = checkOutputs(command)) return reportError(*problem);
    auto prepared = prepareCrowdScene(command.crowd);
    if (!prepared) return reportError(prepared.error());
    CrowdScene& scene = prepared.value();
    if (auto tooMany = checkRowCounts(command, scene)) return reportError(*tooMany);
    Progress progress(command.lastFrame());
    if (auto spawned = scene.respawn(0.0); !spawned) return reportError(spawned.error());

    std::vector<std::string> paths{command.out};
    if (command.jointsOut) paths.push_back(*command.jointsOut);
    auto files = StreamedOutputs::open(paths);
    if (!files) return reportError(files.error());
    const RowCounts rows = simulate(command, scene, files.value(), progress);
    if (auto committed = files.value().commit(); !committed) return reportError(committed.error());
    log::report(summary(command, rows, scene.size(), progress.seconds()));
    return 0;
}

}  // namespace throng::app
