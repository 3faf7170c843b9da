// `throng demo`: the windowed demo. Each frame runs four named phases in order: input (the
// window's events), actions (keys and HUD buttons, from one controls table), simulate (the
// crowd step), and record (wait for a frame slot, upload, record, submit, present). Only the
// record phase touches the swapchain, and it acquires and submits in one call, so no action
// can leave a frame half begun.
#include "demo_command.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <cstdlib>
#include <memory>

#include "crowd_scene.h"
#include "demo_hud_layout.h"
#include "demo_pace.h"
#include "demo_recording.h"
#include "demo_tuning.h"
#include "path_choice.h"
#include "output.h"
#include "throng/core/log.h"
#include "throng/render/crowd_renderer.h"
#include "throng/render/scene_look.h"
#include "throng/viewer/camera_controller.h"
#include "throng/viewer/hud.h"

namespace throng::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kScriptedStep = 1.0 / 60.0;  // --frames runs use fixed steps, so they repeat exactly
constexpr std::size_t kHistory = 120;         // frames in the HUD's graph

constexpr std::uint32_t kHighlight = 0xFF30F0FFU;  // RGBA8, R low: the followed character's warm yellow

// The HUD's lines as one log line.
std::string joined(const std::vector<std::string>& lines, const std::string& separator) {
    std::string text;
    for (const std::string& line : lines) text += (text.empty() ? "" : separator) + line;
    return text;
}

float aspectOf(vk::Extent2D extent) { return static_cast<float>(extent.width) / static_cast<float>(std::max(extent.height, 1U)); }

class DemoSession {
public:
    DemoSession(const DemoCommand& command, CrowdScene scene, viewer::Window& window, const gpu::Context& context, std::string tuning)
        : command_(command), scene_(std::move(scene)), window_(&window), context_(context), tuning_(std::move(tuning)),
          palette_(context_, scene_.clipSpan()), presenter_(context_, window, {.vsync = command.vsync, .msaa = render::samplesFor(command.crowd.path, command.crowd.msaa)}),
          hud_(context_, window, presenter_),
          body_(command.crowd.body), renderer_(makeRenderer()),
          view_(frameView(scene_, aspectOf(presenter_.extent()), requestedCamera(command.crowd, scene_), command.crowd.view)), controller_(view_.camera) {
        pace_.adopt(*scene_.crowd);
        hud_.setVisible(!command.hideUi);
        hud_.build(hudStats());  // lay the panel out once, so the first framing knows its width
        if (!requestedCamera(command.crowd, scene_)) frameCrowd();
    }

    Result<bool> run() {
        if (command_.record)
            if (auto started = recording_.start(command_.record); !started) return started;
        last_ = Clock::now();
        while (!window_->closeRequested() && !quit_) {
            const viewer::FrameInput input = inputPhase();
            if (auto acted = actionsPhase(input); !acted) return acted.error();
            if (quit_) break;
            simulatePhase();
            auto drawn = recordPhase();
            if (!drawn) return drawn.error();
            if (drawn.value() && ++frame_ == command_.frames) break;
        }
        auto saved = recording_.stop();  // closing the window keeps what was recorded
        context_.device().waitIdle();
        log::info("demo: at the end, " + joined(paceLines(), "; "));
        if (frame_ > 0 && wallSeconds_ > 0)
            log::report("demo: " + std::to_string(frame_) + " frames in " + std::to_string(wallSeconds_) + " s, " +
                        std::to_string(frame_ / wallSeconds_) + " fps on average");
        if (context_.validationMessages() > 0)
            return Error{Error::Kind::Runtime, std::to_string(context_.validationMessages()) + " validation message(s)", {}};
        return saved;
    }

private:
    viewer::FrameInput inputPhase() {
        const viewer::FrameInput input = window_->poll(hud_.wantsMouse(), hud_.wantsTextInput());
        const auto now = Clock::now();
        elapsed_ = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        // Scripted resizes: three sizes spread through the run, to exercise swapchain recreation.
        constexpr std::array<vk::Extent2D, 3> resizes{vk::Extent2D{900, 560}, vk::Extent2D{1100, 700}, vk::Extent2D{760, 480}};
        if (command_.scriptResize && command_.frames > 0)
            for (std::size_t r = 0; r < resizes.size(); ++r)
                if (frame_ == static_cast<int>((r + 1) * static_cast<std::size_t>(command_.frames) / (resizes.size() + 1)))
                    window_->resize(resizes[r].width, resizes[r].height);
        return input;
    }

