// Video output (video.h): H.264 in a fragmented MP4, or a GIF, through libavcodec and
// libavformat, the bytes streamed through core's StreamedOutputs; or numbered PNGs.
#include "throng/render/video.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "throng/core/atomic_file.h"
#include "gif_palette.h"
#include "throng/render/png.h"

namespace throng::render {
namespace {

std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

// Whether `pattern` holds exactly one printf integer conversion (%d, %05d, ...) and no other '%'
// but "%%": what framePath may hand to snprintf.
bool oneFrameConversion(const std::string& pattern) {
    int conversions = 0;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        while (j < pattern.size() && (std::isdigit(static_cast<unsigned char>(pattern[j])) != 0) && j - i <= 2) ++j;
        if (j >= pattern.size() || pattern[j] != 'd') return false;
        ++conversions;
        i = j;
    }
    return conversions == 1;
}

std::string avError(int code) {
    std::array<char, AV_ERROR_MAX_STRING_SIZE> text{};
    av_strerror(code, text.data(), text.size());
    return text.data();
}

}  // namespace

std::optional<VideoKind> videoKindOf(const std::string& path) {
    const std::string extension = lowerExtension(path);
    if (extension == ".mp4") return VideoKind::Mp4;
    if (extension == ".gif") return VideoKind::Gif;
    if (extension == ".png" && path.find('%') != std::string::npos) return VideoKind::PngFrames;
    return std::nullopt;
}

std::optional<std::string> videoPathProblem(const std::string& path) {
    if (videoKindOf(path) == VideoKind::PngFrames && !oneFrameConversion(path))
        return "a frame pattern takes one frame number, %d or %05d, and no other '%'";
    return std::nullopt;
}

std::string framePath(const std::string& pattern, std::int64_t index) {
    // %d takes an int: the pattern's conversion is rewritten to take a long long.
    std::string wide;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        wide += pattern[i];
        if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] == '%') {
            wide += pattern[++i];
            continue;
        }
        if (pattern[i] != '%') continue;
        while (i + 1 < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[i + 1])) != 0) wide += pattern[++i];
        if (i + 1 < pattern.size() && pattern[i + 1] == 'd') {
            wide += "ll";
        }
    }
    std::vector<char> out(wide.size() + 32);
    std::snprintf(out.data(), out.size(), wide.c_str(), static_cast<long long>(index));
    return out.data();
}

class VideoWriter::Impl {
public:
    explicit Impl(VideoSpec spec) : spec_(std::move(spec)) {}
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    virtual ~Impl() = default;
    virtual Result<bool> add(const std::uint8_t* rgba, std::size_t stride) = 0;
    virtual Result<bool> repeat() = 0;
    virtual Result<bool> finish() = 0;
    [[nodiscard]] virtual VideoKind kind() const = 0;

protected:
    [[nodiscard]] Error fault(const std::string& message) const { return Error{Error::Kind::BadInput, message, {spec_.path, 0, 0}}; }
    VideoSpec spec_;
};

namespace {

class PngFrames final : public VideoWriter::Impl {
public:
    explicit PngFrames(VideoSpec spec) : Impl(std::move(spec)), next_(spec_.firstFrame) {}
    Result<bool> add(const std::uint8_t* rgba, std::size_t stride) override {
        auto encoded = encodePng(spec_.width, spec_.height, rgba, stride);
        if (!encoded) return fault(encoded.error().message);
        last_ = std::move(encoded.value());
        return writeNext();
    }
    // The last frame's bytes again under the next number, written as atomically as any frame.
    Result<bool> repeat() override { return last_.empty() ? Result<bool>(true) : writeNext(); }
    Result<bool> finish() override { return true; }
    [[nodiscard]] VideoKind kind() const override { return VideoKind::PngFrames; }

private:
    Result<bool> writeNext() { return writeFileAtomically(framePath(spec_.path, next_++), last_); }

