// Per-clip bake overrides: `--bvh FILE:key=value,...` on the command line (render, demo,
// bench), the same overrides as fields of a scene file's clips, and `bvh info`'s options for
// the up axis, travel joint, straightening and foot lock.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <variant>
#include <vector>

#include "clip_spec.h"
#include "scene_file.h"
#include "throng/app/cli.h"

namespace {

using throng::Error;
using throng::app::BenchCommand;
using throng::app::BvhInfoCommand;
using throng::app::ClipSpec;
using throng::app::DemoCommand;
using throng::app::parseCommandLine;
using throng::app::RenderCommand;
using throng::motion::PositionChannels;
using throng::motion::UpAxis;

using Args = std::vector<std::string>;

// The clips of `render --bvh ARG... --out x.png`; a failure to parse fails the test.
std::vector<ClipSpec> renderClips(std::initializer_list<std::string> bvh) {
    Args args{"render", "--out", "x.png"};
    for (const std::string& arg : bvh) args.insert(args.end(), {"--bvh", arg});
    auto result = parseCommandLine(args);
    if (!result.ok()) {
        ADD_FAILURE() << "refused: " << result.error().message;
        return {};
    }
    return std::get<RenderCommand>(result.value()).crowd.clips;
}

ClipSpec renderClip(const std::string& bvh) {
    const std::vector<ClipSpec> clips = renderClips({bvh});
    return clips.empty() ? ClipSpec{} : clips.front();
}

// Expects `render --bvh ARG` to be a usage error mentioning each of `words`.
void expectRefused(const std::string& bvh, std::initializer_list<const char*> words) {
    SCOPED_TRACE(bvh);
    auto result = parseCommandLine(Args{"render", "--bvh", bvh, "--out", "x.png"});
    ASSERT_FALSE(result.ok()) << "parsed, but should be refused";
    const Error& e = result.error();
    EXPECT_EQ(e.kind, Error::Kind::BadInput);
    EXPECT_NE(e.message.find("--bvh " + bvh + ": "), std::string::npos) << e.message;
    for (const char* word : words) EXPECT_NE(e.message.find(word), std::string::npos) << "'" << word << "' not in: " << e.message;
    EXPECT_NE(e.message.find("(see 'throng render --help')"), std::string::npos) << e.message;
    EXPECT_EQ(e.message.find('\n'), std::string::npos) << "one line: " << e.message;
}

// The options that units=0.01, up=z, root=Hips, loop 10..50, straighten on, foot lock off,
// position channels added and keep-first-frame on give, however they were written.
void expectEveryOverride(const throng::motion::BakeOptions& bake) {
    EXPECT_EQ(bake.metresPerUnit, std::optional<double>(0.01));
    EXPECT_EQ(bake.upAxis, std::optional<UpAxis>(UpAxis::PlusZ));
    EXPECT_EQ(bake.travelJoint, "Hips");
    ASSERT_TRUE(bake.loop.has_value());
    EXPECT_EQ(bake.loop->first, 10);
    EXPECT_EQ(bake.loop->last, 50);
    EXPECT_TRUE(bake.straighten);
    EXPECT_FALSE(bake.footLock);
    EXPECT_EQ(bake.positionChannels, PositionChannels::Add);
    EXPECT_EQ(bake.skipFirstFrame, std::optional<bool>(false));
}

// --- The command line ------------------------------------------------------------------

TEST(ClipSpec, PlainPathHasDefaultOptions) {
    const ClipSpec clip = renderClip("walk.bvh");
    EXPECT_EQ(clip.path, "walk.bvh");
    EXPECT_FALSE(clip.bake.metresPerUnit.has_value());
    EXPECT_FALSE(clip.bake.upAxis.has_value());
    EXPECT_TRUE(clip.bake.travelJoint.empty());
    EXPECT_FALSE(clip.bake.loop.has_value());
    EXPECT_FALSE(clip.bake.straighten);
    EXPECT_TRUE(clip.bake.footLock);
    EXPECT_EQ(clip.bake.positionChannels, PositionChannels::Replace);
    EXPECT_FALSE(clip.bake.skipFirstFrame.has_value());
}

TEST(ClipSpec, EveryKey) {
    const ClipSpec clip = renderClip(
        "walk.bvh:units=0.01,up=z,root=Hips,loop=10-50,straighten=1,foot-lock=0,position-channels=add,keep-first-frame=1");
    EXPECT_EQ(clip.path, "walk.bvh");
    expectEveryOverride(clip.bake);
}

TEST(ClipSpec, EachUpAxisAndSwitchSpelling) {
    for (const auto& [name, axis] : std::initializer_list<std::pair<const char*, UpAxis>>{
             {"y", UpAxis::PlusY}, {"-y", UpAxis::MinusY}, {"z", UpAxis::PlusZ}, {"-z", UpAxis::MinusZ}, {"x", UpAxis::PlusX},
             {"-x", UpAxis::MinusX}})
        EXPECT_EQ(renderClip(std::string("a.bvh:up=") + name).bake.upAxis, std::optional<UpAxis>(axis)) << name;
    for (const char* on : {"1", "yes", "true"}) EXPECT_TRUE(renderClip(std::string("a.bvh:straighten=") + on).bake.straighten);
    for (const char* off : {"0", "no", "false"}) EXPECT_FALSE(renderClip(std::string("a.bvh:foot-lock=") + off).bake.footLock);
    // keep-first-frame=0 is the default: frame 0 is checked for a T-pose.
    EXPECT_FALSE(renderClip("a.bvh:keep-first-frame=0").bake.skipFirstFrame.has_value());
    EXPECT_EQ(renderClip("a.bvh:position-channels=replace").bake.positionChannels, PositionChannels::Replace);
}

TEST(ClipSpec, EachClipKeepsItsOwnOptions) {
    const std::vector<ClipSpec> clips = renderClips({"a.bvh:units=0.01", "b.bvh", "c.bvh:up=-x"});
    ASSERT_EQ(clips.size(), 3U);
    EXPECT_EQ(clips[0].bake.metresPerUnit, std::optional<double>(0.01));
    EXPECT_FALSE(clips[1].bake.metresPerUnit.has_value());
    EXPECT_EQ(clips[1].path, "b.bvh");
    EXPECT_EQ(clips[2].bake.upAxis, std::optional<UpAxis>(UpAxis::MinusX));
}

TEST(ClipSpec, JointNameWithColon) {
    // Mixamo names joints "mixamorig:Hips": the overrides start at the ':' before "root".
    const ClipSpec clip = renderClip("walk.bvh:units=0.01,root=mixamorig:Hips,up=z");
    EXPECT_EQ(clip.path, "walk.bvh");
    EXPECT_EQ(clip.bake.travelJoint, "mixamorig:Hips");
    EXPECT_EQ(clip.bake.upAxis, std::optional<UpAxis>(UpAxis::PlusZ));
    EXPECT_EQ(renderClip("dir:x/walk.bvh:root=a:b").path, "dir:x/walk.bvh");
}

TEST(ClipSpec, ExistingFileWithColonStaysAPath) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "throng-clip-spec-test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path odd = dir / "take:units=2";  // looks like an override, but it is a file
    std::ofstream(odd) << "not read by the parser\n";
    const ClipSpec clip = renderClip(odd.string());
    EXPECT_EQ(clip.path, odd.string());
    EXPECT_FALSE(clip.bake.metresPerUnit.has_value());
    // The same file with overrides of its own.
    const ClipSpec withOptions = renderClip(odd.string() + ":up=z");
    EXPECT_EQ(withOptions.path, odd.string());
    EXPECT_EQ(withOptions.bake.upAxis, std::optional<UpAxis>(UpAxis::PlusZ));
    std::filesystem::remove_all(dir);
    // A path with ':' and no key after it is a path too; loading it later says if it is missing.
    EXPECT_EQ(renderClip("no/such:dir/walk.bvh").path, "no/such:dir/walk.bvh");
}

