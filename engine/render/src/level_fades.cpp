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
    while (batches_.size() <= batch)
        batches_.push_back({gpu::Buffer(*context_, {.size = kPlaceholderBytes, .usage = vk::BufferUsageFlagBits::eStorageBuffer})});
    return batches_[batch].buffer;
}

LevelFades::Frame LevelFades::prepare(std::uint32_t index, std::size_t characters, bool continues) {
    static_cast<void>(buffer(index));
    Batch& batch = batches_[index];
    Frame frame;
    if (!kept_) return frame;
    if (characters > batch.capacity) {
        // Doubling, as the batches' own buffers grow; the other slots' frames may still read
        // the old one, and what it held is no previous frame of a crowd this size.
        context_->device().waitIdle();
        batch.capacity = std::min<std::size_t>(std::max(characters, 2 * batch.capacity), batchCharacters_);
        batch.buffer = gpu::Buffer(*context_, {.size = std::max<vk::DeviceSize>(batch.capacity * kFadeBytes, kPlaceholderBytes),
                                               .usage = vk::BufferUsageFlagBits::eStorageBuffer});
        batch.drawn = 0;
        frame.resized = true;
    }
    // Another crowd (or the first frame): no fade to move on from.
    frame.continues = continues && batch.drawn == characters;
    batch.drawn = characters;
    return frame;
}

void LevelFades::idleFrom(std::uint32_t first) {
    for (std::size_t b = first; b < batches_.size(); ++b) batches_[b].drawn = 0;
}

}  // namespace throng::render::detail