    std::int64_t next_;
    std::string last_;  ///< The last frame's PNG bytes, for repeat().
};

// libav's objects, each freed by its own function.
struct AvDeleter {
    void operator()(AVCodecContext* p) const { avcodec_free_context(&p); }
    void operator()(AVFrame* p) const { av_frame_free(&p); }
    void operator()(AVPacket* p) const { av_packet_free(&p); }
    void operator()(SwsContext* p) const { sws_freeContext(p); }
    void operator()(AVFormatContext* p) const { avformat_free_context(p); }
    void operator()(AVIOContext* p) const {
        av_freep(&p->buffer);
        avio_context_free(&p);
    }
};
template <typename T>
using AvPtr = std::unique_ptr<T, AvDeleter>;

// An MP4 (H.264, YUV 4:2:0 through swscale) or a GIF (FFmpeg's GIF encoder, 256 colours
// chosen from the first frame by GifPalette), written through libavformat into the file.
class Encoded final : public VideoWriter::Impl {
public:
    Encoded(VideoSpec spec, StreamedOutputs file, bool gif)
        : Impl(std::move(spec)), file_(std::move(file)), gif_(gif), name_(gif ? "GIF" : "MP4") {}

    Result<bool> open() {
        av_log_set_level(AV_LOG_ERROR);  // x264's statistics are not for the user; failures come back as errors
        const AVCodec* codec = gif_ ? avcodec_find_encoder(AV_CODEC_ID_GIF) : avcodec_find_encoder_by_name("libx264");
        if (codec == nullptr && !gif_) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
        if (codec == nullptr) return fault(gif_ ? "this FFmpeg has no GIF encoder" : "this FFmpeg has no H.264 encoder (Debian's libavcodec has libx264)");
        AVFormatContext* format = nullptr;
        if (avformat_alloc_output_context2(&format, nullptr, gif_ ? "gif" : "mp4", nullptr) < 0 || format == nullptr)
            return fault("FFmpeg has no " + name_ + " muxer");
        format_.reset(format);
        encoder_.reset(avcodec_alloc_context3(codec));
        encoder_->width = static_cast<int>(spec_.width);
        encoder_->height = static_cast<int>(spec_.height);
        encoder_->time_base = AVRational{1, spec_.framesPerSecond};
        encoder_->framerate = AVRational{spec_.framesPerSecond, 1};
        encoder_->pix_fmt = gif_ ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
        encoder_->gop_size = spec_.framesPerSecond * 2;
        encoder_->thread_count = gif_ ? 1 : 0;  // x264 picks; its bytes repeat for the same thread count (x264 is deterministic by default)
        if ((format_->oformat->flags & AVFMT_GLOBALHEADER) != 0) encoder_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        AVDictionary* codecOptions = nullptr;
        if (!gif_) {
            av_dict_set(&codecOptions, "preset", "veryfast", 0);
            av_dict_set(&codecOptions, "crf", "18", 0);
        }
        const int opened = avcodec_open2(encoder_.get(), codec, &codecOptions);
        av_dict_free(&codecOptions);
        if (opened < 0) return fault("cannot open the " + name_ + " encoder: " + avError(opened));
        AVStream* stream = avformat_new_stream(format_.get(), nullptr);
        if (stream == nullptr || avcodec_parameters_from_context(stream->codecpar, encoder_.get()) < 0) return fault("cannot add the video stream");
        stream->time_base = encoder_->time_base;
        stream_ = stream;
        constexpr int kBufferBytes = 1 << 16;
        auto* buffer = static_cast<unsigned char*>(av_malloc(kBufferBytes));
        io_.reset(avio_alloc_context(buffer, kBufferBytes, 1, this, nullptr, &Encoded::writeBytes, nullptr));
        format_->pb = io_.get();
        format_->flags |= AVFMT_FLAG_CUSTOM_IO;
        AVDictionary* muxOptions = nullptr;
        if (!gif_) av_dict_set(&muxOptions, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
        const int header = avformat_write_header(format_.get(), &muxOptions);
        av_dict_free(&muxOptions);
        if (header < 0) return writeFailure("cannot write the " + name_ + " header: " + avError(header));
        frame_.reset(av_frame_alloc());
        frame_->format = encoder_->pix_fmt;
        frame_->width = encoder_->width;
        frame_->height = encoder_->height;
        if (av_frame_get_buffer(frame_.get(), 0) < 0) return fault("out of memory for a video frame");
        packet_.reset(av_packet_alloc());
        if (gif_) return true;
        scaler_.reset(sws_getContext(encoder_->width, encoder_->height, AV_PIX_FMT_RGBA, encoder_->width, encoder_->height,
                                     AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr));
        if (!scaler_) return fault("cannot convert RGBA to YUV 4:2:0");
        return true;
    }

    Result<bool> add(const std::uint8_t* rgba, std::size_t stride) override {
        if (av_frame_make_writable(frame_.get()) < 0) return fault("out of memory for a video frame");
        if (gif_) {
            if (!palette_) palette_.emplace(rgba, spec_.width, spec_.height, stride);
            palette_->map(rgba, spec_.width, spec_.height, stride, frame_->data[0], static_cast<std::size_t>(frame_->linesize[0]));
            std::copy(palette_->argb().begin(), palette_->argb().end(), reinterpret_cast<std::uint32_t*>(frame_->data[1]));
        } else {
            const std::array<const std::uint8_t*, 1> planes{rgba};
            const std::array<int, 1> strides{static_cast<int>(stride)};
            sws_scale(scaler_.get(), planes.data(), strides.data(), 0, encoder_->height, frame_->data, frame_->linesize);
        }
        frame_->pts = frames_++;
        encodedUpTo_ = frames_;
        return encode(frame_.get());
    }

    Result<bool> repeat() override {
        if (frames_ > 0) ++frames_;  // the next frame's time moves on; the last one shows until then
        return true;
    }

    Result<bool> finish() override {
        // A last frame held past its own time is sent again at the end, so the video lasts as long.
        if (encodedUpTo_ < frames_) {
            frame_->pts = frames_ - 1;
            if (auto held = encode(frame_.get()); !held) return held;
        }
        if (auto flushed = encode(nullptr); !flushed) return flushed;
        const int trailer = av_write_trailer(format_.get());
        avio_flush(io_.get());
        if (trailer < 0 || failure_) return writeFailure("cannot finish the " + name_ + ": " + avError(trailer));
        return file_.commit();
    }

    [[nodiscard]] VideoKind kind() const override { return gif_ ? VideoKind::Gif : VideoKind::Mp4; }

private:
    // FFmpeg 5 (Debian 12) passes the bytes as non-const; they are only read.
    static int writeBytes(void* opaque, std::uint8_t* bytes, int size) {
        auto* self = static_cast<Encoded*>(opaque);
        auto appended = self->file_.append(0, std::string_view(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size)));
        if (appended) return size;
        self->failure_ = appended.error();
        return AVERROR(EIO);
    }

