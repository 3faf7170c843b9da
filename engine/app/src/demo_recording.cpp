#include "demo_recording.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "output.h"
#include "throng/core/log.h"

namespace throng::app {
namespace {

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", s);
    return text;
}

}  // namespace

DemoRecording::DemoRecording(viewer::Presenter& presenter) : presenter_(&presenter) {
    presenter_->setCaptureSink([this](const std::uint8_t* rgba, vk::Extent2D extent, double at) { receive(rgba, extent, at); });
}

DemoRecording::~DemoRecording() { presenter_->setCaptureSink({}); }

Result<bool> DemoRecording::start(const std::optional<std::string>& path) {
    const vk::Extent2D window = presenter_->extent();
    const std::string target = path ? *path : nextFreeName("throng-recording-", counter_, ".mp4");
    if (window.width < 2 || window.height < 2)
        return Error{Error::Kind::BadInput, "recording: the window is too small to record (" + std::to_string(window.width) + "x" +
                                                std::to_string(window.height) + ")", {target, 0, 0}};
    const bool even = render::videoKindOf(target) == render::VideoKind::Mp4;
    const vk::Extent2D size{even ? window.width & ~1U : window.width, even ? window.height & ~1U : window.height};
    auto opened = render::VideoWriter::open({.path = target, .width = size.width, .height = size.height, .framesPerSecond = kFramesPerSecond});
    if (!opened) return Error{opened.error().kind, "recording: " + opened.error().message, opened.error().location};
    writer_.emplace(std::move(opened.value()));
    path_ = target;
    extent_ = window;
    videoSize_ = size;
    held_.clear();
    heldWritten_ = false;
    clock_ = 0.0;
    firstFrame_ = true;
    written_ = 0;
    encoded_ = 0;
    failure_.reset();
    log::report("recording to " + path_ + " (" + std::to_string(window.width) + "x" + std::to_string(window.height) +
                ", " + std::to_string(kFramesPerSecond) + " fps; R stops)");
    return true;
}

void DemoRecording::toggle() {
    if (auto done = active() ? stop() : start(std::nullopt); !done) log::error(done.error().describe());
}

void DemoRecording::advance(double seconds) {
    if (active() && !firstFrame_) clock_ += seconds;  // from the first frame captured on
}

std::optional<double> DemoRecording::beforeFrame() {
    if (!active()) return std::nullopt;
    if (failure_) {
        log::error("recording " + path_ + " stopped, nothing saved: " + failure_->message);
        abandon();
        return std::nullopt;
    }
    if (presenter_->extent() != extent_) {
        log::report("recording: the window changed size, so the recording ends here (R records again at the new size)");
        if (auto stopped = stop(); !stopped) log::error(stopped.error().message);
        return std::nullopt;
    }
    firstFrame_ = false;
    return clock_;
}

void DemoRecording::receive(const std::uint8_t* rgba, vk::Extent2D extent, double at) {
    if (!active() || failure_) return;  // captured for a recording that has ended or failed
    if (extent != extent_) return;  // not reached: beforeFrame() ends the recording before a frame of another size
    writeHeldUntil(at, false);
    held_.assign(rgba, rgba + std::size_t{extent.width} * extent.height * 4);
    heldWritten_ = false;
}

void DemoRecording::writeHeldUntil(double seconds, bool through) {
    if (held_.empty() || failure_) return;
    const double due = seconds * kFramesPerSecond;
    const auto isDue = [&] {
        const double frame = static_cast<double>(written_);
        return through ? frame <= due + 1e-6 : frame < due - 1e-6;  // slack: sums of 1/60 s steps
    };
    while (isDue()) {
        auto added = heldWritten_ ? writer_->repeat() : writer_->add(held_.data(), std::size_t{extent_.width} * 4);
        if (!added) {
            failure_ = added.error();
            return;
        }
        encoded_ += heldWritten_ ? 0 : 1;
        heldWritten_ = true;
        ++written_;
    }
}

Result<bool> DemoRecording::stop() {
    if (!active()) return true;
    presenter_->flushCaptures();
    writeHeldUntil(clock_, true);
    if (!failure_ && written_ == 0) failure_ = Error{Error::Kind::Runtime, "no frame was drawn while recording", {}};
    if (!failure_)
        if (auto finished = writer_->finish(); !finished) failure_ = finished.error();
    if (failure_) {
        Error error{failure_->kind, "recording " + path_ + " not saved: " + failure_->message, {}};
        abandon();
        return error;
    }
    log::report("saved " + path_ + ": " + std::to_string(written_) + " frames, " + seconds(static_cast<double>(written_) / kFramesPerSecond) +
                " at " + std::to_string(kFramesPerSecond) + " fps, " + std::to_string(encoded_) + " of them drawn (the others hold one)");
    writer_.reset();
    held_.clear();
    return true;
}

void DemoRecording::abandon() {
    writer_.reset();  // an unfinished writer removes its temporary
    presenter_->flushCaptures();  // frames still in flight are dropped, not handed to a later recording
    held_.clear();
    failure_.reset();
}

std::string DemoRecording::hudLine() const { return active() ? path_ + ", " + seconds(clock_) : std::string(); }

}  // namespace throng::app
