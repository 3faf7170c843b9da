// Reading trajectory files (trajectories.h): one pass over the lines, each row checked where
// it enters and appended to its person's track, so a million rows load in a fraction of a
// second and an error names the line and column it was found at.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "crowd_internal.h"
#include "throng/core/input_file.h"
#include "throng/core/supported_range.h"
#include "throng/crowd/trajectories.h"
#include "trajectory_text.h"

namespace throng::crowd {
namespace {

using namespace detail;

// Which field holds what (-1: none).
struct Columns {
    int id = -1, frame = -1, time = -1, x = -1, y = -1, z = -1, heading = -1;
    [[nodiscard]] int needed() const { return std::max({id, frame, time, x, y, z}) + 1; }
};

// The rows of a file, appended person by person: each row is checked against the one before it
// of the same person, so the file needs no sorting and a fault names both lines.
class TrackBuilder {
public:
    explicit TrackBuilder(std::string path) : path_(std::move(path)) {}

    // `frame` is -1 for a file that gives times instead of frame numbers.
    std::optional<Error> add(std::int64_t id, double time, std::int64_t frame, glm::dvec2 position, int line) {
        const auto [found, fresh] = index_.try_emplace(id, tracks_.size());
        if (fresh) {
            if (tracks_.size() >= static_cast<std::size_t>(range::kMaxCharacters))
                return fault(line, 1, "more than " + std::to_string(range::kMaxCharacters) + " people: Throng draws at most that many characters");
            tracks_.push_back({id, {}});
            lines_.push_back({line, line});
            frames_.push_back(frame);
        }
        const std::size_t t = found->second;
        Track& track = tracks_[t];
        if (!track.samples.empty()) {
            const double before = track.samples.back().time;
            const std::string who = "id " + std::to_string(id);
            const std::string previous = " (line " + std::to_string(lines_[t].last) + ")";
            const bool numbered = frame >= 0;
            const std::string at = numbered ? "frame " + std::to_string(frame) : "time " + shown(time);
            const std::string was = numbered ? "frame " + std::to_string(frames_[t]) : "time " + shown(before);
            if (time == before) return fault(line, 1, who + " has " + at + " twice" + previous + ": one row per person and sample");
            if (time < before)
                return fault(line, 1, who + " goes back in time: " + at + " comes after its " + was + previous +
                                          ": give each person's rows in time order");
            if (time - before < 1.0 / kMaxTrajectoryRate)
                return fault(line, 1, who + "'s samples on lines " + std::to_string(lines_[t].last) + " and " + std::to_string(line) +
                                          " are " + shown(time - before) + " s apart: closer than 1 ms (more than 1000 samples per second)");
        }
        track.samples.push_back({time, position});
        lines_[t].last = line;
        frames_[t] = frame;
        return std::nullopt;
    }

    // The tracks in ascending id, every one at least two samples long, timed from the earliest.
    Result<Trajectories> finish(std::string format, std::size_t rows, int lastLine) {
        if (tracks_.empty()) return fault(std::max(lastLine, 1), 1, "no trajectory rows: the file has a header but no samples");
        double start = tracks_.front().samples.front().time, end = start;
        std::size_t latest = 0;  // the track that ends last
        for (std::size_t t = 0; t < tracks_.size(); ++t) {
            const Track& track = tracks_[t];
            if (track.samples.size() < 2)
                return fault(lines_[t].first, 1, "id " + std::to_string(track.id) + " has one sample: a track needs two or more to move along");
            start = std::min(start, track.samples.front().time);
            if (track.samples.back().time > end) latest = t;
            end = std::max(end, track.samples.back().time);
        }
        // Times may be a clock's (Unix time, say): what is bounded is the span played.
        if (!(end - start <= kMaxTrajectoryTime))
            return fault(lines_[latest].last, 1, "the samples span " + shown(end - start) + " s, from " + shown(start) + " to " + shown(end) +
                                                     ": Throng reads at most " + shown(kMaxTrajectoryTime) +
                                                     " s (about 115 days) from the first sample to the last");
        Trajectories result;
        result.tracks = std::move(tracks_);
        for (Track& track : result.tracks)
            for (TrackSample& sample : track.samples) sample.time -= start;
        std::sort(result.tracks.begin(), result.tracks.end(), [](const Track& a, const Track& b) { return a.id < b.id; });
        result.format = std::move(format);
        result.startTime = start;
        result.duration = end - start;
        result.rows = rows;
        return result;
    }

