#pragma once
// Frames in, a video out: an H.264 MP4 or a GIF through FFmpeg's libraries (libavcodec,
// libavformat, libswscale from Debian, linked, not a shelled-out binary), or numbered PNG files.
//
// An MP4 or GIF streams through a temporary beside the target (core's StreamedOutputs), renamed into
// place only by finish(): an error, Ctrl-C or SIGTERM leaves no file. It is fragmented
// (movflags frag_keyframe+empty_moov), so it needs no seeking back and its memory stays small
// however long the video; FFmpeg's tools, browsers and players read it, and parts rendered
// apart join with FFmpeg's concat demuxer without re-encoding. PNG frames are each written
// atomically, so a frame is either whole or absent.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "throng/core/error.h"

namespace throng::render {

/// What kind of output a path names.
enum class VideoKind : std::uint8_t {
    Mp4,        ///< FILE.mp4
    Gif,        ///< FILE.gif: 256 colours (median cut of the first frame, ordered dither), looping.
    PngFrames,  ///< A printf pattern with one integer conversion ending .png, e.g. frames/%05d.png.
};
/// The kind `path` names, or nullopt (a plain FILE.png is one image, not a video).
[[nodiscard]] std::optional<VideoKind> videoKindOf(const std::string& path);

/// Why a path videoKindOf accepts can't be written (a frame pattern without exactly one
/// integer conversion), or nullopt; VideoWriter::open refuses the same.
[[nodiscard]] std::optional<std::string> videoPathProblem(const std::string& path);

/// The path of frame `index` of a PngFrames pattern.
[[nodiscard]] std::string framePath(const std::string& pattern, std::int64_t index);

/// A GIF's frame rate limit: its delays are hundredths of a second, and browsers show one
/// under 2/100 s as 10/100.
inline constexpr int kMaxGifFramesPerSecond = 50;

struct VideoSpec {
    std::string path;                   ///< The target (an MP4) or a frame pattern.
    std::uint32_t width = 0, height = 0;  ///< Pixels; even for an MP4 (4:2:0 chroma).
    int framesPerSecond = 30;
    std::int64_t firstFrame = 0;        ///< Index of the first frame added (PNG names count from it).
};

/// Why `spec` can't be written (BadInput naming its path), or nullopt: what VideoWriter::open
/// refuses before it touches the disk, so a command can refuse it before it spends seconds
/// opening a device and building a crowd.
[[nodiscard]] std::optional<Error> videoSpecProblem(const VideoSpec& spec);

/// Writes frames one by one. Move-only; destroyed before finish(), it leaves no MP4.
class VideoWriter {
public:
    /// Checks the spec and opens the output (BadInput naming the path when it can't).
    [[nodiscard]] static Result<VideoWriter> open(const VideoSpec& spec);
    /// Adds one RGBA8 frame of the spec's size (`strideBytes` apart rows). Errors name the path.
    [[nodiscard]] Result<bool> add(const std::uint8_t* rgba, std::size_t strideBytes);
    /// The last frame added, once more: an MP4 or GIF holds it a frame longer without encoding
    /// it again (its timing varies), frame files get a copy. A no-op before the first add().
    [[nodiscard]] Result<bool> repeat();
    /// Flushes the encoder and puts the MP4 in place. Call once, after the last frame.
    [[nodiscard]] Result<bool> finish();
    [[nodiscard]] VideoKind kind() const;

    class Impl;  ///< One per kind (video.cpp).

    VideoWriter(VideoWriter&&) noexcept;
    VideoWriter& operator=(VideoWriter&&) noexcept;
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;
    ~VideoWriter();

private:
    VideoWriter();
    std::unique_ptr<Impl> impl_;
};

}  // namespace throng::render