    Result<bool> encode(AVFrame* frame) {
        if (const int sent = avcodec_send_frame(encoder_.get(), frame); sent < 0) return fault("the " + name_ + " encoder refused a frame: " + avError(sent));
        while (true) {
            const int received = avcodec_receive_packet(encoder_.get(), packet_.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return true;
            if (received < 0) return fault("the " + name_ + " encoder failed: " + avError(received));
            // One frame time unless the encoder says otherwise: only the last packet's is read
            // (the others last until the next), and a held last frame then ends on time.
            if (packet_->duration <= 0) packet_->duration = 1;
            av_packet_rescale_ts(packet_.get(), encoder_->time_base, stream_->time_base);
            packet_->stream_index = stream_->index;
            const int written = av_interleaved_write_frame(format_.get(), packet_.get());
            if (written < 0) return writeFailure("cannot write to the " + name_ + ": " + avError(written));
        }
    }

    // A write that failed in StreamedOutputs says why (a full disk, ...); else libav's words.
    Result<bool> writeFailure(const std::string& message) { return failure_ ? *failure_ : fault(message); }

    StreamedOutputs file_;
    bool gif_;
    std::string name_;                ///< "MP4" or "GIF", for messages.
    std::optional<GifPalette> palette_;  ///< A GIF's colours, from its first frame.
    AvPtr<AVFormatContext> format_;
    AvPtr<AVCodecContext> encoder_;
    AvPtr<AVIOContext> io_;
    AvPtr<AVFrame> frame_;
    AvPtr<AVPacket> packet_;
    AvPtr<SwsContext> scaler_;
    AVStream* stream_ = nullptr;
    std::int64_t frames_ = 0;       ///< Frame times used, repeats included.
    std::int64_t encodedUpTo_ = 0;  ///< frames_ as of the last frame encoded.
    std::optional<Error> failure_;
};

}  // namespace

std::optional<Error> videoSpecProblem(const VideoSpec& spec) {
    const std::optional<VideoKind> kind = videoKindOf(spec.path);
    const auto refuse = [&](const std::string& message) { return Error{Error::Kind::BadInput, message, {spec.path, 0, 0}}; };
    if (!kind) return refuse("a video is written to FILE.mp4, FILE.gif or a frame pattern such as frames/%05d.png");
    if (spec.width == 0 || spec.height == 0 || spec.framesPerSecond < 1) return refuse("a video needs a size and a frame rate");
    if (auto problem = videoPathProblem(spec.path)) return refuse(*problem);
    if (*kind == VideoKind::Mp4 && (spec.width % 2 != 0 || spec.height % 2 != 0))
        return refuse("an MP4 (H.264, 4:2:0) needs an even width and height, not " + std::to_string(spec.width) + "x" + std::to_string(spec.height));
    // A GIF times each frame in hundredths of a second: past 100 fps two frames share a time
    // (the muxer fails after the render), and browsers show a delay under 2/100 s as 10/100.
    if (*kind == VideoKind::Gif && spec.framesPerSecond > kMaxGifFramesPerSecond)
        return refuse("a GIF times its frames in hundredths of a second, which browsers play at most " +
                      std::to_string(kMaxGifFramesPerSecond) + " a second: --fps " + std::to_string(kMaxGifFramesPerSecond) +
                      " at most (an MP4 takes up to 240)");
    return std::nullopt;
}

Result<VideoWriter> VideoWriter::open(const VideoSpec& spec) {
    if (auto problem = videoSpecProblem(spec)) return *problem;
    const VideoKind kind = *videoKindOf(spec.path);  // videoSpecProblem refused a path that names none
    VideoWriter writer;
    if (kind == VideoKind::PngFrames) {
        writer.impl_ = std::make_unique<PngFrames>(spec);
        return writer;
    }
    auto file = StreamedOutputs::open(std::span<const std::string>(&spec.path, 1));
    if (!file) return file.error();
    auto encoded = std::make_unique<Encoded>(spec, std::move(file.value()), kind == VideoKind::Gif);
    if (auto opened = encoded->open(); !opened) return opened.error();
    writer.impl_ = std::move(encoded);
    return writer;
}

Result<bool> VideoWriter::add(const std::uint8_t* rgba, std::size_t strideBytes) { return impl_->add(rgba, strideBytes); }
Result<bool> VideoWriter::repeat() { return impl_->repeat(); }
Result<bool> VideoWriter::finish() { return impl_->finish(); }
VideoKind VideoWriter::kind() const { return impl_->kind(); }
VideoWriter::VideoWriter() = default;
VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&&) noexcept = default;
VideoWriter::~VideoWriter() = default;

}  // namespace throng::render
