#include "throng/gpu/gpu_timer.h"

namespace throng::gpu {

GpuTimer::GpuTimer(const Context& context, std::uint32_t marks) : context_(&context), marks_(marks) {
    const auto families = context.physicalDevice().getQueueFamilyProperties();
    const bool supported = context.limits().timestampComputeAndGraphics && families[context.queueFamily()].timestampValidBits > 0;
    if (supported && marks > 0)
        queries_ = vk::raii::QueryPool(context.device(),
                                       vk::QueryPoolCreateInfo{.queryType = vk::QueryType::eTimestamp, .queryCount = marks});
}

void GpuTimer::reset(const vk::raii::CommandBuffer& commands) {
    if (!supported()) return;
    commands.resetQueryPool(*queries_, 0, marks_);
    measured_ = true;
}

void GpuTimer::mark(const vk::raii::CommandBuffer& commands, vk::PipelineStageFlags2 stage, std::uint32_t index) const {
    if (supported()) commands.writeTimestamp2(stage, *queries_, index);
}

std::optional<std::vector<double>> GpuTimer::intervalsMs() const {
    if (!supported() || !measured_) return std::nullopt;
    std::vector<std::uint64_t> ticks(marks_);
    const vk::Result result = (*context_->device()).getQueryPoolResults(*queries_, 0, marks_, ticks.size() * sizeof(std::uint64_t),
                                                                      ticks.data(), sizeof(std::uint64_t), vk::QueryResultFlagBits::e64);
    if (result != vk::Result::eSuccess) return std::nullopt;
    const double msPerTick = static_cast<double>(context_->limits().timestampPeriod) * 1e-6;
    std::vector<double> intervals;
    // Stamps at different stages may land out of order on a GPU: a negative interval reads 0.
    for (std::size_t i = 1; i < ticks.size(); ++i)
        intervals.push_back(ticks[i] > ticks[i - 1] ? static_cast<double>(ticks[i] - ticks[i - 1]) * msPerTick : 0.0);
    return intervals;
}

}  // namespace throng::gpu
