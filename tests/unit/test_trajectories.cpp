// Reading trajectory files (crowd/trajectories.h): each layout from a small hand-written file
// whose positions are stated here, and every kind of bad file refused with its line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "throng/crowd/trajectories.h"

namespace {

using namespace throng;
using crowd::parseTrajectories;
using crowd::TrajectoryAxes;
using crowd::TrajectoryOptions;

TrajectoryOptions atRate(double framesPerSecond) {
    TrajectoryOptions options;
    options.framesPerSecond = framesPerSecond;
    return options;
}
TrajectoryOptions onAxes(TrajectoryAxes axes) {
    TrajectoryOptions options;
    options.axes = axes;
    return options;
}
TrajectoryOptions inUnits(double metresPerUnit) {
    TrajectoryOptions options;
    options.metresPerUnit = metresPerUnit;
    return options;
}

crowd::Trajectories read(const std::string& text, const TrajectoryOptions& options = {}) {
    auto result = parseTrajectories(text, "t.csv", options);
    if (!result) ADD_FAILURE() << result.error().describe();
    return result ? result.value() : crowd::Trajectories{};
}

void expectSample(const crowd::Track& track, std::size_t k, double time, double x, double z) {
    ASSERT_LT(k, track.samples.size());
    EXPECT_NEAR(track.samples[k].time, time, 1e-12) << "sample " << k << " of id " << track.id;
    EXPECT_NEAR(track.samples[k].position.x, x, 1e-12) << "sample " << k << " of id " << track.id;
    EXPECT_NEAR(track.samples[k].position.y, z, 1e-12) << "sample " << k << " of id " << track.id;
}

TEST(Trajectories, CsvWithTimeOnTheXyPlaneTurnsYIntoMinusZAndStartsTimeAtTheFirstSample) {
    // Rows of two people interleaved, as simulators write them; time starts at 10 s.
    const crowd::Trajectories t = read("id,time,x,y\n5,10.0,1,2\n3,10.0,0,0\n5,10.5,1.5,2\n3,10.5,0,-1\n3,11,0,-2\n");
    ASSERT_EQ(t.tracks.size(), 2U);
    EXPECT_EQ(t.tracks[0].id, 3);
    EXPECT_EQ(t.tracks[1].id, 5);
    expectSample(t.tracks[0], 0, 0.0, 0.0, 0.0);
    expectSample(t.tracks[0], 1, 0.5, 0.0, 1.0);
    expectSample(t.tracks[0], 2, 1.0, 0.0, 2.0);
    expectSample(t.tracks[1], 0, 0.0, 1.0, -2.0);
    expectSample(t.tracks[1], 1, 0.5, 1.5, -2.0);
    EXPECT_DOUBLE_EQ(t.startTime, 10.0);
    EXPECT_DOUBLE_EQ(t.duration, 1.0);
    EXPECT_EQ(t.rows, 5U);
    EXPECT_NE(t.format.find("CSV (id, time, x, y)"), std::string::npos) << t.format;
}

TEST(Trajectories, CsvWithFramesNeedsARateAndMayGiveColumnsInAnyOrderWithSpacesAndExtras) {
    const std::string text = "x , id, note, frame, y\n1,7,a,0,0\n2,7,b,5,0\n3.5, 7 ,c,10,1\n";
    EXPECT_FALSE(parseTrajectories(text, "t.csv", {}).ok());
    const crowd::Trajectories t = read(text, atRate(10.0));
    ASSERT_EQ(t.tracks.size(), 1U);
    expectSample(t.tracks[0], 0, 0.0, 1.0, 0.0);
    expectSample(t.tracks[0], 1, 0.5, 2.0, 0.0);
    expectSample(t.tracks[0], 2, 1.0, 3.5, -1.0);
}

TEST(Trajectories, TheXzPlaneKeepsZAndThrongsOwnCsvIsReadAsXzWithoutBeingTold) {
    const std::string own = "id,frame,time,x,y,z,heading,speed\n0,0,0.0,1,0,2,0,0\n0,1,0.1,1,0,2.5,0,5\n";
    const crowd::Trajectories t = read(own);
    expectSample(t.tracks[0], 1, 0.1, 1.0, 2.5);
    EXPECT_NE(t.format.find("ground plane x,z"), std::string::npos) << t.format;
    // Another tool's x,y,z (z is height) is read on x,y unless told otherwise.
    const std::string other = "id,time,x,y,z\n1,0,1,2,9\n1,1,2,4,9\n";
    expectSample(read(other).tracks[0], 1, 1.0, 2.0, -4.0);
    expectSample(read(other, onAxes(TrajectoryAxes::Xz)).tracks[0], 1, 1.0, 2.0, 9.0);
    expectSample(read(own, onAxes(TrajectoryAxes::Xy)).tracks[0], 1, 0.1, 1.0, 0.0);
}

TEST(Trajectories, TheJuPedSimTextLayoutTakesItsRateAndUnitFromTheHeader) {
    const std::string text =
        "#description: corridor\n#framerate: 16.00\n#unit: x/cm\n#ID: the agent ID\n#FR: the current frame\n"
        "#ID\tFR\tX\tY\tZ\tA\tB\tANGLE\tCOLOR\n"
        "1\t0\t100\t200\t30\t0.2\t0.2\t0\t255\n2\t0\t0\t0\t30\t0.2\t0.2\t0\t255\n"
        "1\t8\t150\t200\t30\t0.2\t0.2\t0\t255\n2\t8\t0\t-50\t30\t0.2\t0.2\t0\t255\n";
    const crowd::Trajectories t = read(text);
    ASSERT_EQ(t.tracks.size(), 2U);
    expectSample(t.tracks[0], 0, 0.0, 1.0, -2.0);
    expectSample(t.tracks[0], 1, 0.5, 1.5, -2.0);
    expectSample(t.tracks[1], 1, 0.5, 0.0, 0.5);
    EXPECT_NE(t.format.find("JuPedSim"), std::string::npos) << t.format;
    EXPECT_NE(t.format.find("centimetres"), std::string::npos) << t.format;
    EXPECT_NE(t.format.find("16 frames per second"), std::string::npos) << t.format;
    // Without a column line: PedPy's order ID FR X Y Z; the unit option overrides the header.
    const crowd::Trajectories plain = read("# framerate: 2\n1 0 1 1 0\n1 1 3 1 0\n", inUnits(0.001));
    expectSample(plain.tracks[0], 1, 0.5, 0.003, -0.001);
    // Z is optional there: rows of ID FR X Y read, unless Z is the ground's second axis.
    const std::string four = "#framerate: 8\n1 0 0 0\n1 8 1 2\n";
    expectSample(read(four).tracks[0], 1, 1.0, 1.0, -2.0);
    const auto needsZ = parseTrajectories(four, "t.txt", onAxes(TrajectoryAxes::Xz));
    ASSERT_FALSE(needsZ.ok());
    EXPECT_NE(needsZ.error().describe().find("t.txt:2:8: error: the row has 4 fields; the layout needs 5"), std::string::npos)
        << needsZ.error().describe();
    expectSample(read("#framerate: 8\n1 0 0 0 5\n1 8 1 2 6\n", onAxes(TrajectoryAxes::Xz)).tracks[0], 1, 1.0, 1.0, 6.0);
}

TEST(Trajectories, ANumberTooSmallForADoubleIsZeroAndOneTooLargeIsRefusedQuotingItShort) {
    // 1e-400 and 0.000...1 underflow to 0, as strtod and spreadsheets read them; 1e400 does not.
    const crowd::Trajectories t = read("id,time,x,y\n1,0,1e-400,-1e-400\n1,1,0." + std::string(400, '0') + "1,2\n");
    expectSample(t.tracks[0], 0, 0.0, 0.0, 0.0);
    expectSample(t.tracks[0], 1, 1.0, 0.0, -2.0);
    const auto huge = parseTrajectories("id,time,x,y\n1,0,1e400,0\n", "t.csv", {});
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(huge.error().describe().find("x '1e400' is not a finite number"), std::string::npos) << huge.error().describe();
    // A negative exponent does not make a number small: 1 and 400 zeros, e-1, is 1e399.
    EXPECT_FALSE(parseTrajectories("id,time,x,y\n1,0,1" + std::string(400, '0') + "e-1,0\n", "t.csv", {}).ok());
    EXPECT_FALSE(parseTrajectories("id,time,x,y\n1,0,0.0001e400,0\n", "t.csv", {}).ok());
    // A field of a megabyte is quoted by its first 48 bytes, not echoed whole.
    const auto long_field = parseTrajectories("id,time,x,y\n1,0," + std::string(1 << 20, '7') + "x,0\n", "t.csv", {});
    ASSERT_FALSE(long_field.ok());
    EXPECT_LT(long_field.error().describe().size(), 200U);
    EXPECT_NE(long_field.error().describe().find("x '" + std::string(48, '7') + "...' is not a finite number"), std::string::npos);
}

TEST(Trajectories, VaderesFootstepsReadFromTheirSpaceSeparatedColumns) {
    // postvis.traj: a row per footstep, from (startX, startY) at simTime; ids in any order.
    const crowd::Trajectories t = read(
        "pedestrianId simTime endTime-PID1 startX-PID1 startY-PID1 endX-PID1 endY-PID1 targetId-PID2\n"
        "1 0.0 0.5 1.0 2.0 1.5 2.0 1\n2 0.2 0.7 5.0 5.0 5.0 5.6 1\n1 0.5 1.0 1.5 2.0 2.0 2.0 1\n2 0.7 1.2 5.0 5.6 5.0 6.2 1\n");
    ASSERT_EQ(t.tracks.size(), 2U);
    expectSample(t.tracks[0], 0, 0.0, 1.0, -2.0);
    expectSample(t.tracks[0], 1, 0.5, 1.5, -2.0);
    expectSample(t.tracks[1], 0, 0.2, 5.0, -5.0);
    expectSample(t.tracks[1], 1, 0.7, 5.0, -5.6);
    EXPECT_NE(t.format.find("columns separated by spaces (id, time, x, y)"), std::string::npos) << t.format;
    // Vadere's older per-step positions: timeStep pedestrianId x-PID1 y-PID1, at a given rate.
    const crowd::Trajectories steps = read("timeStep pedestrianId x-PID1 y-PID1\n1 4 0.0 0.0\n2 4 0.4 0.0\n", atRate(2.5));
    expectSample(steps.tracks[0], 1, 0.4, 0.4, 0.0);
}

TEST(Trajectories, PositionsBetweenSamplesFollowASmoothCurveThatIsExactAtSamplesAndOnStraightLines) {
    const crowd::Trajectories t = read("id,time,x,y\n1,0,0,0\n1,1,1.2,0\n1,2,2.4,0\n1,4,4.8,0\n");
    const crowd::Track& track = t.tracks[0];
    for (double time : {0.0, 0.3, 1.0, 1.7, 2.9, 4.0}) {
        const glm::dvec2 p = crowd::trackPosition(track, time);
        EXPECT_NEAR(p.x, 1.2 * time, 1e-12) << time;
        EXPECT_NEAR(p.y, 0.0, 1e-12) << time;
    }
    EXPECT_EQ(crowd::trackPosition(track, -1.0), track.samples.front().position);
    EXPECT_EQ(crowd::trackPosition(track, 9.0), track.samples.back().position);
}

TEST(Trajectories, TheCurveNeverOvershootsIntoAStopOrPastASuddenMove) {
    // 10 m in 1 s, then standing for 100 s; and a walk that stops dead at a sample.
    const crowd::Trajectories t = read("id,time,x,y\n1,0,0,0\n1,1,10,0\n1,101,10,0\n2,0,0,0\n2,1,1,0\n2,2,2,0\n2,3,2,0\n");
    for (const crowd::Track& track : t.tracks)
        for (double time = 0.0; time <= track.samples.back().time; time += 0.05) {
            const glm::dvec2 p = crowd::trackPosition(track, time);
            const double end = track.samples.back().position.x;
            EXPECT_LE(p.x, end + 1e-9) << "id " << track.id << " at " << time << " s";
            EXPECT_GE(p.x, -1e-9) << "id " << track.id << " at " << time << " s";
        }
}

TEST(Trajectories, SpreadsheetCsvReadsAsWritten) {
    // R's write.csv quotes names (and a note may hold commas); Excel's "CSV UTF-8" starts with
    // a byte-order mark. Both read as the plain file does.
    const std::string plain = "id,time,x,y\n1,0,0,0\n1,1,2,0\n";
    for (const std::string& text : {std::string("\xEF\xBB\xBF") + plain,
                                    std::string("\"id\",\"time\",\"x\",\"y\",\"note\"\n\"1\",0,0,0,\"Smith, J\"\n1, \"1\" ,2,0,\"say \"\"hi\"\"\"\n")}) {
        const crowd::Trajectories t = read(text);
        ASSERT_EQ(t.tracks.size(), 1U) << text;
        EXPECT_EQ(t.tracks[0].id, 1);
        expectSample(t.tracks[0], 0, 0.0, 0.0, 0.0);
        expectSample(t.tracks[0], 1, 1.0, 2.0, 0.0);
    }
    // An error on the first line counts columns from after the mark, as an editor shows them.
    auto bad = parseTrajectories("\xEF\xBB\xBFid,time,x\n", "bom.csv", {});
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("no 'y' column"), std::string::npos) << bad.error().describe();
}

