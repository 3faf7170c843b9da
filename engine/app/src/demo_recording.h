#pragma once
// The demo's recording (R, or --record FILE from the start): what the window shows, HUD
// included, through the writer `throng render --out FILE.mp4` uses. The presenter copies each
// frame and hands it over when that frame's slot comes round again, so the demo never waits
// on the frame it has just submitted.
//
// The video runs at a fixed 30 fps in the demo's own time: real time interactively, fixed
// 1/60 s steps in a --frames run. Each video frame shows the last frame drawn at or before its
// time, so a slow demo's frames repeat and a fast one's are dropped, and the video plays at
// the pace the user saw. A repeat is not encoded again (VideoWriter::repeat), so recording a
// slow demo costs one encode per frame drawn, and a stall costs nothing. The size is the
// window's when recording starts (even for an MP4, for H.264's 4:2:0 chroma); a resize ends
// the recording there, saved, with a line that says so.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "throng/core/error.h"
#include "throng/render/video.h"
#include "throng/viewer/presenter.h"

namespace throng::app {

class DemoRecording {
public:
    static constexpr int kFramesPerSecond = 30;

    explicit DemoRecording(viewer::Presenter& presenter);
    DemoRecording(const DemoRecording&) = delete;
    DemoRecording& operator=(const DemoRecording&) = delete;
    ~DemoRecording();  ///< An unfinished recording leaves no MP4.

    /// Starts recording to `path` (an MP4 or a frames/%05d.png pattern), or to the first
    /// throng-recording-N.mp4 not yet in the working directory. A path that can't be opened
    /// is an error naming it, and nothing starts.
    Result<bool> start(const std::optional<std::string>& path);
    /// Ends the recording and puts the file in place; the error says why it couldn't be saved.
    Result<bool> stop();
    /// R: start to the next free name, or stop. Errors are logged: the demo goes on.
    void toggle();
    /// Every turn of the demo's loop, drawn or not: the demo seconds it took.
    void advance(double seconds);
    /// Before each drawn frame: the label to capture it with (its recording time), or nullopt
    /// for no capture. Ends a recording that failed or whose window was resized.
    std::optional<double> beforeFrame();

    [[nodiscard]] bool active() const { return writer_.has_value(); }
    /// For the HUD: "throng-recording-1.mp4, 3.2 s", or empty when not recording.
    [[nodiscard]] std::string hudLine() const;

private:
    void receive(const std::uint8_t* rgba, vk::Extent2D extent, double at);
    /// Writes the held frame for every video frame due before `seconds` (through it with `through`).
    void writeHeldUntil(double seconds, bool through);
    void abandon();

    viewer::Presenter* presenter_;
    std::optional<render::VideoWriter> writer_;
    std::string path_;
    vk::Extent2D extent_{};        ///< The window's size when recording started.
    vk::Extent2D videoSize_{};     ///< extent_, cut to even sizes for an MP4.
    double clock_ = 0.0;           ///< Recording time of the frame being drawn.
    bool firstFrame_ = true;
    std::vector<std::uint8_t> held_;  ///< The last frame received: shown until a newer one is due.
    bool heldWritten_ = false;     ///< held_ went into the video once: more of it are repeats.
    std::int64_t written_ = 0;     ///< Video frames written.
    std::int64_t encoded_ = 0;     ///< Of them, frames drawn (not holds of the one before).
    std::optional<Error> failure_;  ///< The writer's error, reported by the next beforeFrame().
    int counter_ = 0;              ///< Last N tried for throng-recording-N.mp4.
};

}  // namespace throng::app
