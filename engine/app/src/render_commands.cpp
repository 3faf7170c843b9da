#include "render_commands.h"

#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "crowd_scene.h"
#include "output.h"
#include "path_choice.h"
#include "render_dumps.h"
#include "render_video.h"
#include "throng/core/atomic_file.h"
#include "throng/core/log.h"
#include "throng/gpu/context.h"
#include "throng/render/offscreen.h"
#include "throng/render/png.h"
#include "throng/render/scene_look.h"

namespace throng::app {
namespace {


std::optional<Error> checkOutputs(const RenderCommand& command) {
    if (auto problem = checkOutputPath(command.out, "--out")) return problem;
    if (command.duration) return std::nullopt;  // a video: the CLI checked its kind and that nothing else is dumped
    if (!namesPngImage(command.out))
        return Error{Error::Kind::BadInput, "--out writes PNG images only: give a FILE.png, or - for stdout", {command.out, 0, 0}};
    for (const auto& [dump, flag] : {std::pair{command.dumpInstances, "--dump-instances"}, std::pair{command.dumpBodies, "--dump-bodies"}}) {
        if (!dump) continue;
        if (auto problem = checkOutputPath(*dump, flag)) return problem;
        if (sameFile(command.out, *dump)) return Error{Error::Kind::BadInput, std::string("--out and ") + flag + " name the same file", {command.out, 0, 0}};
    }
    if (command.dumpInstances && command.dumpBodies && sameFile(*command.dumpInstances, *command.dumpBodies))
        return Error{Error::Kind::BadInput, "--dump-instances and --dump-bodies name the same file", {*command.dumpBodies, 0, 0}};
    return std::nullopt;
}

// Every drawn joint read back from the GPU, grouped by character, with what the compute pass
// used: clip, frame position, ground frame, scale, foot twist, blend and transition. The fast path lists only the characters it
// kept, and the culled ones apart.
Json instanceDump(std::span<const motion::BakedClip> clips, std::span<const crowd::CharacterState> packed,
                  const render::OffscreenRenderer& offscreen, std::uint32_t k) {
    Json json;
    json["clips"] = clipListJson(clips);
    json["joints_per_character"] = k;
    json["path"] = render::renderPathName(offscreen.renderer().path());
    const std::vector<render::InstanceGpu> instances = offscreen.instances();
    const std::vector<glm::uvec2> owners = offscreen.instanceOwners();
    // Per character, (instance, joint) pairs; the fast path keeps visible characters only, and
    // distant ones only their major joints.
    std::vector<std::vector<std::pair<std::size_t, std::uint32_t>>> drawn(packed.size());
    if (owners.empty()) {
        for (std::size_t m = 0; m < packed.size(); ++m)
            for (std::uint32_t j = 0; j < clips[packed[m].clip].parents.size(); ++j) drawn[m].emplace_back(m * k + j, j);
    } else {
        for (std::size_t i = 0; i < owners.size(); ++i) {
            // Data read back from the GPU is checked like any input before it indexes anything.
            if (owners[i].x >= packed.size() || owners[i].y >= clips[packed[owners[i].x].clip].parents.size())
                throw ThrongException(Error{Error::Kind::Runtime, "the GPU returned an invalid instance record; nothing written", {}});
            drawn[owners[i].x].emplace_back(i, owners[i].y);
        }
    }
    Json characters = Json::array(), culled = Json::array();
    for (std::size_t m = 0; m < packed.size(); ++m) {
        if (drawn[m].empty()) {
            culled.push_back(m);
            continue;
        }
        Json positions = Json::array(), orientations = Json::array(), joints = Json::array();
        for (const auto& [index, joint] : drawn[m]) {
            const render::InstanceGpu& instance = instances.at(index);
            positions.push_back({instance.positionRadius.x, instance.positionRadius.y, instance.positionRadius.z});
            orientations.push_back({instance.orientation.x, instance.orientation.y, instance.orientation.z, instance.orientation.w});
            joints.push_back(joint);
        }
        Json record = characterJson(m, packed[m]);
        record["first_instance"] = drawn[m].front().first;  // where its joints are among those written
        record["joints"] = joints;
        record["positions"] = positions;
        record["orientations"] = orientations;
        characters.push_back(record);
    }
    json["characters"] = characters;
    json["culled"] = culled;
    return json;
}

// A render of a following crowd after every track has ended shows no one: said, since the
// file's clock is easy to mistake (its time 0 is the earliest sample). A video's frames are
// those it writes: --frames A:B, else 0 to the last, frame f at --time + f / fps.
void warnPastTheTracks(const CrowdScene& crowd, const RenderCommand& command) {
    const auto& tracks = crowd.description.setup.trajectories;
    if (!tracks) return;
    const double time = command.crowd.time, fps = command.fps;
    const auto [first, last] = command.frames.value_or(std::pair<std::int64_t, std::int64_t>{0, std::max<std::int64_t>(command.frameCount() - 1, 0)});
    const double firstTime = time + static_cast<double>(first) / fps, lastTime = time + static_cast<double>(last) / fps;
    const double end = tracks->duration + crowd::Crowd::kPresenceSlack;
    if (lastTime <= end) return;
    char line[240];
    if (!command.duration)
        std::snprintf(line, sizeof line, "every track has ended by --time %g s (the file spans %.2f s from its first sample): the picture shows no one",
                      time, tracks->duration);
    else if (firstTime > end)
        std::snprintf(line, sizeof line, "every track has ended by the video's first frame at %.2f s (the file spans %.2f s from its first sample): "
                      "its frames show no one", firstTime, tracks->duration);
    else
        std::snprintf(line, sizeof line, "the tracks end at %.2f s (from the file's first sample): the video's frames after it show no one",
                      tracks->duration);
    log::warning(line);
}

}  // namespace

// The frame's outputs, written together: both or neither.
int writeRenderOutputs(const RenderCommand& command, const CrowdScene& crowd, const render::OffscreenRenderer& offscreen,
                       std::uint32_t jointsPerCharacter) {
    const CrowdOptions& options = command.crowd;
    auto png = render::encodePng(options.width, options.height, offscreen.pixels().data(), std::size_t{options.width} * 4);
    if (!png) return reportError(Error{png.error().kind, png.error().message, {command.out, 0, 0}});
    std::vector<OutputFile> outputs;
    std::string dump, bodies;
    if (command.dumpInstances) {
        dump = jsonText(instanceDump(crowd.clipSpan(), crowd.packed(), offscreen, jointsPerCharacter)) + "\n";
        outputs.push_back({*command.dumpInstances, dump});
    }
    if (command.dumpBodies) {
        bodies = jsonText(bodyDump(crowd.clipSpan(), crowd.packed(), offscreen)) + "\n";
        outputs.push_back({*command.dumpBodies, bodies});
    }
    outputs.push_back({command.out, png.value()});
    return writeOutputs(outputs);
}

int runRender(const RenderCommand& command) {
    if (auto problem = checkOutputs(command)) return reportError(*problem);
    auto prepared = prepareCrowdScene(command.crowd);
    if (!prepared) return reportError(prepared.error());
    CrowdScene& crowd = prepared.value();
    const CrowdOptions& options = command.crowd;
    warnPastTheTracks(crowd, command);
    std::vector<CameraKey> cameraPath = crowd.description.cameraPath;
    if (command.cameraPath) {
        auto loaded = loadCameraPath(*command.cameraPath);
        if (!loaded) return reportError(loaded.error());
        cameraPath = std::move(loaded.value());
    }

    const gpu::Context context({.deviceFilter = options.device, .validation = options.validation,
                                .synchronizationValidation = true, .instanceExtensions = {}, .createSurface = {}});
    if (options.width > context.limits().maxImageDimension2D || options.height > context.limits().maxImageDimension2D)
        return reportError(Error{Error::Kind::BadInput,
                                 "image size exceeds this device's limit of " + std::to_string(context.limits().maxImageDimension2D) + " pixels",
                                 {}});
    const render::Palette palette(context, crowd.clipSpan());
    if (auto tooMany = checkCrowdFits(context, crowd, options.body, 1)) return reportError(*tooMany);
    if (auto spawned = crowd.respawn(options.time); !spawned) return reportError(spawned.error());

    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    const CrowdView view = frameView(crowd, aspect, requestedCamera(options, crowd), options.view);
    // The camera at a time of the crowd's clock: fixed, or moving along a camera path.
    // A moving camera may fly far out: the ground reaches past the farthest keyframe, so its
    // edge stays out of view, and it is the same at every time (a frame of a video is then the
    // single render of its time).
    float ground = view.reach + 40.0F;
    for (const CameraKey& key : cameraPath) ground = std::max(ground, 3.0F * glm::length(key.camera.eye) + 100.0F);
    const auto sceneAt = [&](double time) {
        render::Camera camera = view.camera;
        if (!cameraPath.empty()) {
            placeCamera(camera, cameraAt(cameraPath, time), view);
            camera.farPlane = glm::length(camera.eye - camera.target) + 2.0F * ground + 200.0F;
        }
        return render::makeScene(camera, {options.width, options.height}, ground);
    };
    const render::SceneUniforms scene = sceneAt(options.time);
    std::optional<render::OffscreenRenderer> drawn;
    emplaceOffscreen(drawn, context, palette, crowd.clipSpan(),
                     {.width = options.width, .height = options.height, .msaa = options.msaa, .path = options.path,
                      .lodPixels = options.lodPixels, .body = options.body},
                     static_cast<std::size_t>(crowd.size()), command.choosePath);
    render::OffscreenRenderer& offscreen = *drawn;
    // The dumps read one batch's buffers: a crowd drawn in several is refused before anything is written.
    if ((command.dumpInstances || command.dumpBodies) && static_cast<std::size_t>(crowd.size()) > offscreen.renderer().batchCharacters())
        return reportError(Error{Error::Kind::BadInput,
                                 "--dump-instances and --dump-bodies take at most " + std::to_string(offscreen.renderer().batchCharacters()) +
                                     " characters on this device (what one batch of its buffers holds); got " + std::to_string(crowd.size()),
                                 {}});
    if (command.dumpInstances && !offscreen.renderer().instanceLayout().exists)
        return reportError(Error{Error::Kind::BadInput, "--dump-instances needs a path with an instance buffer (compute, cpu or fast)", {}});
    if (command.duration) return renderVideo(command, crowd, offscreen, sceneAt, context);
    const render::FrameTimings timings = offscreen.render(crowd.source(), scene);
    if (context.validationMessages() > 0)
        return reportError(Error{Error::Kind::Runtime,
                                 std::to_string(context.validationMessages()) + " validation message(s); no output written", {}});
    if (const int code = writeRenderOutputs(command, crowd, offscreen, palette.jointsPerCharacter())) return code;
    char summary[512];
    const std::uint32_t batches = offscreen.renderer().batchCount(0);
    const std::string inBatches = batches > 1 ? " in " + std::to_string(batches) + " batches" : "";
    std::snprintf(summary, sizeof summary, "wrote %s: %ux%u, %d character%s x %u joints%s, %s path, %ux MSAA on %s; frame %.1f ms",
                  command.out == "-" ? "stdout" : command.out.c_str(), options.width, options.height, crowd.size(), crowd.size() == 1 ? "" : "s",
                  palette.jointsPerCharacter(),
                  inBatches.c_str(), std::string(render::renderPathName(offscreen.renderer().path())).c_str(), offscreen.samples(),
                  context.description().name.c_str(), timings.frameMs);
    log::report(summary);
    return 0;
}

int runDevices(const DevicesCommand&) {
    const std::vector<gpu::DeviceDescription> devices = gpu::listDevices();
    if (devices.empty()) {
        return reportError(Error{Error::Kind::Runtime, "no Vulkan devices (Debian: install mesa-vulkan-drivers for lavapipe)", {}});
    }
    for (const gpu::DeviceDescription& d : devices)
        std::printf("%-40s %-15s Vulkan %-9s %s\n", d.name.c_str(), d.type.c_str(), d.apiVersion.c_str(), d.driver.c_str());
    return 0;
}

}  // namespace throng::app
