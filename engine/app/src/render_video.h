#pragma once
// `throng render --duration`: frames rendered back to back through one offscreen renderer (no
// per-frame set-up) and handed to a video writer.

#include <functional>

#include "crowd_scene.h"
#include "throng/app/cli.h"
#include "throng/gpu/context.h"
#include "throng/render/offscreen.h"
#include "throng/render/scene_look.h"

namespace throng::app {

/// Renders frames 0..frameCount()-1 (or --frames A:B) of `crowd`, already spawned at
/// --time, into command.out; returns the exit code. Frame f shows --time + f / fps: the crowd
/// is stepped 1/fps s between frames from frame 0 on, so a part renders what a whole run does.
/// `sceneAt(t)` gives the view at crowd time t (a fixed camera, or one on a camera path).
int renderVideo(const RenderCommand& command, CrowdScene& crowd, render::OffscreenRenderer& offscreen,
                const std::function<render::SceneUniforms(double)>& sceneAt, const gpu::Context& context);

}  // namespace throng::app
