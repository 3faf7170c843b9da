#pragma once
// `throng render` and `throng devices`. Each returns the process exit code.

#include "throng/app/cli.h"

namespace throng::app {

int runRender(const RenderCommand& command);
int runDevices(const DevicesCommand& command);

}  // namespace throng::app
