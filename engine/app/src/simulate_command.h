#pragma once
// `throng simulate`: the crowd stepped on the CPU and written as CSV, no Vulkan device needed.

#include "throng/app/cli.h"

namespace throng::app {

/// Runs `throng simulate`; returns the exit code (0, 1 runtime failure, 2 bad input).
int runSimulate(const SimulateCommand& command);

}  // namespace throng::app
