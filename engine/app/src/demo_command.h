#pragma once
// `throng demo`: the windowed, interactive crowd.

#include "throng/app/cli.h"

namespace throng::app {

int runDemo(const DemoCommand& command);

}  // namespace throng::app