TEST(ClipSpec, RefusesBadKeysAndValues) {
    expectRefused("walk.bvh:colour=red", {"unknown key 'colour'", "units, up, root, loop, straighten, foot-lock",
                                          "position-channels and keep-first-frame"});
    expectRefused("walk.bvh:units=1e400", {"units takes a positive number of metres per file unit", "not '1e400'"});
    for (const char* units : {"0", "-1", "nan", "inf", "2e6", "", "0.01m"})
        expectRefused(std::string("walk.bvh:units=") + units, {"units takes a positive number"});
    expectRefused("walk.bvh:up=w", {"up takes y, -y, z, -z, x or -x, not 'w'"});
    expectRefused("walk.bvh:up=Y", {"up takes y, -y, z, -z, x or -x"});
    expectRefused("walk.bvh:loop=5-2", {"loop takes FIRST-LAST frame indices with FIRST < LAST, not '5-2'"});
    for (const char* loop : {"5-5", "5", "-1-5", "a-b", "1-99999999999", "1:5", ""})
        expectRefused(std::string("walk.bvh:loop=") + loop, {"loop takes FIRST-LAST"});
    expectRefused("walk.bvh:root=", {"root takes the name of a joint of the file"});
    expectRefused("walk.bvh:straighten=maybe", {"straighten takes 0 or 1 (or no/yes, false/true), not 'maybe'"});
    expectRefused("walk.bvh:foot-lock=2", {"foot-lock takes 0 or 1"});
    expectRefused("walk.bvh:keep-first-frame=", {"keep-first-frame takes 0 or 1"});
    expectRefused("walk.bvh:position-channels=both", {"position-channels takes replace or add, not 'both'"});
}

