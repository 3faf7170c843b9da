#pragma once
// `throng bench`: benchmark figures (never assertions).

#include "throng/app/cli.h"

namespace throng::app {

int runBench(const BenchCommand& command);

}  // namespace throng::app
