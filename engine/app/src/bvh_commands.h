#pragma once
// The `throng bvh ...` subcommands. Each returns the process exit code.

#include "throng/app/cli.h"

namespace throng::app {

int runBvhInfo(const BvhInfoCommand& command);
int runBvhBake(const BvhBakeCommand& command);
int runBvhBench(const BvhBenchCommand& command);

/// Prints `error` as one line on stderr and returns its exit code (2 bad input, 1 runtime).
int reportError(const Error& error);

/// The project's own default clip (assets/walk.bvh), found without the working directory.
std::string defaultClipPath();

}  // namespace throng::app
