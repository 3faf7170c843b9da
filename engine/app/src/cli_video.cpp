// `throng render`'s video options: --duration makes a video of --out (an MP4 or a frame
// pattern), --fps its rate, --frames A:B one part of it.
#include <cmath>

#include "cli_internal.h"
#include "throng/render/video.h"

namespace throng::app {

std::int64_t RenderCommand::frameCount() const { return duration ? std::llround(*duration * static_cast<double>(fps)) : 0; }

namespace detail {

void addVideoOptions(CLI::App& app, RenderCommand& command) {
    const std::string most = std::to_string(static_cast<int>(kMaxTimeSeconds));
    addNumber(app, "--duration", command.duration,
              NumberRule<double>{kPositive<double>, kMaxTimeSeconds, "--duration takes seconds, more than 0 and at most " + most},
              "Render a video of this many seconds from --time on, to\n"
              "--out FILE.mp4 (H.264), FILE.gif or a frame pattern such as\n"
              "frames/%05d.png; the camera stays where the first frame puts it")
        ->type_name("SECONDS")
        ->default_str("");
    addNumber(app, "--fps", command.fps,
              NumberRule<int>{1, kMaxVideoFps, "--fps takes whole frames per second from 1 to " + std::to_string(kMaxVideoFps)},
              "Video frames per second; the crowd steps 1/N s between frames");
    app.add_option_function<std::string>(
           "--frames",
           [&command](const std::string& text) {
               const std::size_t colon = text.find(':');
               const auto first = parseBounded<std::int64_t>(std::string_view(text).substr(0, colon), 0, INT64_MAX);
               const auto last = colon == std::string::npos ? std::nullopt
                                                            : parseBounded<std::int64_t>(std::string_view(text).substr(colon + 1), 0, INT64_MAX);
               if (!first || !last || *last < *first)
                   refuse("--frames takes A:B, whole frame numbers with 0 <= A <= B, not '" + text + "'");
               command.frames = std::pair{*first, *last};
           },
           "Render only frames A to B (inclusive, from 0) of the video:\n"
           "one part of a render split over jobs; the frames are\n"
           "byte-identical to those of a whole run")
        ->type_name("A:B");
    addText(app, "--camera-path", command.cameraPath, "FILE.json",
            "Move the camera through keyframes by the crowd's clock: the\n"
            "file's \"camera_path\", [{\"time\": s, \"eye\": [x, y, z], \"target\":\n"
            "[x, y, z], \"fov\": degrees}, ...] (a scene file's works); a\n"
            "scene's own camera_path is used without it; excludes --camera",
            "--camera-path needs a file name");
}

std::optional<Error> videoConflicts(const CLI::App& app, const RenderCommand& command) {
    if (command.cameraPath && command.crowd.camera) return usage("--camera places the camera and --camera-path moves it: give one", app);
    const std::optional<render::VideoKind> kind = render::videoKindOf(command.out);
    if (!command.duration) {
        if (kind) return usage("--out " + command.out + " is a video: give --duration SECONDS", app);
        if (app.count("--fps") > 0 || command.frames) return usage("--fps and --frames shape a video: give --duration SECONDS too", app);
        return std::nullopt;
    }
    if (!kind) return usage("--duration writes a video: give --out FILE.mp4, FILE.gif or a frame pattern such as frames/%05d.png", app);
    if (command.dumpInstances || command.dumpBodies) return usage("--dump-instances and --dump-bodies write one frame: not with --duration", app);
    if (command.frameCount() < 1)
        return usage("--duration " + defaultText(*command.duration) + " is less than half a frame at --fps " + std::to_string(command.fps), app);
    if (command.crowd.time + *command.duration > kMaxTimeSeconds)
        return usage("--time plus --duration pass " + std::to_string(static_cast<int>(kMaxTimeSeconds)) + " s", app);
    if (command.frames && command.frames->second >= command.frameCount())
        return usage("--frames " + std::to_string(command.frames->first) + ":" + std::to_string(command.frames->second) + " passes the video's last frame, " +
                         std::to_string(command.frameCount() - 1),
                     app);
    // What the writer would refuse (an odd-sized MP4, a bad frame pattern), refused before the
    // device opens and the crowd is built.
    return render::videoSpecProblem({.path = command.out, .width = command.crowd.width, .height = command.crowd.height, .framesPerSecond = command.fps});
}

}  // namespace detail
}  // namespace throng::app