TEST(ClipSpec, RefusesMalformedLists) {
    expectRefused("walk.bvh:units=0.01,units=0.02", {"units is given twice"});
    expectRefused("walk.bvh:straighten", {"straighten needs a value"});
    expectRefused("walk.bvh:up=z,straighten", {"straighten needs a value"});
    expectRefused("walk.bvh:units=0.01,", {"expected key=value, not ''"});
    expectRefused("walk.bvh:units=0.01,,up=z", {"expected key=value"});
    expectRefused(":units=0.01", {"needs a FILE before the ':'"});
}

TEST(ClipSpec, DemoAndBenchTakeOverridesToo) {
    const auto demo = std::get<DemoCommand>(parseCommandLine(Args{"demo", "--bvh", "a.bvh:up=z"}).value());
    ASSERT_EQ(demo.crowd.clips.size(), 1U);
    EXPECT_EQ(demo.crowd.clips[0].bake.upAxis, std::optional<UpAxis>(UpAxis::PlusZ));
    const auto bench = std::get<BenchCommand>(parseCommandLine(Args{"bench", "--bvh=a.bvh:straighten=yes", "--bvh", "b.bvh"}).value());
    ASSERT_EQ(bench.clips.size(), 2U);
    EXPECT_TRUE(bench.clips[0].bake.straighten);
    EXPECT_EQ(bench.clips[1].path, "b.bvh");
    auto refused = parseCommandLine(Args{"bench", "--bvh", "a.bvh:up=w"});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("up takes y, -y"), std::string::npos) << refused.error().message;
    EXPECT_NE(refused.error().message.find("(see 'throng bench --help')"), std::string::npos) << refused.error().message;
}

TEST(ClipSpec, ParsedDirectlyWithAnyNotionOfExistence) {
    const auto none = [](const std::string&) { return false; };
    const auto all = [](const std::string&) { return true; };
    EXPECT_EQ(throng::app::parseClipArgument("a.bvh:up=z", all).value().path, "a.bvh:up=z");
    EXPECT_EQ(throng::app::parseClipArgument("a.bvh:up=z", none).value().path, "a.bvh");
    EXPECT_FALSE(throng::app::parseClipArgument("a.bvh:up=w", none).ok());
}

// --- bvh info ----------------------------------------------------------------------------

TEST(ClipSpec, BvhInfoRootMotionOptions) {
    auto parsed = parseCommandLine(Args{"bvh", "info", "a.bvh", "--up", "-z", "--root", "mixamorig:Hips", "--straighten", "--no-foot-lock"});
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    const auto info = std::get<BvhInfoCommand>(parsed.value());
    EXPECT_EQ(info.bake.upAxis, std::optional<UpAxis>(UpAxis::MinusZ));
    EXPECT_EQ(info.bake.travelJoint, "mixamorig:Hips");
    EXPECT_TRUE(info.bake.straighten);
    EXPECT_FALSE(info.bake.footLock);
    const auto plain = std::get<BvhInfoCommand>(parseCommandLine(Args{"bvh", "info", "a.bvh"}).value());
    EXPECT_FALSE(plain.bake.upAxis.has_value());
    EXPECT_TRUE(plain.bake.travelJoint.empty());
    EXPECT_FALSE(plain.bake.straighten);
    EXPECT_TRUE(plain.bake.footLock);

    auto badUp = parseCommandLine(Args{"bvh", "info", "a.bvh", "--up", "w"});
    ASSERT_FALSE(badUp.ok());
    EXPECT_NE(badUp.error().message.find("--up takes y, -y, z, -z, x or -x, not 'w'"), std::string::npos) << badUp.error().message;
    auto emptyRoot = parseCommandLine(Args{"bvh", "info", "a.bvh", "--root", ""});
    ASSERT_FALSE(emptyRoot.ok());
    EXPECT_NE(emptyRoot.error().message.find("--root takes the name of a joint"), std::string::npos) << emptyRoot.error().message;
}

// --- Scene files -------------------------------------------------------------------------

// A scene beside the project's walk.bvh, with `clip` as its only clip.
throng::Result<throng::app::SceneDescription> sceneWithClip(const std::string& clip) {
    const std::string scenePath = (std::filesystem::path(THRONG_DEFAULT_CLIP).parent_path() / "test-scene.json").string();
    const std::string text = R"({"clips": [)" + clip + R"(], "groups": [{"count": 2, "region": {"centre": [0, 0], "size": [5, 5]}}]})";
    return throng::app::parseScene(text, scenePath);
}