    // Buttons first, then every key press in the order it came: two presses of ] in one slow
    // frame double the crowd twice, and space twice pauses and resumes.
    Result<bool> actionsPhase(const viewer::FrameInput& input) {
        const viewer::ActionSet clicked = hud_.build(hudStats());
        for (std::size_t a = 0; a < viewer::kActionCount; ++a)
            if (clicked[a])
                if (auto done = apply(static_cast<viewer::Action>(a)); !done) return done;
        for (const viewer::Key key : input.pressed)
            if (const auto action = viewer::actionForKey(key))
                if (auto done = apply(*action); !done) return done;
        if (input.orbiting) controller_.orbit(input.mouseDelta);
        if (input.panning) controller_.pan(input.mouseDelta);
        if (input.scroll != 0.0F) controller_.zoom(input.scroll);
        const auto axis = [&](viewer::Key plus, viewer::Key minus) {
            return (input.isHeld(plus) ? 1.0F : 0.0F) - (input.isHeld(minus) ? 1.0F : 0.0F);
        };
        controller_.fly(axis(viewer::Key::W, viewer::Key::S), axis(viewer::Key::D, viewer::Key::A), axis(viewer::Key::E, viewer::Key::Q),
                        static_cast<float>(std::min(elapsed_, 0.1)));
        return true;
    }

    Result<bool> apply(viewer::Action action) {
        using viewer::Action;
        switch (action) {
            case Action::Quit: quit_ = true; break;
            case Action::TogglePause: paused_ = !paused_; break;
            case Action::Faster: speed_ = std::min(speed_ * 1.25F, 8.0F); break;
            case Action::Slower: speed_ = std::max(speed_ / 1.25F, 0.05F); break;
            case Action::WalkFaster: changePace(+1); break;
            case Action::WalkSlower: changePace(-1); break;
            case Action::HalveCrowd:
            case Action::DoubleCrowd:
            case Action::NextMode: return reshapeCrowd(action);
            case Action::NextBody: nextBody(); break;
            case Action::FrameCrowd: frameCrowd(); break;
            case Action::FollowNext: followNext(); break;
            case Action::ToggleHud: hud_.setVisible(!hud_.visible()); break;
            case Action::Screenshot: screenshots_.push_back(nextFreeName("throng-screenshot-", screenshotCount_, ".png")); break;
            case Action::Record: recording_.toggle(); break;
            case Action::Count: break;
        }
        return true;
    }

    // The whole crowd in the part of the window the HUD leaves free.
    void frameCrowd() {
        following_ = -1;
        const vk::Extent2D extent = presenter_.extent();
        const float width = static_cast<float>(std::max(extent.width, 1U));
        const float free = std::max(width - hud_.panelRight(), 0.25F * width);
        controller_.reset(frameView(scene_, free / static_cast<float>(std::max(extent.height, 1U)), std::nullopt).camera);
    }

    // C: the next character, seen from close by, and highlighted until followed no more.
    void followNext() {
        following_ = (following_ + 1) % std::max(scene_.size(), 1);
        controller_.setDistance(4.0F * std::max(view_.height, 0.5F));
    }

