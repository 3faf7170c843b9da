#pragma once
// The `throng bvh ...` subcommands. Each returns the process exit code.

#include "throng/app/cli.h"

namespace throng::app {

int runBvhInfo(const BvhInfoCommand& command);
int runBvhBake(const BvhBakeCommand& command);
int runBvhBench(const BvhBenchCommand& command);

}  // namespace throng::app