    [[nodiscard]] Error fault(int line, int column, const std::string& message) const {
        return Error{Error::Kind::BadInput, message, {path_, line, column}};
    }

private:
    struct Lines {
        int first = 0, last = 0;
    };
    std::string path_;
    std::unordered_map<std::int64_t, std::size_t> index_;
    std::vector<Track> tracks_;
    std::vector<Lines> lines_;
    std::vector<std::int64_t> frames_;
};

// What the header and options settle before the rows are read.
struct Reading {
    Columns columns;
    bool csv = true;
    bool spaced = false;        // a header-led file whose fields are separated by spaces or tabs (Vadere's)
    bool namedColumns = false;  // the text layout's "#ID FR X Y ..." line named them
    bool ground_xz = false;
    double metresPerUnit = 1.0;
    std::optional<double> rate;  // samples per second, for numbered frames
    std::string description;
};

std::optional<Error> checkRate(const TrackBuilder& builder, double rate, int line, const std::string& from) {
    if (range::within(rate, kMinTrajectoryRate, kMaxTrajectoryRate)) return std::nullopt;
    return builder.fault(line, 1, from + " gives " + shown(rate) + " frames per second; Throng reads 1 to 1000");
}

// A header's column name as Throng reads it: lower case, Vadere's "-PID<n>" processor suffix
// dropped, and other tools' names for id, time, frame, x and y (Vadere's pedestrianId, simTime,
// timeStep, and a footstep's startX and startY) taken as those.
std::string columnName(std::string_view text) {
    std::string name = lower(text);
    const std::size_t suffix = name.rfind("-pid");
    if (suffix != std::string::npos && suffix + 4 < name.size() &&
        name.find_first_not_of("0123456789", suffix + 4) == std::string::npos)
        name.resize(suffix);
    if (name == "pedestrianid") return "id";
    if (name == "simtime") return "time";
    if (name == "timestep") return "frame";
    if (name == "startx") return "x";
    if (name == "starty") return "y";
    return name;
}

// The CSV header: every needed column named once.
std::optional<Error> readCsvHeader(const std::vector<Field>& fields, int line, const TrackBuilder& builder, Columns& columns) {
    if (!fields.empty() && parseReal(fields.front().text))
        return builder.fault(line, fields.front().column,
                             "the first line is data, not a header: a CSV needs one such as 'id,frame,x,y' or 'id,time,x,y,z' "
                             "(or use the '# ID FR X Y Z' text layout)");
    for (std::size_t f = 0; f < fields.size(); ++f) {
        const std::string name = columnName(fields[f].text);
        int* slot = name == "id" ? &columns.id : name == "frame" ? &columns.frame : name == "time" ? &columns.time
                  : name == "x" ? &columns.x : name == "y" ? &columns.y : name == "z" ? &columns.z
                  : name == "heading" ? &columns.heading : nullptr;
        if (slot == nullptr) continue;
        if (*slot >= 0) return builder.fault(line, fields[f].column, "the header names column '" + name + "' twice");
        *slot = static_cast<int>(f);
    }
    for (const auto& [slot, name] : {std::pair{columns.id, "id"}, {columns.x, "x"}, {columns.y, "y"}})
        if (slot < 0) return builder.fault(line, 1, std::string("the header has no '") + name + "' column: a CSV needs id, frame or time, x and y");
    if (columns.frame < 0 && columns.time < 0)
        return builder.fault(line, 1, "the header has neither a 'frame' nor a 'time' column: a CSV needs id, frame or time, x and y");
    return std::nullopt;
}

// The text layout's comment lines: the frame rate, the unit and the column names.
void readTextComment(std::string_view line, Reading& reading, std::optional<double>& headerRate, std::optional<double>& headerUnit,
                     int number, int& rateLine) {
    const std::string text = lower(line);
    std::vector<Field> tokens;
    splitWhitespace(line.substr(1), tokens);
    if (text.find("framerate") != std::string::npos && !headerRate)
        for (const Field& token : tokens)
            if (const std::optional<double> value = parseReal(token.text)) {
                headerRate = value;
                rateLine = number;
                break;
            }
    const auto says = [&](std::string_view what) { return text.find(what) != std::string::npos; };
    if (says("x/cm") || says("in cm")) headerUnit = 0.01;
    else if (says("x/mm") || says("in mm")) headerUnit = 0.001;
    else if (says("x/m") || says("in m")) headerUnit = 1.0;
    // "#ID FR X Y Z ...": the columns by name.
    if (tokens.size() >= 4 && lower(tokens[0].text) == "id" && lower(tokens[1].text) == "fr") {
        Columns columns;
        for (std::size_t f = 0; f < tokens.size(); ++f) {
            const std::string name = lower(tokens[f].text);
            int* slot = name == "id" ? &columns.id : name == "fr" ? &columns.frame : name == "x" ? &columns.x
                      : name == "y" ? &columns.y : name == "z" ? &columns.z : nullptr;
            if (slot != nullptr && *slot < 0) *slot = static_cast<int>(f);
        }
        if (columns.x >= 0 && columns.y >= 0) {
            reading.columns = columns;
            reading.namedColumns = true;
        }
    }
}

// One row after another, each checked where it enters and handed to the builder.
struct RowReader {
    const Reading& reading;
    TrackBuilder& builder;
    bool numbered;
    std::size_t rows = 0;
    std::vector<Field> fields;

