#include "mp4_encoder.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace fv::anim {
namespace {

std::string av_error(int code) {
    char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
    av_strerror(code, buf, sizeof buf);
    return buf;
}

void check(int code, const char* what) {
    if (code < 0) throw std::runtime_error(std::string("MP4 encoder: ") + what + ": " + av_error(code));
}

// A growable, seekable file in memory for the MP4 muxer (it goes back to write the sizes of its boxes).
struct MemoryFile {
    std::string bytes;
    std::size_t pos = 0;
};

int write_memory(void* opaque, std::uint8_t* buf, int size) {
    auto* f = static_cast<MemoryFile*>(opaque);
    const std::size_t n = static_cast<std::size_t>(size);
    if (f->bytes.size() < f->pos + n) f->bytes.resize(f->pos + n);
    std::memcpy(&f->bytes[f->pos], buf, n);
    f->pos += n;
    return size;
}

std::int64_t seek_memory(void* opaque, std::int64_t offset, int whence) {
    auto* f = static_cast<MemoryFile*>(opaque);
    std::int64_t base = 0;
    switch (whence & ~AVSEEK_FORCE) {
    case AVSEEK_SIZE:
        return static_cast<std::int64_t>(f->bytes.size());
    case SEEK_SET:
        base = 0;
        break;
    case SEEK_CUR:
        base = static_cast<std::int64_t>(f->pos);
        break;
    case SEEK_END:
        base = static_cast<std::int64_t>(f->bytes.size());
        break;
    default:
        return AVERROR(EINVAL);
    }
    if (base + offset < 0) return AVERROR(EINVAL);
    f->pos = static_cast<std::size_t>(base + offset);
    return base + offset;
}

} // namespace

std::string h264_unavailable() {
    if (!avcodec_find_encoder_by_name("libx264"))
        return "this FFmpeg (libavcodec " AV_STRINGIFY(LIBAVCODEC_VERSION) ") has no libx264 encoder";
    return {};
}

struct Mp4Encoder::Impl {
    MemoryFile file;
    AVFormatContext* fmt = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVIOContext* io = nullptr;
    SwsContext* sws = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    std::int64_t next_pts = 0;
    bool header = false;

    ~Impl() {
        av_packet_free(&packet);
        av_frame_free(&frame);
        sws_freeContext(sws);
        avcodec_free_context(&codec);
        if (io) {
            av_freep(&io->buffer);
            avio_context_free(&io);
        }
        avformat_free_context(fmt);
    }

    // Sends `f` (nullptr: flush) and writes every packet the encoder has ready.
    void encode(AVFrame* f) {
        check(avcodec_send_frame(codec, f), "encoding a frame");
        for (;;) {
            const int r = avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
            check(r, "encoding a frame");
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(fmt, packet), "writing a frame");
        }
    }
};

Mp4Encoder::Mp4Encoder(int width, int height, double fps) : impl_(std::make_unique<Impl>()) {
    if (width % 2 || height % 2)
        throw std::runtime_error("MP4 encoder: yuv420p needs an even width and height");
    Impl& m = *impl_;
    av_log_set_level(AV_LOG_ERROR); // libx264's statistics are not for the user
    const AVCodec* x264 = avcodec_find_encoder_by_name("libx264");
    if (!x264) throw std::runtime_error("MP4 encoder: " + h264_unavailable());
    check(avformat_alloc_output_context2(&m.fmt, nullptr, "mp4", nullptr), "mp4 muxer");
    m.stream = avformat_new_stream(m.fmt, nullptr);
    m.codec = avcodec_alloc_context3(x264);
    m.frame = av_frame_alloc();
    m.packet = av_packet_alloc();
    if (!m.stream || !m.codec || !m.frame || !m.packet)
        throw std::runtime_error("MP4 encoder: out of memory");

    const AVRational rate = av_d2q(fps, 100000);
    m.codec->width = width;
    m.codec->height = height;
    m.codec->time_base = av_inv_q(rate);
    m.codec->framerate = rate;
    m.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    m.codec->color_range = AVCOL_RANGE_MPEG;
    m.codec->colorspace = AVCOL_SPC_BT709;
    m.codec->color_primaries = AVCOL_PRI_BT709;
    m.codec->color_trc = AVCOL_TRC_BT709;
    m.codec->gop_size = std::max(1, static_cast<int>(fps * 2));
    if (m.fmt->oformat->flags & AVFMT_GLOBALHEADER) m.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* opts = nullptr;
    // Drawings: flat colours and thin lines. CRF 20 keeps lines and text sharp at a few hundred kB per
    // loop; "animation" tuning suits flat areas; "faster" is the budget on two cores.
    av_dict_set(&opts, "preset", "faster", 0);
    av_dict_set(&opts, "tune", "animation", 0);
    av_dict_set(&opts, "crf", "20", 0);
    const int opened = avcodec_open2(m.codec, x264, &opts);
    av_dict_free(&opts);
    check(opened, "libx264");
    check(avcodec_parameters_from_context(m.stream->codecpar, m.codec), "stream parameters");
    m.stream->time_base = m.codec->time_base;
    m.stream->avg_frame_rate = rate;

    constexpr int kIoBuffer = 1 << 16;
    auto* buffer = static_cast<unsigned char*>(av_malloc(kIoBuffer));
    m.io = buffer ? avio_alloc_context(buffer, kIoBuffer, 1, &m.file, nullptr, write_memory, seek_memory)
                  : nullptr;
    if (!m.io) {
        av_free(buffer);
        throw std::runtime_error("MP4 encoder: out of memory");
    }
    m.fmt->pb = m.io;
    m.fmt->flags |= AVFMT_FLAG_CUSTOM_IO;
    check(avformat_write_header(m.fmt, nullptr), "mp4 header");
    m.header = true;

    m.frame->format = AV_PIX_FMT_YUV420P;
    m.frame->width = width;
    m.frame->height = height;
    check(av_frame_get_buffer(m.frame, 0), "frame buffer");
    m.sws = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                           SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
    if (!m.sws) throw std::runtime_error("MP4 encoder: no RGBA to yuv420p conversion");
    // BT.709 matrix into limited range, as tagged above (the default would be BT.601).
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(m.sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
}

Mp4Encoder::~Mp4Encoder() = default;

void Mp4Encoder::add(const gfx::Image& img) {
    Impl& m = *impl_;
    if (img.width != m.codec->width || img.height != m.codec->height)
        throw std::runtime_error("MP4 encoder: frame size changed");
    check(av_frame_make_writable(m.frame), "frame buffer");
    const std::uint8_t* src[1] = {img.rgba.data()};
    const int stride[1] = {img.width * 4};
    sws_scale(m.sws, src, stride, 0, img.height, m.frame->data, m.frame->linesize);
    m.frame->pts = m.next_pts++;
    m.encode(m.frame);
}

std::string Mp4Encoder::finish() {
    Impl& m = *impl_;
    m.encode(nullptr);
    check(av_write_trailer(m.fmt), "mp4 trailer");
    avio_flush(m.io);
    return std::move(m.file.bytes);
}

} // namespace fv::anim