TEST(Trajectories, TimesMayBeAClocksAsLongAsTheSpanPlayedIsBounded) {
    // Unix time in seconds, as loggers write it: time 0 is the first sample.
    const crowd::Trajectories t = read("id,time,x,y\n1,1764400000.0,0,0\n1,1764400000.5,1,0\n1,1764400001.0,2,0\n");
    ASSERT_EQ(t.tracks.size(), 1U);
    EXPECT_DOUBLE_EQ(t.startTime, 1764400000.0);
    EXPECT_DOUBLE_EQ(t.duration, 1.0);
    expectSample(t.tracks[0], 1, 0.5, 1.0, 0.0);
    expectSample(t.tracks[0], 2, 1.0, 2.0, 0.0);
}

struct BadFile {
    const char* what;
    std::string text;
    int line, column;
    const char* says;
    TrajectoryOptions options{};
};

TEST(Trajectories, EveryKindOfBadFileIsRefusedNamingItsLineAndColumn) {
    const BadFile cases[] = {
        {"empty", "\n  \n", 2, 1, "empty", {}},
        {"no header", "1,0,0,0\n1,1,1,0\n", 1, 1, "not a header", {}},
        {"missing column", "id,time,x\n1,0,0\n", 1, 1, "no 'y' column", {}},
        {"neither frame nor time", "id,x,y\n1,0,0\n", 1, 1, "neither a 'frame' nor a 'time'", {}},
        {"column twice", "id,time,x,y,x\n", 1, 13, "'x' twice", {}},
        {"row with fields missing", "id,time,x,y\n1,0,0,0\n1,1,2\n", 3, 6, "has 3 fields", {}},
        {"not a number", "id,time,x,y\n1,0,0,0\n1,1,abc,0\n", 3, 5, "'abc' is not a finite number", {}},
        {"NaN", "id,time,x,y\n1,0,0,0\n1,1,0,nan\n", 3, 7, "'nan' is not a finite number", {}},
        {"infinity", "id,time,x,y\n1,0,0,0\n1,inf,0,0\n", 3, 3, "'inf' is not a finite number", {}},
        {"coordinate out of range", "id,time,x,y\n1,0,0,0\n1,1,0,1e39\n", 3, 7, "out of range", {}},
        {"id not whole", "id,time,x,y\n1.5,0,0,0\n", 2, 1, "id '1.5' is not a whole number", {}},
        {"negative frame", "id,frame,x,y\n1,-3,0,0\n", 2, 3, "frame '-3' is not a whole number", atRate(10.0)},
        {"duplicate (id, frame)", "id,frame,x,y\n1,0,0,0\n2,0,0,0\n1,0,1,1\n", 4, 1, "id 1 has frame 0 twice (line 2)",
         atRate(10.0)},
        {"unsorted frames", "id,frame,x,y\n1,5,0,0\n1,3,1,1\n", 3, 1, "goes back in time: frame 3 comes after its frame 5 (line 2)",
         atRate(10.0)},
        {"one-sample track", "id,time,x,y\n1,0,0,0\n2,0,0,0\n1,1,1,1\n", 3, 1, "id 2 has one sample", {}},
        {"samples under 1 ms apart", "id,time,x,y\n1,0,0,0\n1,0.0001,1,1\n", 3, 1, "closer than 1 ms", {}},
        {"no frame rate", "# ID FR X Y Z\n1 0 0 0 0\n1 1 1 1 0\n", 1, 1, "gives no frame rate", {}},
        {"frame rate out of range", "#framerate: 5000\n1 0 0 0 0\n1 1 1 1 0\n", 1, 1, "5000 frames per second", {}},
        {"time out of range", "id,time,x,y\n1,0,0,0\n1,1e12,0,0\n", 3, 3, "out of range", {}},
        {"span over 115 days", "id,time,x,y\n1,0,0,0\n2,5,0,0\n1,1,0,1\n2,2e7,1,1\n", 5, 1, "the samples span 2e+07 s", {}},
        {"frames spanning over 115 days", "id,frame,x,y\n1,0,0,0\n1,20000000,0,1\n", 3, 1, "the samples span 2e+07 s", atRate(1.0)},
        {"quoted field left open", "id,time,x,y\n1,0,0,0\n1,\"1,0,1\n", 3, 9, "the row has 2 fields", {}},
        {"text after a closing quote", "id,time,x,y\n1,0,0,0\n1,\"1\"5,0,1\n", 3, 3, "time '\"1\"5' is not a finite number", {}},
        {"header but no rows", "id,time,x,y\n\n", 2, 1, "no trajectory rows", {}},
        {"xz without z", "id,time,x,y\n1,0,0,0\n", 1, 1, "no z column", onAxes(TrajectoryAxes::Xz)},
    };
    for (const BadFile& bad : cases) {
        auto result = parseTrajectories(bad.text, "bad.csv", bad.options);
        ASSERT_FALSE(result.ok()) << bad.what;
        const Error& error = result.error();
        EXPECT_EQ(error.kind, Error::Kind::BadInput) << bad.what;
        EXPECT_EQ(error.location.file, "bad.csv") << bad.what;
        EXPECT_EQ(error.location.line, bad.line) << bad.what << ": " << error.describe();
        EXPECT_EQ(error.location.column, bad.column) << bad.what << ": " << error.describe();
        EXPECT_NE(error.message.find(bad.says), std::string::npos) << bad.what << ": " << error.describe();
    }
}

TEST(Trajectories, AMissingFileOrAFolderIsRefusedNamingIt) {
    for (const char* path : {"/nonexistent/tracks.csv", "/tmp"}) {
        auto result = crowd::readTrajectories(path, {});
        ASSERT_FALSE(result.ok());
        EXPECT_NE(result.error().describe().find(path), std::string::npos) << result.error().describe();
    }
}

}  // namespace