    // [ ] and M: a new crowd from the changed description. The renderer keeps its pipelines;
    // its per-frame buffers grow when the next frame needs more room.
    Result<bool> reshapeCrowd(viewer::Action action) {
        // A crowd following --trajectories has a character per track and no mode to change.
        const std::shared_ptr<const crowd::Trajectories>& tracks = scene_.description.setup.trajectories;
        if (tracks && action == viewer::Action::NextMode) {
            log::report("mode: the crowd follows --trajectories, so M changes nothing");
            return true;
        }
        if (action == viewer::Action::HalveCrowd || action == viewer::Action::DoubleCrowd) {
            // A visibility path the user asked for draws one batch at most.
            const bool capped = renderer_->path() == render::RenderPath::Visibility && !command_.tunePath;
            const std::int64_t total = reshapedCrowdSize(scene_.plannedCharacters(), action == viewer::Action::HalveCrowd ? 0.5 : 2.0,
                                                         static_cast<std::int64_t>(scene_.description.setup.groups.size()),
                                                         capped ? renderer_->batchCharacters() : 0,
                                                         tracks ? static_cast<std::int64_t>(tracks->tracks.size()) : 0);
            if (auto refused = scaleScene(scene_.description, total)) log::warning(refused->message);  // the crowd stays as it was
        }
        if (action == viewer::Action::NextMode)
            for (crowd::GroupSpec& group : scene_.description.setup.groups)
                group.mode = static_cast<crowd::Mode>((static_cast<int>(group.mode) + 1) % 3);
        following_ = -1;
        simulatedSeconds_ = 0.0;
        freshCrowd_ = true;  // its first frame continues no cross-fades of the crowd before
        auto spawned = scene_.respawn(0.0);
        if (spawned) {
            pace_.adopt(*scene_.crowd);  // the new crowd walks at the pace chosen
            view_.reach = crowdReach(scene_);  // the ground reaches a grown crowd's edge (the clips, so the height, stay)
            // Out of sight (the camera followed someone away, or looks past a smaller crowd's
            // edge) it is framed, as F frames it; a crowd still in sight keeps the user's view.
            if (!seesAnyCharacter(scene_, controller_.camera(), aspectOf(presenter_.extent()), view_.height)) {
                log::report("the new crowd is out of view: framed it");
                frameCrowd();
            }
        }
        if (spawned && renderer_->path() == render::RenderPath::Visibility && static_cast<std::uint32_t>(scene_.size()) > renderer_->batchCharacters()) {
            context_.device().waitIdle();  // the frames in flight read the old renderer's buffers
            renderer_ = makeRenderer();    // the path the demo picked gives way to the fast path
            details_.reset();
        }
        return spawned;
    }

    // Up and Down. Each press is logged, as the blend takes a second or two to follow it; a
    // press that changes nothing says why.
    void changePace(int steps) {
        const PaceChange change = pace_.shift(*scene_.crowd, steps);
        if (change == PaceChange::NoSet) {
            log::report("pace: no character blends a locomotion set (each plays one clip), so walking faster or slower "
                        "changes nothing");
            return;
        }
        const std::string pace = describePace(summarizePace(*scene_.crowd), scene_.description.clipNames, pace_.offset()).front();
        if (change == PaceChange::AtLimit)
            log::report(pace + " (every character already wants its set's " + (steps > 0 ? "fastest" : "slowest") + " speed)");
        else
            log::report(pace);
    }

    // The followed character's blend, else the crowd's.
    [[nodiscard]] std::vector<std::string> paceLines() const {
        const std::optional<int> followed = following_ >= 0 && following_ < scene_.size() ? std::optional(following_) : std::nullopt;
        return describePace(summarizePace(*scene_.crowd, followed), scene_.description.clipNames, pace_.offset(), followed);
    }

    void simulatePhase() {
        // Real time (capped so a stall doesn't teleport anyone), or fixed steps when scripted.
        const double dt = command_.frames > 0 ? kScriptedStep : std::min(elapsed_, 0.1);
        const auto start = Clock::now();
        if (!paused_) {
            scene_.step(dt * speed_);
            pace_.keep(*scene_.crowd);
            simulatedSeconds_ += dt * speed_;
        }
        simulationMs_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        recording_.advance(command_.frames > 0 ? kScriptedStep : elapsed_);  // a recording runs in real time, paused or not
        if (following_ >= 0 && following_ < scene_.size()) {
            const crowd::CharacterState c = scene_.character(following_);
            controller_.lookAt(glm::vec3(c.groundFrame.x, 0.9F, c.groundFrame.z));
        }
    }

