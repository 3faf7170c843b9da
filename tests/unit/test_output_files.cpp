// Input files that are not regular files, and outputs written atomically: devices and FIFOs
// in place (never replaced), several outputs all or nothing, no temporary left behind by a
// failure or a signal. Device outputs go through symbolic links of our own, so a writer that
// wrongly replaced its target would replace the link, never /dev/null (tests may run as root).
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "throng/core/atomic_file.h"
#include "throng/core/input_file.h"

namespace {

namespace fs = std::filesystem;
using throng::Error;

class OutputFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("throng-output-files-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    [[nodiscard]] std::string at(const std::string& name) const { return (dir_ / name).string(); }
    // Names in the directory other than `keep`.
    [[nodiscard]] std::vector<std::string> others(const std::vector<std::string>& keep) const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_))
            if (std::find(keep.begin(), keep.end(), entry.path().filename().string()) == keep.end())
                names.push_back(entry.path().filename().string());
        return names;
    }
    fs::path dir_;
};

TEST_F(OutputFiles, DevNullIsWrittenInPlaceNotReplaced) {
    fs::create_symlink("/dev/null", at("null"));
    ASSERT_TRUE(throng::writeFileAtomically(at("null"), "bytes").ok());
    EXPECT_TRUE(fs::is_symlink(at("null")));
    EXPECT_TRUE(fs::is_character_file(at("null")));
    EXPECT_TRUE(others({"null"}).empty());
}

TEST_F(OutputFiles, DevFullFailsWithTheDevicesErrorAndLeavesNothing) {
    fs::create_symlink("/dev/full", at("full"));
    auto written = throng::writeFileAtomically(at("full"), "bytes");
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().kind, Error::Kind::BadInput);
    EXPECT_NE(written.error().message.find("No space left on device"), std::string::npos) << written.error().message;
    EXPECT_EQ(written.error().location.file, at("full"));
    EXPECT_TRUE(fs::is_symlink(at("full")));
    EXPECT_TRUE(others({"full"}).empty());
}

TEST_F(OutputFiles, SeveralOutputsAreAllOrNothing) {
    fs::create_symlink("/dev/full", at("full"));
    const std::vector<throng::OutputFile> outputs{{at("a.json"), "first"}, {at("full"), "second"}, {at("b.png"), "third"}};
    EXPECT_FALSE(throng::writeFilesAtomically(outputs).ok());
    EXPECT_TRUE(others({"full"}).empty());  // neither regular output, no temporary
    const std::vector<throng::OutputFile> good{{at("a.json"), "first"}, {at("b.png"), "third"}};
    ASSERT_TRUE(throng::writeFilesAtomically(good).ok());
    EXPECT_EQ(fs::file_size(at("a.json")), 5U);
    EXPECT_EQ(fs::file_size(at("b.png")), 5U);
    EXPECT_TRUE(others({"a.json", "b.png", "full"}).empty());
}

TEST_F(OutputFiles, DashIsStandardOutput) {
    ::testing::internal::CaptureStdout();
    const auto written = throng::writeFileAtomically("-", "to stdout");
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "to stdout");
    EXPECT_TRUE(written.ok());
    EXPECT_FALSE(throng::writeFileAtomically("", "x").ok());
}

TEST_F(OutputFiles, FifoIsWrittenInPlace) {
    ASSERT_EQ(::mkfifo(at("fifo").c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] {
        std::ifstream in(at("fifo"));
        received.assign(std::istreambuf_iterator<char>(in), {});
    });
    EXPECT_TRUE(throng::writeFileAtomically(at("fifo"), "through a pipe").ok());
    reader.join();
    EXPECT_EQ(received, "through a pipe");
    struct stat info {};
    ASSERT_EQ(::stat(at("fifo").c_str(), &info), 0);
    EXPECT_TRUE(S_ISFIFO(info.st_mode));
}

// Streamed outputs (throng simulate): bytes go to temporaries piece by piece, and the targets
// appear only at commit, together.
std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST_F(OutputFiles, StreamedOutputsAppearTogetherAtCommit) {
    const std::vector<std::string> paths{at("t.csv"), at("j.csv")};
    auto opened = throng::StreamedOutputs::open(paths);
    ASSERT_TRUE(opened.ok()) << opened.error().describe();
    throng::StreamedOutputs& files = opened.value();
    EXPECT_FALSE(files.writesInPlace(0));
    for (int piece = 0; piece < 3; ++piece) {
        ASSERT_TRUE(files.append(0, "row " + std::to_string(piece) + "\n").ok());
        ASSERT_TRUE(files.append(1, "joint\n").ok());
    }
    const std::vector<std::string> pending = others({});
    ASSERT_EQ(pending.size(), 2U);  // two temporaries, no target yet
    for (const std::string& name : pending) EXPECT_NE(name.find(".tmp-"), std::string::npos) << name;
    ASSERT_TRUE(files.commit().ok());
    EXPECT_EQ(contents(at("t.csv")), "row 0\nrow 1\nrow 2\n");
    EXPECT_EQ(contents(at("j.csv")), "joint\njoint\njoint\n");
    EXPECT_TRUE(others({"t.csv", "j.csv"}).empty());
    EXPECT_EQ(fs::status(at("t.csv")).permissions() & fs::perms::others_read, fs::perms::others_read);
}

