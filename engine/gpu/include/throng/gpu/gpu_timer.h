#pragma once
// GPU time between points of a command buffer, from timestamp queries.

#include <optional>
#include <vector>

#include "throng/gpu/context.h"

namespace throng::gpu {

class GpuTimer {
public:
    /// Room for `marks` timestamps. Without timestamp support on the context's queue the timer
    /// records nothing and intervalsMs() is always empty.
    GpuTimer(const Context& context, std::uint32_t marks);

    [[nodiscard]] bool supported() const { return static_cast<bool>(*queries_); }
    /// Starts a new measurement: resets every query. Record before the first mark().
    void reset(const vk::raii::CommandBuffer& commands);
    /// Writes timestamp `index` once all earlier work has passed `stage`.
    void mark(const vk::raii::CommandBuffer& commands, vk::PipelineStageFlags2 stage, std::uint32_t index) const;
    /// After the recorded work finished: milliseconds from each mark to the next (marks - 1
    /// values); nullopt without support, before the first measurement, or if not all are ready.
    [[nodiscard]] std::optional<std::vector<double>> intervalsMs() const;

private:
    const Context* context_;
    vk::raii::QueryPool queries_{nullptr};
    std::uint32_t marks_;
    bool measured_ = false;
};

}  // namespace throng::gpu