    // Returns whether a frame was drawn.
    Result<bool> recordPhase() {
        const std::optional<std::uint32_t> slot = presenter_.waitForSlot();
        if (!slot) return false;  // minimised, or the swapchain was just rebuilt: nothing was begun
        details_ = renderer_->detailCounts(*slot);  // that slot's previous frame has finished
        // A window grown past the visibility path's frame: a path the demo picked gives way to
        // the fast path (one the user asked for stops with update's error). The frames in
        // flight still read the old renderer's buffers.
        if (renderer_->path() == render::RenderPath::Visibility && command_.tunePath &&
            !render::CrowdRenderer::visibilityFrameFits(context_, presenter_.extent())) {
            context_.device().waitIdle();
            renderer_ = makeRenderer();
            details_.reset();
        }
        render::Camera camera = controller_.camera();
        camera.lensShiftX = hud_.panelRight() / static_cast<float>(std::max(presenter_.extent().width, 1U));
        // The followed character is highlighted in the upload only (packed with kHighlight for its colour).
        renderer_->update(*slot, scene_.source(following_, kHighlight),
                          render::makeScene(camera, presenter_.extent(), view_.reach + 200.0F, !std::exchange(freshCrowd_, false)));
        std::optional<std::string> screenshot;  // one per frame; more asked for in one frame wait their turn
        if (!screenshots_.empty()) {
            screenshot = screenshots_.front();
            screenshots_.pop_front();
        }
        if (command_.frames > 0 && frame_ + 1 == command_.frames && command_.screenshot) screenshot = command_.screenshot;
        auto presented = presenter_.drawFrame(
            {.compute = [&](const vk::raii::CommandBuffer& c) { renderer_->recordCompute(c, *slot); },
             .scene = [&](const vk::raii::CommandBuffer& c) { renderer_->recordDraw(c, *slot, presenter_.extent()); },
             .overlay = [&](const vk::raii::CommandBuffer& c) { hud_.record(c); },
             .sceneNeedsClearedDepth = renderer_->needsClearedDepth()},
            {.screenshotPath = screenshot, .captureLabel = recording_.beforeFrame()});
        if (!presented) return presented;
        if (screenshot) log::report("saved " + *screenshot);
        hudLayout_.write(hud_.buttons());
        frameMs_ = elapsed_ * 1000.0;
        wallSeconds_ += elapsed_;
        history_.push_back(static_cast<float>(frameMs_));
        if (history_.size() > kHistory) history_.pop_front();
        return true;
    }

    [[nodiscard]] viewer::HudStats hudStats() const {
        return {.frameMs = frameMs_, .frameHistory = {history_.begin(), history_.end()}, .simulationMs = simulationMs_,
                .gpu = presenter_.lastTimings(), .characters = scene_.size(), .jointsPerCharacter = palette_.jointsPerCharacter(),
                .device = context_.description().name, .presentMode = presenter_.presentModeName(), .paused = paused_,
                .playbackSpeed = speed_, .pace = paceLines(), .simulatedSeconds = simulatedSeconds_, .groupModes = groupModes(),
                .following = following_, .swapchainRecreations = presenter_.recreations(),
                .renderPath = std::string(render::renderPathName(renderer_->path())) + ", " + std::string(render::bodyName(body_)),
                .msaa = static_cast<std::uint32_t>(presenter_.samples()),
                .fullDetail = details_ ? std::int64_t{details_->full} : -1,
                .coarseDetail = details_ ? std::int64_t{details_->coarse} : -1,
                .culled = details_ ? std::int64_t{details_->culled} : -1,
                .skinDetail = details_ && details_->skin ? std::int64_t{*details_->skin} : -1,
                .boneDetail = details_ && details_->bones ? std::int64_t{*details_->bones} : -1, .tuning = tuning_,
                .recording = recording_.hudLine()};
    }

    [[nodiscard]] std::vector<std::string> groupModes() const {
        std::vector<std::string> modes;
        for (const crowd::GroupSpec& group : scene_.description.setup.groups) modes.emplace_back(crowd::modeName(group.mode));
        return modes;
    }

    // The crowd's renderer for the body shown: spheres by the path the command chose, other
    // bodies by it too when it draws them (fast, visibility), else by the fast path.
    // A visibility path the demo picked itself (tuneForDevice) gives way to the fast path for a
    // crowd past what one of its batches holds or a window past its per-pixel buffer; one the
    // user asked for refuses such a crowd or window.
    std::unique_ptr<render::CrowdRenderer> makeRenderer() const {
        const render::RenderPath chosen = command_.crowd.path;
        const bool drawsBodies = chosen == render::RenderPath::Fast || chosen == render::RenderPath::Visibility;
        render::RenderPath path = body_ == render::Body::Spheres || drawsBodies ? chosen : render::RenderPath::Fast;
        // As `throng render` gives them (the demo's camera flies close).
        if (path == render::RenderPath::Visibility && command_.tunePath) path = pickedPathFor(body_);
        const auto make = [&](render::RenderPath which) {
            return std::make_unique<render::CrowdRenderer>(
                context_, palette_, scene_.clipSpan(),
                render::CrowdRendererCreateInfo{.path = which, .colorFormat = presenter_.colorFormat(), .depthFormat = presenter_.depthFormat(),
                                                .samples = presenter_.samples(), .slots = viewer::Presenter::kFramesInFlight,
                                                .lodPixels = command_.crowd.lodPixels, .body = body_});
        };
        if (path == render::RenderPath::Visibility && command_.tunePath && !visibilityHoldsFrame(context_, presenter_.extent(), "demo: ", "window"))
            path = render::RenderPath::Fast;
        auto renderer = make(path);
        if (path == render::RenderPath::Visibility && command_.tunePath && static_cast<std::uint32_t>(scene_.size()) > renderer->batchCharacters()) {
            log::report("demo: " + std::to_string(scene_.size()) + " characters are more than the visibility path's " +
                        std::to_string(renderer->batchCharacters()) + " on this device: drawing with the fast path");
            renderer = make(render::RenderPath::Fast);
        }
        return renderer;
    }

