#pragma once
// A command pool with one resettable primary command buffer: what a frame slot records into.

#include "throng/gpu/context.h"

namespace throng::gpu {

class FrameCommands {
public:
    explicit FrameCommands(const Context& context);

    /// Resets the buffer and begins a one-time-submit recording. The caller has waited for the
    /// submission that last used it.
    const vk::raii::CommandBuffer& begin();
    [[nodiscard]] const vk::raii::CommandBuffer& buffer() const { return buffer_; }

private:
    vk::raii::CommandPool pool_{nullptr};
    vk::raii::CommandBuffer buffer_{nullptr};
};

/// Submits one command buffer on the context's queue, waiting on and signalling at most one
/// semaphore each (null handles for none), and signalling `fence`.
void submit(const Context& context, const vk::raii::CommandBuffer& commands, vk::Fence fence,
            vk::Semaphore wait = {}, vk::PipelineStageFlags2 waitStage = {}, vk::Semaphore signal = {});

}  // namespace throng::gpu