void expectSceneRefused(const std::string& clip, const std::string& message) {
    SCOPED_TRACE(clip);
    auto scene = sceneWithClip(clip);
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().message.find(message), std::string::npos) << scene.error().message;
    EXPECT_NE(scene.error().location.file.find("test-scene.json"), std::string::npos) << "the error names the file";
}

TEST(SceneClips, EveryField) {
    auto scene = sceneWithClip(R"({"path": "walk.bvh", "units": 0.01, "up": "z", "root": "Hips", "loop": [10, 50],
                                   "straighten": true, "foot_lock": false, "position_channels": "add", "keep_first_frame": true})");
    ASSERT_TRUE(scene.ok()) << scene.error().describe();
    ASSERT_EQ(scene.value().clips.size(), 1U);
    const ClipSpec& clip = scene.value().clips[0];
    EXPECT_EQ(std::filesystem::path(clip.path).filename(), "walk.bvh");
    expectEveryOverride(clip.bake);
}

TEST(SceneClips, PlainPathAndNoFieldsKeepDefaults) {
    for (const char* clip : {R"("walk.bvh")", R"({"path": "walk.bvh", "name": "w"})"}) {
        auto scene = sceneWithClip(clip);
        ASSERT_TRUE(scene.ok()) << scene.error().describe();
        const throng::motion::BakeOptions& bake = scene.value().clips.at(0).bake;
        EXPECT_FALSE(bake.metresPerUnit.has_value());
        EXPECT_FALSE(bake.upAxis.has_value());
        EXPECT_TRUE(bake.footLock);
        EXPECT_FALSE(bake.skipFirstFrame.has_value());
    }
}

TEST(SceneClips, RefusesBadFields) {
    expectSceneRefused(R"({"path": "walk.bvh", "colour": "red"})",
                       "at /clips/0: unknown field \"colour\" (a clip takes name, path, units, up, root, loop, straighten, "
                       "foot_lock, position_channels and keep_first_frame)");
    // The command line's spelling is not the scene's.
    expectSceneRefused(R"({"path": "walk.bvh", "foot-lock": false})", "at /clips/0: unknown field \"foot-lock\"");
    expectSceneRefused(R"({"path": "walk.bvh", "units": 0})", "at /clips/0/units: expected a positive number of metres per file unit, at most 1e6, found 0");
    expectSceneRefused(R"({"path": "walk.bvh", "units": 1e300})", "at /clips/0/units: expected a positive number");
    expectSceneRefused(R"({"path": "walk.bvh", "units": "cm"})", "at /clips/0/units: expected a positive number of metres per file unit, at most 1e6, found string");
    expectSceneRefused(R"({"path": "walk.bvh", "up": "w"})", "at /clips/0/up: expected the file's up axis: y, -y, z, -z, x or -x");
    expectSceneRefused(R"({"path": "walk.bvh", "up": 1})", "at /clips/0/up: expected the file's up axis");
    expectSceneRefused(R"({"path": "walk.bvh", "root": ""})", "at /clips/0/root: expected the name of a joint of the file");
    expectSceneRefused(R"({"path": "walk.bvh", "loop": [5, 2]})", "at /clips/0/loop: expected frame indices with 0 <= FIRST < LAST, found [5,2]");
    expectSceneRefused(R"({"path": "walk.bvh", "loop": [-1, 2]})", "at /clips/0/loop: expected frame indices with 0 <= FIRST < LAST");
    expectSceneRefused(R"({"path": "walk.bvh", "loop": [1, 18446744073709551615]})", "at /clips/0/loop: expected frame indices with");
    expectSceneRefused(R"({"path": "walk.bvh", "loop": "10-50"})", "at /clips/0/loop: expected frame indices as [FIRST, LAST]");
    expectSceneRefused(R"({"path": "walk.bvh", "loop": [1.5, 2]})", "at /clips/0/loop: expected frame indices as [FIRST, LAST]");
    expectSceneRefused(R"({"path": "walk.bvh", "straighten": 1})", "at /clips/0/straighten: expected true or false, found number");
    expectSceneRefused(R"({"path": "walk.bvh", "foot_lock": "no"})", "at /clips/0/foot_lock: expected true or false, found string");
    expectSceneRefused(R"({"path": "walk.bvh", "keep_first_frame": null})", "at /clips/0/keep_first_frame: expected true or false");
    expectSceneRefused(R"({"path": "walk.bvh", "position_channels": "both"})", "at /clips/0/position_channels: expected \"replace\" or \"add\"");
}

}  // namespace