TEST_F(OutputFiles, StreamedOutputsNotCommittedLeaveTheTargetsAsTheyWere) {
    ASSERT_TRUE(throng::writeFileAtomically(at("t.csv"), "old").ok());
    {
        const std::vector<std::string> paths{at("t.csv"), at("j.csv")};
        auto files = throng::StreamedOutputs::open(paths);
        ASSERT_TRUE(files.ok());
        ASSERT_TRUE(files.value().append(0, "new rows").ok());
        ASSERT_TRUE(files.value().append(1, "new joints").ok());
    }  // an error or an exception: destroyed before commit
    EXPECT_EQ(contents(at("t.csv")), "old");
    EXPECT_TRUE(others({"t.csv"}).empty());
}

TEST_F(OutputFiles, StreamedOutputToAFullDeviceFailsAtItsBytes) {
    fs::create_symlink("/dev/full", at("full"));
    {
        const std::vector<std::string> paths{at("t.csv"), at("full")};
        auto files = throng::StreamedOutputs::open(paths);
        ASSERT_TRUE(files.ok());
        EXPECT_TRUE(files.value().writesInPlace(1));
        ASSERT_TRUE(files.value().append(0, "rows").ok());
        const auto written = files.value().append(1, "joints");
        ASSERT_FALSE(written.ok());
        EXPECT_EQ(written.error().kind, Error::Kind::BadInput);
        EXPECT_NE(written.error().message.find("No space left on device"), std::string::npos) << written.error().message;
    }
    EXPECT_TRUE(others({"full"}).empty());
    const std::vector<std::string> empty{at("a.csv"), ""};
    EXPECT_FALSE(throng::StreamedOutputs::open(empty).ok());
    EXPECT_TRUE(others({"full"}).empty());
}

// The child writes a PNG's temporary, then blocks opening a FIFO nobody reads; the signal
// must remove the temporary and still end the process.
TEST_F(OutputFiles, SignalsRemovePendingTemporaries) {
    for (const int signal : {SIGTERM, SIGINT, SIGHUP, SIGPIPE}) {
        SCOPED_TRACE(signal);
        fs::remove(at("fifo"));
        ASSERT_EQ(::mkfifo(at("fifo").c_str(), 0600), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            std::signal(signal, SIG_DFL);
            const std::vector<throng::OutputFile> outputs{{at("out.png"), "png bytes"}, {at("fifo"), "dump"}};
            (void)throng::writeFilesAtomically(outputs);
            ::_exit(0);
        }
        bool pending = false;
        for (int i = 0; i < 400 && !pending; ++i) {
            pending = !others({"fifo"}).empty();
            if (!pending) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        EXPECT_TRUE(pending);
        ::kill(child, signal);
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << status;
        EXPECT_TRUE(others({"fifo"}).empty());
    }
}

TEST_F(OutputFiles, InputsThatAreNotRegularFilesAreRefusedWithoutBlocking) {
    ASSERT_EQ(::mkfifo(at("fifo").c_str(), 0600), 0);
    fs::create_symlink("loop_b", at("loop_a"));
    fs::create_symlink("loop_a", at("loop_b"));
    const std::string longName = at(std::string(300, 'n') + ".bvh");
    const std::pair<std::string, std::string> cases[] = {
        {at("fifo"), "not a regular file"},       {"/dev/zero", "not a regular file"},
        {dir_.string(), "it is a directory"},      {at("loop_a"), "Too many levels of symbolic links"},
        {longName, "File name too long"},          {at("missing"), "no such file"},
    };
    for (const auto& [path, why] : cases) {
        auto read = throng::readInputFile(path, 1 << 20, "test file");
        ASSERT_FALSE(read.ok()) << path;
        EXPECT_EQ(read.error().kind, Error::Kind::BadInput);
        EXPECT_EQ(read.error().location.file, path);
        EXPECT_NE(read.error().message.find(why), std::string::npos) << read.error().message;
    }
    ASSERT_TRUE(throng::writeFileAtomically(at("big"), std::string(100, 'x')).ok());
    EXPECT_FALSE(throng::readInputFile(at("big"), 99, "test file").ok());
    EXPECT_EQ(throng::readInputFile(at("big"), 100, "test file").value().size(), 100U);
}

}  // namespace
