#pragma once
// What the demo picks for the device when the user left an option at its default.

#include <cstdint>
#include <string>

#include "throng/app/cli.h"
#include "throng/gpu/context.h"

namespace throng::app {

/// The demo's defaults on a CPU device, where the user gave none (its help says so too).
inline constexpr int kCpuDemoCharacters = 500;
inline constexpr std::uint32_t kCpuDemoMsaa = 1;

/// On a CPU device: fewer characters, the visibility path and 1x MSAA, each only where the
/// user gave no option for it. Returns what was picked ("" on a GPU), for the HUD and the log.
[[nodiscard]] std::string tuneForDevice(DemoCommand& command, const gpu::Context& context);

/// The crowd size [ or ] asks for (`factor` times `planned`), within what may be drawn: one
/// batch of a visibility path the user asked for (`batch`; 0: no cap) and a trajectory file's
/// `tracks` (0: none), each cap said as a warning when it bites; at least `groups`.
[[nodiscard]] std::int64_t reshapedCrowdSize(std::int64_t planned, double factor, std::int64_t groups, std::int64_t batch, std::int64_t tracks);

}  // namespace throng::app