    std::optional<Error> whole(int number, int index, const char* what, std::int64_t lo, std::int64_t hi, std::int64_t& out) const {
        const Field& field = fields[static_cast<std::size_t>(index)];
        const std::optional<std::int64_t> value = parseWhole(field.text);
        if (!value || *value < lo || *value > hi)
            return builder.fault(number, field.column, std::string(what) + " '" + excerpt(field.text) + "' is not a whole number from " +
                                                           std::to_string(lo) + " to " + std::to_string(hi));
        out = *value;
        return std::nullopt;
    }

    std::optional<Error> real(int number, int index, const char* what, double limit, double scale, double& out) const {
        const Field& field = fields[static_cast<std::size_t>(index)];
        const std::optional<double> value = parseReal(field.text);
        if (!value) return builder.fault(number, field.column, std::string(what) + " '" + excerpt(field.text) + "' is not a finite number");
        out = *value * scale;
        if (!(std::abs(out) <= limit))
            return builder.fault(number, field.column, std::string(what) + " " + excerpt(field.text) + " is out of range: at most " +
                                                           shown(limit) + (scale == 1.0 ? "" : " after the unit"));
        return std::nullopt;
    }

    std::optional<Error> read(std::string_view row, int number) {
        const Columns& c = reading.columns;
        if (reading.csv && !reading.spaced) splitCsv(row, fields);
        else splitWhitespace(row, fields);
        if (static_cast<int>(fields.size()) < c.needed())
            return builder.fault(number, static_cast<int>(row.size()) + 1,
                                 "the row has " + std::to_string(fields.size()) + " fields; " +
                                     (reading.csv ? "the header names " : "the layout needs ") + std::to_string(c.needed()));
        std::int64_t id = 0, frame = -1;
        double time = 0.0, x = 0.0, ground = 0.0;
        if (auto bad = whole(number, c.id, "id", -(std::int64_t{1} << 53), std::int64_t{1} << 53, id)) return bad;
        if (numbered) {
            if (auto bad = whole(number, c.frame, "frame", 0, kMaxTrajectoryFrame, frame)) return bad;
            time = static_cast<double>(frame) / *reading.rate;
        } else if (auto bad = real(number, c.time, "time", kMaxTrajectoryClock, 1.0, time)) {
            return bad;
        }
        if (auto bad = real(number, c.x, "x", range::kMaxCoordinate, reading.metresPerUnit, x)) return bad;
        const int groundColumn = reading.ground_xz ? c.z : c.y;
        if (auto bad = real(number, groundColumn, reading.ground_xz ? "z" : "y", range::kMaxCoordinate, reading.metresPerUnit, ground))
            return bad;
        ++rows;
        return builder.add(id, time, frame, reading.ground_xz ? glm::dvec2(x, ground) : glm::dvec2(x, -ground), number);
    }
};

// What was detected, for the user.
std::string describeFormat(const Reading& reading, bool numbered) {
    std::string format = reading.csv ? std::string(reading.spaced ? "columns separated by spaces" : "CSV") + " (id, " +
                                           std::string(numbered ? "frame" : "time") + ", x, " + (reading.ground_xz ? "z" : "y") + ")"
                                     : std::string("JuPedSim/PedPy text (ID FR X Y)");
    format += std::string("; ground plane ") + (reading.ground_xz ? "x,z" : "x,y") + "; ";
    format += reading.metresPerUnit == 1.0 ? "metres" : reading.metresPerUnit == 0.01 ? "centimetres" : reading.metresPerUnit == 0.001 ? "millimetres"
                                                                                                      : shown(reading.metresPerUnit) + " m per unit";
    if (numbered) format += "; " + shown(*reading.rate) + " frames per second";
    return format;
}

}  // namespace

const char* trajectoryAxesName(TrajectoryAxes axes) {
    switch (axes) {
        case TrajectoryAxes::Auto: return "auto";
        case TrajectoryAxes::Xy: return "xy";
        case TrajectoryAxes::Xz: return "xz";
    }
    return "?";
}

Result<Trajectories> readTrajectories(const std::string& path, const TrajectoryOptions& options) {
    auto text = readInputFile(path, kMaxTrajectoryBytes, "trajectory file");
    if (!text) return text.error();
    return parseTrajectories(text.value(), path, options);
}

Result<Trajectories> parseTrajectories(std::string_view text, const std::string& path, const TrajectoryOptions& options) {
    // A UTF-8 byte-order mark (spreadsheets' "CSV UTF-8") is not part of the first column's name.
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) text.remove_prefix(kByteOrderMark.size());
    Lines lines(text);
    std::string_view line;
    // The first line that is not blank says the layout.
    while (lines.next(line) && blankLine(line)) {}
    if (lines.number() == 0 || blankLine(line))
        return Error{Error::Kind::BadInput, "the trajectory file is empty: it needs a header and rows", {path, std::max(lines.number(), 1), 1}};
    Reading reading;
    reading.csv = line.front() != '#';
    std::vector<Field> fields;
    std::optional<double> headerRate, headerUnit;
    int rateLine = 1;
    const int headerLine = lines.number();
    TrackBuilder builder(path);
    if (reading.csv) {
        // A header with no comma but with spaces or tabs leads a file separated by them (Vadere's
        // postvis.traj: "pedestrianId simTime endTime-PID1 startX-PID1 startY-PID1 ...").
        reading.spaced = line.find(',') == std::string_view::npos && line.find_first_of(" \t") != std::string_view::npos;
        if (reading.spaced) splitWhitespace(line, fields);
        else splitCsv(line, fields);
        if (auto bad = readCsvHeader(fields, headerLine, builder, reading.columns)) return *bad;
    } else {
        // PedPy's order when no column line names them: ID FR X Y, then Z (a level's height) only
        // where it is the ground's second axis (--trajectory-axes xz), so rows of four fields read.
        reading.columns = {.id = 0, .frame = 1, .x = 2, .y = 3};
        // Comments up to the first row; the row itself is read below.
        do {
            if (!blankLine(line) && line.front() == '#') readTextComment(line, reading, headerRate, headerUnit, lines.number(), rateLine);
        } while ((blankLine(line) || line.front() == '#') && lines.next(line));
    }
    const bool numbered = reading.csv ? reading.columns.time < 0 : true;
    // Ground axes: Throng's own CSV (it writes a heading) is Y up; other tools' z is height.
    const TrajectoryAxes axes = options.axes != TrajectoryAxes::Auto ? options.axes
                              : reading.columns.heading >= 0     ? TrajectoryAxes::Xz
                                                                 : TrajectoryAxes::Xy;
    reading.ground_xz = axes == TrajectoryAxes::Xz;
    if (!reading.csv && !reading.namedColumns && reading.ground_xz) reading.columns.z = 4;
    if (reading.ground_xz && reading.columns.z < 0)
        return builder.fault(headerLine, 1, "the ground plane is x,z (--trajectory-axes xz) but the file has no z column");
    reading.metresPerUnit = options.metresPerUnit.value_or(headerUnit.value_or(1.0));
    if (numbered) {
        if (options.framesPerSecond) {
            reading.rate = options.framesPerSecond;
            if (auto bad = checkRate(builder, *reading.rate, headerLine, "--trajectory-fps")) return *bad;
        } else if (headerRate) {
            reading.rate = headerRate;
            if (auto bad = checkRate(builder, *reading.rate, rateLine, "the framerate line")) return *bad;
        } else {
            return builder.fault(headerLine, 1, std::string("the file numbers frames but gives no frame rate: ") +
                                                    (reading.csv ? "add a 'time' column or give --trajectory-fps N"
                                                                 : "add a '#framerate: N' line or give --trajectory-fps N"));
        }
    }
    RowReader reader{reading, builder, numbered, 0, {}};
    const auto readRow = [&](std::string_view row) { return reader.read(row, lines.number()); };
    // A CSV's rows start after its header; the text layout's first row is the line in hand.
    if (!reading.csv && !blankLine(line) && line.front() != '#')
        if (auto bad = readRow(line)) return *bad;
    while (lines.next(line)) {
        if (blankLine(line) || (!reading.csv && line.front() == '#')) continue;
        if (auto bad = readRow(line)) return *bad;
    }
    std::string format = describeFormat(reading, numbered);
    return builder.finish(std::move(format), reader.rows, lines.number());
}

}  // namespace throng::crowd
