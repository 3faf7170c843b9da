#include "demo_command.h"

#include <chrono>
#include <cstdio>
#include <deque>
#include <memory>

#include "bvh_commands.h"
#include "crowd_setup.h"
#include "throng/render/camera_controller.h"
#include "throng/render/crowd_renderer.h"
#include "throng/render/headless.h"
#include "throng/render/hud.h"

namespace throng::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kScriptedStep = 1.0 / 60.0;  // --frames runs use fixed steps, so they repeat exactly
constexpr std::size_t kHistory = 120;         // frames in the HUD's graph

// Everything that changes when the crowd is rebuilt ([ ] and M): the crowd and the GPU-side
// renderer sized for it.
struct LiveCrowd {
    SceneDescription description;
    std::unique_ptr<crowd::Crowd> people;
    std::unique_ptr<render::CrowdRenderer> renderer;
    std::vector<crowd::CharacterState> packed;
};

Result<bool> rebuild(LiveCrowd& live, const gpu::Context& context, const render::Palette& palette, const render::Presenter& presenter,
                     std::span<const motion::BakedClip> clips, render::RenderPath path, float lodPixels) {
    auto spawned = crowd::Crowd::spawn(clips, live.description.setup);
    if (!spawned) return spawned.error();
    context.device().waitIdle();  // the old renderer's buffers may still be in flight
    live.renderer.reset();
    live.people = std::make_unique<crowd::Crowd>(std::move(spawned.value()));
    live.packed.resize(static_cast<std::size_t>(live.people->size()));
    live.renderer = std::make_unique<render::CrowdRenderer>(
        context, palette,
        render::CrowdRendererCreateInfo{.path = path, .colorFormat = presenter.colorFormat(), .depthFormat = presenter.depthFormat(),
                                        .samples = presenter.samples(), .framesInFlight = render::Presenter::kFramesInFlight,
                                        .maxCharacters = static_cast<std::uint32_t>(live.people->size()), .sphereSegments = 12,
                                        .sphereRings = 8, .lodPixels = lodPixels});
    return true;
}

// Scales every group's count by `factor` (at least one character each), growing spawn regions
// with the square root so the density stays the same.
void scaleCrowd(SceneDescription& description, double factor) {
    for (crowd::GroupSpec& group : description.setup.groups) {
        const int count = std::clamp(static_cast<int>(std::lround(group.count * factor)), 1, kMaxCharacters);
        group.region.size *= std::sqrt(static_cast<float>(count) / static_cast<float>(group.count));
        group.count = count;
    }
}

}  // namespace

