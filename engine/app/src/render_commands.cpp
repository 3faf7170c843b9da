#include "render_commands.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "bvh_commands.h"
#include "crowd_setup.h"
#include "throng/core/atomic_file.h"
#include "throng/crowd/crowd.h"
#include "throng/gpu/context.h"
#include "throng/motion/bvh_parser.h"
#include "throng/render/headless.h"
#include "throng/render/png.h"

namespace throng::app {
namespace {

using Json = nlohmann::ordered_json;


// Refuses an output path whose directory doesn't exist before any expensive work.
std::optional<Error> checkOutputPath(const std::string& path, const char* option) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
        return Error{Error::Kind::BadInput, std::string(option) + ": directory '" + parent.string() + "' does not exist", {path, 0, 0}};
    if (std::filesystem::is_directory(path))
        return Error{Error::Kind::BadInput, std::string(option) + ": is a directory", {path, 0, 0}};
    return std::nullopt;
}

// Every drawn joint read back from the GPU, grouped by character, with what the compute pass
// used: clip, frame position, ground frame, scale. The fast path lists only the characters it
// kept, and the culled ones apart.
Json instanceDump(const std::vector<motion::BakedClip>& clips, const std::vector<crowd::CharacterState>& packed,
                  const render::OffscreenRenderer& offscreen, std::uint32_t k) {
    Json json;
    Json clipList = Json::array();
    for (const motion::BakedClip& clip : clips)
        clipList.push_back({{"source", clip.name}, {"joints", clip.jointNames}, {"height", clip.height}});
    json["clips"] = clipList;
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
        const crowd::CharacterState& c = packed[m];
        Json positions = Json::array(), orientations = Json::array(), joints = Json::array();
        for (const auto& [index, joint] : drawn[m]) {
            const render::InstanceGpu& instance = instances.at(index);
            positions.push_back({instance.positionRadius.x, instance.positionRadius.y, instance.positionRadius.z});
            orientations.push_back({instance.orientation.x, instance.orientation.y, instance.orientation.z, instance.orientation.w});
            joints.push_back(joint);
        }
        characters.push_back({{"index", m}, {"clip", c.clip}, {"frame", c.frame}, {"ground", {c.groundFrame.x, c.groundFrame.z, c.groundFrame.w}},
                              {"scale", c.scale}, {"joints", joints}, {"positions", positions}, {"orientations", orientations}});
    }
    json["characters"] = characters;
    json["culled"] = culled;
    return json;
}

}  // namespace

int runRender(const RenderCommand& command) {
    for (const auto& [path, option] : {std::pair{command.out, "--out"}, std::pair{command.dumpInstances.value_or(""), "--dump-instances"}})
        if (!path.empty())
            if (auto problem = checkOutputPath(path, option)) return reportError(*problem);
    auto description = describeCrowd(command.crowd);
    if (!description) return reportError(description.error());
    auto clips = loadClips(description.value().clipPaths);
    if (!clips) return reportError(clips.error());

    auto spawned = crowd::Crowd::spawn(clips.value(), description.value().setup);
    if (!spawned) return reportError(spawned.error());
    crowd::Crowd& people = spawned.value();
    advance(people, clips.value(), command.crowd.time);
    std::vector<crowd::CharacterState> packed(static_cast<std::size_t>(people.size()));
    people.pack(packed);
    const float aspect = static_cast<float>(command.crowd.width) / static_cast<float>(command.crowd.height);
    const CrowdView view = frameView(packed, clips.value(), aspect, command.crowd.camera ? command.crowd.camera : description.value().camera);
    const render::Camera& camera = view.camera;
    const float reach = view.reach;
    const render::SceneUniforms scene = render::makeScene(camera, {command.crowd.width, command.crowd.height}, reach + 40.0F);

    const gpu::Context context({.deviceFilter = command.crowd.device, .validation = command.crowd.validation,
                                .synchronizationValidation = true, .instanceExtensions = {}, .createSurface = {}});
    if (command.crowd.width > context.limits().maxImageDimension2D || command.crowd.height > context.limits().maxImageDimension2D)
        return reportError(Error{Error::Kind::BadInput,
                                 "image size exceeds this device's limit of " + std::to_string(context.limits().maxImageDimension2D) + " pixels",
                                 {}});
    const render::Palette palette(context, clips.value());
    const render::RenderPath path = command.crowd.path;
    if (command.dumpInstances && path == render::RenderPath::Paper)
        return reportError(Error{Error::Kind::BadInput, "--dump-instances needs a path with an instance buffer (compute, cpu or fast)", {}});
    render::OffscreenRenderer offscreen(context, palette, clips.value(), static_cast<std::uint32_t>(packed.size()),
                                        {.width = command.crowd.width, .height = command.crowd.height, .msaa = command.crowd.msaa,
                                         .path = path, .lodPixels = command.crowd.lodPixels});
    const render::FrameTimings timings = offscreen.render(packed, scene);
    if (context.validationMessages() > 0)
        return reportError(Error{Error::Kind::Runtime,
                                 std::to_string(context.validationMessages()) + " validation message(s); no output written", {}});

    if (command.dumpInstances) {
        const Json dump = instanceDump(clips.value(), packed, offscreen, palette.jointsPerCharacter());
        auto written = writeFileAtomically(*command.dumpInstances, dump.dump() + "\n");
        if (!written) return reportError(written.error());
    }
    const std::vector<std::uint8_t> rgba = offscreen.pixels();
    auto written = render::writePng(command.out, command.crowd.width, command.crowd.height, rgba.data(), std::size_t{command.crowd.width} * 4);
    if (!written) return reportError(written.error());
    std::fprintf(stderr, "throng: wrote %s: %ux%u, %d characters x %u joints, %s path, %ux MSAA on %s; frame %.1f ms\n",
                 command.out.c_str(), command.crowd.width, command.crowd.height, people.size(), palette.jointsPerCharacter(),
                 std::string(render::renderPathName(path)).c_str(), offscreen.samples(), context.description().name.c_str(), timings.frameMs);
    return 0;
}

int runDevices(const DevicesCommand&) {
    const std::vector<gpu::DeviceDescription> devices = gpu::listDevices();
    if (devices.empty()) {
        std::fprintf(stderr, "throng: error: no Vulkan devices (Debian: install mesa-vulkan-drivers for lavapipe)\n");
        return 1;
    }
    for (const gpu::DeviceDescription& d : devices)
        std::printf("%-40s %-15s Vulkan %-9s %s\n", d.name.c_str(), d.type.c_str(), d.apiVersion.c_str(), d.driver.c_str());
    return 0;
}

}  // namespace throng::app
