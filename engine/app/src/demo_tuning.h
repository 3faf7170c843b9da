#pragma once
// What the demo picks for the device when the user left an option at its default.

#include <string>

#include "throng/app/cli.h"
#include "throng/gpu/context.h"

namespace throng::app {

/// On a CPU device: fewer characters, the visibility path and 1x MSAA, each only where the
/// user gave no option for it. Returns what was picked ("" on a GPU), for the HUD and the log.
[[nodiscard]] std::string tuneForDevice(DemoCommand& command, const gpu::Context& context);

}  // namespace throng::app