int runDemo(const DemoCommand& command) {
    auto description = describeCrowd(command.crowd);
    if (!description) return reportError(description.error());
    auto clips = loadClips(description.value().clipPaths);
    if (!clips) return reportError(clips.error());

    auto window = render::Window::create({.width = command.crowd.width, .height = command.crowd.height, .title = "throng demo"});
    if (!window) return reportError(window.error());
    const render::Window& win = *window.value();
    const gpu::Context context({.deviceFilter = command.crowd.device, .validation = command.crowd.validation,
                                .synchronizationValidation = true,
                                .instanceExtensions = render::Window::requiredInstanceExtensions(),
                                .createSurface = [&](VkInstance instance) { return win.createSurface(instance); }});
    const render::Palette palette(context, clips.value());
    render::Presenter presenter(context, win, {.vsync = command.vsync, .msaa = command.crowd.msaa});
    render::Hud hud(context, win, presenter);

    LiveCrowd live{std::move(description.value()), nullptr, nullptr, {}};
    const render::RenderPath renderPath = command.crowd.path;
    std::vector<render::InstanceGpu> cpuInstances;
    if (auto built = rebuild(live, context, palette, presenter, clips.value(), renderPath, command.crowd.lodPixels); !built) return reportError(built.error());
    advance(*live.people, clips.value(), command.crowd.time);
    live.people->pack(live.packed);
    const auto aspectOf = [](vk::Extent2D e) { return static_cast<float>(e.width) / static_cast<float>(std::max(e.height, 1U)); };
    const std::optional<CameraSpec> given = command.crowd.camera ? command.crowd.camera : live.description.camera;
    CrowdView view = frameView(live.packed, clips.value(), aspectOf(presenter.extent()), given);
    render::CameraController controller(view.camera);

    bool paused = false;
    float speed = 1.0F;
    int following = -1;
    int frame = 0, screenshots = 0;
    std::deque<float> history;
    double simulationMs = 0.0, frameMs = 0.0;
    auto last = Clock::now();
    // Scripted resizes: three sizes spread through the run, to exercise swapchain recreation.
    const std::array<vk::Extent2D, 3> resizes{vk::Extent2D{900, 560}, vk::Extent2D{1100, 700}, vk::Extent2D{760, 480}};

    while (!win.closeRequested()) {
        const render::FrameInput input = window.value()->poll(hud.wantsMouse(), hud.wantsKeyboard());
        if (input.wasPressed(render::Key::Escape)) break;
        const auto now = Clock::now();
        const double elapsed = std::chrono::duration<double>(now - last).count();
        last = now;
        if (command.scriptResize && command.frames > 0)
            for (std::size_t r = 0; r < resizes.size(); ++r)
                if (frame == static_cast<int>((r + 1) * static_cast<std::size_t>(command.frames) / (resizes.size() + 1)))
                    win.resize(resizes[r].width, resizes[r].height);

        const std::optional<std::uint32_t> slot = presenter.beginFrame();
        if (!slot) continue;  // minimised or the swapchain was rebuilt: try again next time round

        // The HUD's buttons and the keys do the same things.
        render::HudStats stats{.frameMs = frameMs, .frameHistory = {history.begin(), history.end()}, .simulationMs = simulationMs,
                               .gpu = presenter.lastTimings(), .characters = live.people->size(),
                               .jointsPerCharacter = palette.jointsPerCharacter(), .device = context.description().name,
                               .presentMode = presenter.presentModeName(), .paused = paused, .playbackSpeed = speed,
                               .mode = crowd::modeName(live.description.setup.groups.front().mode), .following = following,
                               .swapchainRecreations = presenter.recreations()};
        const render::HudActions ui = hud.build(stats);
        if (ui.quit) break;
        if (ui.togglePause || input.wasPressed(render::Key::Space)) paused = !paused;
        if (ui.faster || input.wasPressed(render::Key::Plus)) speed = std::min(speed * 1.25F, 8.0F);
        if (ui.slower || input.wasPressed(render::Key::Minus)) speed = std::max(speed / 1.25F, 0.05F);
        const bool halve = ui.halveCrowd || input.wasPressed(render::Key::LeftBracket);
        const bool grow = ui.doubleCrowd || input.wasPressed(render::Key::RightBracket);
        const bool nextMode = ui.nextMode || input.wasPressed(render::Key::M);
        if (halve || grow || nextMode) {
            if (halve || grow) scaleCrowd(live.description, halve ? 0.5 : 2.0);
            if (nextMode)
                for (crowd::GroupSpec& group : live.description.setup.groups)
                    group.mode = static_cast<crowd::Mode>((static_cast<int>(group.mode) + 1) % 3);
            if (auto built = rebuild(live, context, palette, presenter, clips.value(), renderPath, command.crowd.lodPixels); !built) return reportError(built.error());
            following = -1;
            continue;  // the frame slot is untouched; begin again with the new crowd
        }
        if (ui.followNext || input.wasPressed(render::Key::C)) following = (following + 1) % live.people->size();
        if (ui.frameCrowd || input.wasPressed(render::Key::F)) {
            following = -1;
            controller.reset(frameView(live.packed, clips.value(), aspectOf(presenter.extent()), std::nullopt).camera);
        }
        if (input.orbiting) controller.orbit(input.mouseDelta);
        if (input.panning) controller.pan(input.mouseDelta);
        if (input.scroll != 0.0F) controller.zoom(input.scroll);
        const auto axis = [&](render::Key plus, render::Key minus) {
            return (input.isHeld(plus) ? 1.0F : 0.0F) - (input.isHeld(minus) ? 1.0F : 0.0F);
        };
        controller.fly(axis(render::Key::W, render::Key::S), axis(render::Key::D, render::Key::A), axis(render::Key::E, render::Key::Q),
                       static_cast<float>(std::min(elapsed, 0.1)));

        // Simulation: real time (capped so a stall doesn't teleport anyone), or fixed steps when scripted.
        const double dt = command.frames > 0 ? kScriptedStep : std::min(elapsed, 0.1);
        const auto simulationStart = Clock::now();
        if (!paused) live.people->step(clips.value(), dt * speed);
        live.people->pack(live.packed);
        simulationMs = std::chrono::duration<double, std::milli>(Clock::now() - simulationStart).count();
        if (following >= 0) {
            const crowd::CharacterState& c = live.packed[static_cast<std::size_t>(following)];
            controller.lookAt(glm::vec3(c.groundFrame.x, 0.9F, c.groundFrame.z));
        }
        const render::Camera camera = controller.camera();
        live.renderer->update(*slot, live.packed, render::makeScene(camera, presenter.extent(), view.reach + 200.0F));
        if (renderPath == render::RenderPath::Cpu) {
            cpuInstances.resize(live.packed.size() * palette.jointsPerCharacter());
            render::resolveInstancesOnCpu(clips.value(), live.packed, palette.jointsPerCharacter(), cpuInstances);
            live.renderer->uploadInstances(*slot, cpuInstances);
        }

        std::optional<std::string> screenshot;
        const bool lastScripted = command.frames > 0 && frame + 1 == command.frames;
        if (lastScripted && command.screenshot) screenshot = command.screenshot;
        if (input.wasPressed(render::Key::P) || ui.screenshot) screenshot = "throng-screenshot-" + std::to_string(++screenshots) + ".png";
        const render::CrowdRenderer& renderer = *live.renderer;
        auto presented = presenter.endFrame([&](const vk::raii::CommandBuffer& c) { renderer.recordCompute(c, *slot); },
                                            [&](const vk::raii::CommandBuffer& c) { renderer.recordDraw(c, *slot, presenter.extent()); },
                                            [&](const vk::raii::CommandBuffer& c) { hud.record(c); }, screenshot);
        if (!presented) return reportError(presented.error());
        if (screenshot) std::fprintf(stderr, "throng: saved %s\n", screenshot->c_str());

        frameMs = elapsed * 1000.0;
        history.push_back(static_cast<float>(frameMs));
        if (history.size() > kHistory) history.pop_front();
        if (++frame == command.frames) break;
    }
    context.device().waitIdle();
    if (context.validationMessages() > 0)
        return reportError(Error{Error::Kind::Runtime, std::to_string(context.validationMessages()) + " validation message(s)", {}});
    return 0;
}

}  // namespace throng::app
