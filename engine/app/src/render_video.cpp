#include "render_video.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <cstdio>

#include "output.h"
#include "throng/core/log.h"
#include "throng/render/scene_look.h"
#include "throng/render/video.h"

namespace throng::app {
namespace {

using Clock = std::chrono::steady_clock;

// Progress on stderr: a bar redrawn in place on a terminal, else a line at each tenth.
class VideoProgress {
public:
    explicit VideoProgress(std::int64_t frames) : frames_(frames), terminal_(isatty(STDERR_FILENO) != 0) {}
    void update(std::int64_t done) {
        const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
        const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0.0;
        const double left = rate > 0 ? static_cast<double>(frames_ - done) / rate : 0.0;
        char line[200];
        if (terminal_) {
            constexpr int kWidth = 30;
            const auto filled = static_cast<int>(kWidth * done / std::max<std::int64_t>(frames_, 1));
            std::string bar(static_cast<std::size_t>(filled), '#');
            bar.resize(kWidth, '-');
            std::snprintf(line, sizeof line, "\rrender: [%s] %lld/%lld frames, %.1f fps, about %.0f s left ", bar.c_str(),
                          static_cast<long long>(done), static_cast<long long>(frames_), rate, left);
            std::fputs(line, stderr);
            if (done == frames_) std::fputs("\n", stderr);
            std::fflush(stderr);
            return;
        }
        // Not a terminal: a line at each tenth, once the render has taken a second (a short one prints none).
        const auto tenth = static_cast<int>(done * 10 / std::max<std::int64_t>(frames_, 1));
        if (tenth <= shown_ || done == frames_ || seconds < 1.0) return;
        shown_ = tenth;
        std::snprintf(line, sizeof line, "render: %lld/%lld frames, %.1f fps, about %.0f s left", static_cast<long long>(done),
                      static_cast<long long>(frames_), rate, left);
        log::report(line);
    }

private:
    std::int64_t frames_;
    bool terminal_;
    int shown_ = 0;
    Clock::time_point start_ = Clock::now();
};

}  // namespace

int renderVideo(const RenderCommand& command, CrowdScene& crowd, render::OffscreenRenderer& offscreen,
                const std::function<render::SceneUniforms(double)>& sceneAt, const gpu::Context& context) {
    const CrowdOptions& options = command.crowd;
    const auto [first, last] = command.frames.value_or(std::pair<std::int64_t, std::int64_t>{0, command.frameCount() - 1});
    auto opened = render::VideoWriter::open({command.out, options.width, options.height, command.fps, first});
    if (!opened) return reportError(opened.error());
    render::VideoWriter& writer = opened.value();
    VideoProgress progress(last - first + 1);
    const auto start = Clock::now();
    const double step = 1.0 / static_cast<double>(command.fps);
    // A part starts where a whole run would be: its crowd stepped there, and the frames its first
    // frame's cross-fades between levels of detail depend on drawn (not written) first, where
    // the bodies have such fades.
    const std::int64_t warmUp = render::fadesBetweenLevels(options.body) ? render::kLevelFadeFrames : 0;
    const std::int64_t drawnFrom = std::max<std::int64_t>(first - warmUp, 0);
    std::optional<std::uint32_t> mostFading;  // bodies' cross-fades: the most characters at two levels in a frame
    for (std::int64_t frame = 0; frame <= last; ++frame) {
        if (frame > 0) crowd.step(step);
        if (frame < drawnFrom) continue;
        render::SceneUniforms scene = sceneAt(options.time + static_cast<double>(frame) / static_cast<double>(command.fps));
        scene.levelFadesContinue = frame > drawnFrom ? 1.0F : 0.0F;
        offscreen.render(crowd.source(), scene);
        if (frame < first) continue;
        if (const auto details = offscreen.renderer().detailCounts(0); details && details->fading) mostFading = std::max(mostFading.value_or(0U), *details->fading);
        if (context.validationMessages() > 0)
            return reportError(Error{Error::Kind::Runtime, std::to_string(context.validationMessages()) + " validation message(s); no video written", {}});
        if (auto added = writer.add(offscreen.pixels().data(), std::size_t{options.width} * 4); !added) return reportError(added.error());
        progress.update(frame - first + 1);
    }
    if (auto finished = writer.finish(); !finished) return reportError(finished.error());
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    char summary[512];
    const std::int64_t count = last - first + 1;
    std::snprintf(summary, sizeof summary, "wrote %s: %lld frame%s (%lld to %lld) of %ux%u at %d fps, %d character%s, %s path; %.1f s, %.2f frames per second",
                  command.out.c_str(), static_cast<long long>(count), count == 1 ? "" : "s", static_cast<long long>(first), static_cast<long long>(last),
                  options.width, options.height, command.fps, crowd.size(), crowd.size() == 1 ? "" : "s",
                  std::string(render::renderPathName(offscreen.renderer().path())).c_str(), seconds,
                  static_cast<double>(last - first + 1) / std::max(seconds, 1e-9));
    std::string line = summary;
    if (mostFading && render::fadesBetweenLevels(options.body)) line += "; at most " + std::to_string(*mostFading) + " cross-fading between levels in a frame";
    // A still camera: the visibility path draws over the last frame, shading again only the squares where something moved.
    if (const auto kept = offscreen.renderer().keptGroundSquares(0)) line += "; its last frame kept the ground of " + std::to_string(*kept) + " squares of the one before";
    log::report(line);
    return 0;
}

}  // namespace throng::app
