#include "throng/render/offscreen.h"

#include <chrono>
#include <cstring>
#include <utility>

#include "throng/gpu/barriers.h"
#include "throng/gpu/commands.h"
#include "throng/gpu/gpu_timer.h"
#include "throng/gpu/readback.h"
#include "throng/gpu/render_target.h"
#include "throng/render/scene_look.h"

namespace throng::render {
namespace {

constexpr vk::Format kColorFormat = vk::Format::eR8G8B8A8Srgb;  // linear shading, sRGB-encoded output
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;
// Timestamps per frame; kResolved and kShaded split the visibility path's passes (on the others
// they are written beside kComputed, outside the scene pass, so they cost nothing there).
enum Mark : std::uint32_t { kStart, kResolved, kComputed, kShaded, kDrawn, kCopied, kMarks };

}  // namespace

// The images, commands and sync of one offscreen frame, reused frame after frame.
struct OffscreenRenderer::Frame {
    Frame(const gpu::Context& context, const OffscreenOptions& options)
        : target(context, {.extent = {options.width, options.height}, .colorFormat = kColorFormat, .depthFormat = kDepthFormat,
                           .samples = context.sampleCount(samplesFor(options.path, options.msaa))}),
          resolved(context, {.extent = {options.width, options.height}, .format = kColorFormat,
                             .usage = vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc}),
          readback(context, {options.width, options.height}), commands(context), done(context.device(), vk::FenceCreateInfo{}),
          timer(context, kMarks) {}
    gpu::RenderTarget target;
    gpu::Image resolved;
    gpu::ImageReadback readback;
    gpu::FrameCommands commands;
    vk::raii::Fence done;
    gpu::GpuTimer timer;
};

OffscreenRenderer::OffscreenRenderer(const gpu::Context& context, const Palette& palette, std::span<const motion::BakedClip> clips,
                                     const OffscreenOptions& options)
    : context_(&context), options_(options), frame_(std::make_unique<Frame>(context, options)),
      renderer_(context, palette, clips,
                {.path = options.path, .colorFormat = kColorFormat, .depthFormat = kDepthFormat, .samples = frame_->target.samples(),
                 .slots = 1, .lodPixels = options.lodPixels, .body = options.body}) {}

OffscreenRenderer::~OffscreenRenderer() { context_->device().waitIdle(); }

std::uint32_t OffscreenRenderer::samples() const { return static_cast<std::uint32_t>(frame_->target.samples()); }

FrameTimings OffscreenRenderer::render(const CharacterSource& characters, const SceneUniforms& scene, bool timePasses,
                                       const std::function<void()>& whileDrawing) {
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
    using Stage = vk::PipelineStageFlagBits2;
    FrameTimings timings;
    Frame& f = *frame_;
    const auto frameStart = Clock::now();
    // The output holds the last frame only once that frame has finished (not after a throw).
    renderer_.update(0, characters, scene, std::exchange(holdsLastFrame_, false) && options_.keepLastFrame);
    timings.uploadMs = ms(Clock::now() - frameStart);

    const vk::raii::CommandBuffer& commands = f.commands.begin();
    const auto mark = [&f, timePasses](const vk::raii::CommandBuffer& c, vk::PipelineStageFlags2 stage, Mark at) {
        if (timePasses) f.timer.mark(c, stage, at);
    };
    if (timePasses) f.timer.reset(commands);
    mark(commands, Stage::eTopOfPipe, kStart);
    const auto boundary = [&mark](const vk::raii::CommandBuffer& c, FramePass pass) {
        if (pass == FramePass::Visibility) mark(c, Stage::eComputeShader, kResolved);
        else mark(c, Stage::eColorAttachmentOutput, kShaded);
    };
    const bool splats = renderer_.splats();
    renderer_.recordCompute(commands, 0, boundary);
    if (!splats) mark(commands, Stage::eComputeShader, kResolved);
    mark(commands, Stage::eComputeShader, kComputed);
    if (!splats) mark(commands, Stage::eComputeShader, kShaded);
    // Drawn over the last frame, the output is in the layout that frame left it in.
    const auto lastLayout = options_.readBack ? vk::ImageLayout::eTransferSrcOptimal : vk::ImageLayout::eColorAttachmentOptimal;
    f.target.begin(commands, {f.resolved.handle(), f.resolved.view()}, skyClearColor(),
                   renderer_.drawsOverLastFrame(0) ? std::optional(lastLayout) : std::nullopt, renderer_.needsClearedDepth());
    renderer_.recordDraw(commands, 0, f.target.extent(), boundary);
    f.target.end(commands);
    mark(commands, Stage::eColorAttachmentOutput, kDrawn);
    if (options_.readBack) {
        gpu::transitionImage(commands, f.resolved.handle(), vk::ImageAspectFlagBits::eColor, vk::ImageLayout::eColorAttachmentOptimal,
                             vk::ImageLayout::eTransferSrcOptimal, Stage::eColorAttachmentOutput, vk::AccessFlagBits2::eColorAttachmentWrite,
                             Stage::eCopy, vk::AccessFlagBits2::eTransferRead);
        // The previous frame's host read of the readback buffer finished at its fence.
        f.readback.recordCopy(commands, f.resolved.handle());
    }
    mark(commands, Stage::eCopy, kCopied);
    commands.end();
    context_->device().resetFences(*f.done);
    gpu::submit(*context_, commands, *f.done);
    if (whileDrawing) whileDrawing();  // reads and writes nothing this frame's commands use
    THRONG_VK_CHECK(context_->device().waitForFences(*f.done, VK_TRUE, UINT64_MAX));
    holdsLastFrame_ = true;
    const auto readStart = Clock::now();
    if (options_.readBack) pixels_ = f.readback.read();
    timings.readbackMs = options_.readBack ? ms(Clock::now() - readStart) : 0.0;
    if (const auto intervals = timePasses ? f.timer.intervalsMs() : std::nullopt) {
        const std::vector<double>& passes = *intervals;  // passes[m]: from mark m to the next
        timings.computeMs = passes[kStart] + passes[kResolved];
        timings.visibilityMs = splats ? passes[kResolved] : 0.0;
        timings.drawMs = passes[kComputed] + passes[kShaded];
        timings.shadingMs = splats ? passes[kComputed] : 0.0;
        if (options_.readBack) timings.readbackMs += passes[kDrawn];  // the GPU's copy into host memory, then the host's read of it
    }
    timings.frameMs = ms(Clock::now() - frameStart);
    return timings;
}

const std::vector<std::uint8_t>& OffscreenRenderer::pixels() const { return pixels_; }

std::size_t OffscreenRenderer::instanceCount() const {
    const InstanceLayout layout = renderer_.instanceLayout();
    if (!layout.exists) return 0;
    if (!layout.compacted) return std::size_t{renderer_.characterCount(0)} * renderer_.jointsPerCharacter();
    const std::vector<std::byte> arguments = gpu::downloadBuffer(*context_, renderer_.drawArguments(0), sizeof(DrawArguments));
    DrawArguments draw;
    std::memcpy(&draw, arguments.data(), sizeof draw);
    return draw.vertexCount;
}

std::vector<InstanceGpu> OffscreenRenderer::instances() const {
    const std::size_t count = instanceCount();
    const std::vector<std::byte> bytes = gpu::downloadBuffer(*context_, renderer_.instances(0), count * sizeof(InstanceGpu));
    std::vector<InstanceGpu> out(count);
    if (count > 0) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<glm::uvec2> OffscreenRenderer::instanceOwners() const {
    if (!renderer_.instanceLayout().compacted) return {};
    const std::size_t count = instanceCount();
    const std::vector<std::byte> bytes = gpu::downloadBuffer(*context_, renderer_.instanceOwners(0), count * sizeof(glm::uvec2));
    std::vector<glm::uvec2> out(count);
    if (count > 0) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<BodyLevelGpu> OffscreenRenderer::bodyLevels() const {
    if (renderer_.bodyLevels(0).size() < std::size_t{renderer_.characterCount(0)} * sizeof(BodyLevelGpu) || renderer_.characterCount(0) == 0) return {};
    const std::size_t count = renderer_.characterCount(0);
    const std::vector<std::byte> bytes = gpu::downloadBuffer(*context_, renderer_.bodyLevels(0), count * sizeof(BodyLevelGpu));
    std::vector<BodyLevelGpu> out(count);
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::vector<BoneInstanceGpu> OffscreenRenderer::boneInstances() const {
    const std::vector<std::byte> arguments = gpu::downloadBuffer(*context_, renderer_.drawArguments(0), sizeof(FastPathCounts));
    FastPathCounts counts;
    std::memcpy(&counts, arguments.data(), sizeof counts);
    const std::size_t count = std::min<std::size_t>(counts.boneDraw.instanceCount, renderer_.boneInstances(0).size() / sizeof(BoneInstanceGpu));
    if (count == 0) return {};
    const std::vector<std::byte> bytes = gpu::downloadBuffer(*context_, renderer_.boneInstances(0), count * sizeof(BoneInstanceGpu));
    std::vector<BoneInstanceGpu> out(count);
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

}  // namespace throng::render
