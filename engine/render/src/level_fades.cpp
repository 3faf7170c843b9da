#include "level_fades.h"

#include <algorithm>

#include "binding_numbers.h"
#include "throng/gpu/context.h"
#include "throng/render/scene_look.h"

namespace throng::render::detail {
namespace {

constexpr vk::DeviceSize kFadeBytes = sizeof(std::uint32_t);  // bindings.glsl's uint a character: two levels' histories
constexpr vk::DeviceSize kPlaceholderBytes = 16;
static_assert(kLevelFadeFrames == THRONG_LEVEL_FADE_FRAMES, "lod_fade.glsl keeps as many frames as a video part draws first");

}  // namespace

LevelFades::LevelFades(const gpu::Context& context, bool kept, std::uint32_t batchCharacters)
    : context_(&context), kept_(kept), batchCharacters_(std::max(batchCharacters, 1U)) {}

const gpu::Buffer& LevelFades::buffer(std::uint32_t batch) {
    while (buffers_.size() <= batch) {
        buffers_.emplace_back(*context_, gpu::BufferCreateInfo{.size = kPlaceholderBytes, .usage = vk::BufferUsageFlagBits::eStorageBuffer});
        capacity_.push_back(0);
        drawn_.push_back(0);
    }
    return buffers_[batch];
}

LevelFades::Frame LevelFades::prepare(std::uint32_t batch, std::size_t characters, bool continues) {
    static_cast<void>(buffer(batch));
    Frame frame;
    if (!kept_) return frame;
    if (characters > capacity_[batch]) {
        // Doubling, as the batches' own buffers grow; the other slots' frames may still read
        // the old one, and what it held is no previous frame of a crowd this size.
        context_->device().waitIdle();
        const std::size_t capacity = std::min<std::size_t>(std::max(characters, 2 * capacity_[batch]), batchCharacters_);
        buffers_[batch] = gpu::Buffer(*context_, {.size = std::max<vk::DeviceSize>(capacity * kFadeBytes, kPlaceholderBytes),
                                                  .usage = vk::BufferUsageFlagBits::eStorageBuffer});
        capacity_[batch] = capacity;
        drawn_[batch] = 0;
        frame.resized = true;
    }
    // Another crowd (or the first frame): no fade to move on from.
    frame.continues = continues && drawn_[batch] == characters;
    drawn_[batch] = characters;
    return frame;
}

void LevelFades::idleFrom(std::uint32_t batch) {
    for (std::size_t b = batch; b < drawn_.size(); ++b) drawn_[b] = 0;
}

}  // namespace throng::render::detail