    // B: the next body. The frames in flight still read the old renderer's buffers.
    void nextBody() {
        const auto at = std::find(render::kBodies.begin(), render::kBodies.end(), body_);
        body_ = at + 1 == render::kBodies.end() ? render::kBodies.front() : *(at + 1);
        context_.device().waitIdle();
        renderer_ = makeRenderer();
        details_.reset();
        log::report("body: " + std::string(render::bodyName(body_)) + " (" + std::string(render::renderPathName(renderer_->path())) + " path)");
    }

    const DemoCommand& command_;
    CrowdScene scene_;
    viewer::Window* window_;
    const gpu::Context& context_;
    std::string tuning_;
    render::Palette palette_;
    viewer::Presenter presenter_;
    viewer::Hud hud_;
    DemoRecording recording_{presenter_};  ///< After the presenter: it unhooks from it when destroyed.
    render::Body body_;
    std::unique_ptr<render::CrowdRenderer> renderer_;
    CrowdView view_;
    CrowdPace pace_;
    viewer::CameraController controller_;
    bool paused_ = false, quit_ = false, freshCrowd_ = true;
    float speed_ = 1.0F;
    double simulatedSeconds_ = 0.0, wallSeconds_ = 0.0;
    HudLayoutFile hudLayout_;
    std::optional<render::DetailCounts> details_;
    int following_ = -1, frame_ = 0, screenshotCount_ = 0;
    std::deque<std::string> screenshots_;  ///< Asked for, not yet saved.
    std::deque<float> history_;
    double simulationMs_ = 0.0, frameMs_ = 0.0, elapsed_ = 0.0;
    Clock::time_point last_;
};

}  // namespace

int runDemo(const DemoCommand& original) {
    if (original.record)
        if (auto unwritable = checkOutputPath(*original.record, "--record")) return reportError(*unwritable);
    if (original.screenshot)
        if (auto unwritable = checkOutputPath(*original.screenshot, "--screenshot")) return reportError(*unwritable);
    auto window = viewer::Window::create({.width = original.crowd.width, .height = original.crowd.height, .title = "throng demo"});
    if (!window) return reportError(window.error());
    viewer::Window& win = *window.value();
    const gpu::Context context({.deviceFilter = original.crowd.device, .validation = original.crowd.validation,
                                .synchronizationValidation = true, .instanceExtensions = viewer::Window::requiredInstanceExtensions(),
                                .createSurface = [&](VkInstance instance) { return win.createSurface(instance); }});
    DemoCommand command = original;
    const std::string tuning = tuneForDevice(command, context);
    auto scene = prepareCrowdScene(command.crowd);
    if (!scene) return reportError(scene.error());
    if (auto tooMany = checkCrowdFits(context, scene.value(), command.crowd.body, viewer::Presenter::kFramesInFlight)) return reportError(*tooMany);
    if (auto spawned = scene.value().respawn(command.crowd.time); !spawned) return reportError(spawned.error());
    // The path the first body is drawn by (bone bodies alone leave a picked visibility path).
    const bool picked = command.tunePath && command.crowd.path == render::RenderPath::Visibility;
    log::report("demo on " + context.description().name + ": " + std::to_string(scene.value().size()) + " characters, " +
                std::string(render::renderPathName(picked ? pickedPathFor(command.crowd.body) : command.crowd.path)) + " path" +
                (tuning.empty() ? "" : "; picked for a " + context.description().type + " device: " + tuning +
                                           " (--characters, --path and --msaa override)"));
    DemoSession session(command, std::move(scene.value()), win, context, tuning);
    auto ran = session.run();
    return ran ? 0 : reportError(ran.error());
}

}  // namespace throng::app
