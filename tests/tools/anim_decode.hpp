// Decoders for the animation tests: a GIF through giflib (DGifSlurp, frames composited as a viewer shows
// them) and an MP4 through libavformat/libavcodec (every frame converted to RGBA). Header-only; link giflib
// and FFmpeg's libraries.
#pragma once

#include "fv/gfx/image.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}
#include <gif_lib.h>

#include <cstring>
#include <string>
#include <vector>

namespace fv::test {

struct DecodedGif {
    std::string error; // empty when read
    int width = 0, height = 0;
    int image_count = 0;
    bool loops = false; // NETSCAPE2.0 application extension with a repeat count of 0 (forever)
    std::vector<int> delays_cs;
    std::vector<gfx::Image> frames; // composited (disposal "do not dispose": each frame draws over the last)
};

inline DecodedGif decode_gif(const std::string& path) {
    DecodedGif out;
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
    if (!gif) {
        out.error = GifErrorString(error);
        return out;
    }
    if (DGifSlurp(gif) != GIF_OK) {
        out.error = GifErrorString(gif->Error);
        DGifCloseFile(gif, &error);
        return out;
    }
    out.width = gif->SWidth;
    out.height = gif->SHeight;
    out.image_count = gif->ImageCount;
    gfx::Image canvas(out.width, out.height);
    for (int i = 0; i < gif->ImageCount; ++i) {
        const SavedImage& im = gif->SavedImages[i];
        for (int e = 0; e + 1 < im.ExtensionBlockCount; ++e) {
            const ExtensionBlock& b = im.ExtensionBlocks[e];
            if (b.Function == APPLICATION_EXT_FUNC_CODE && b.ByteCount == 11 &&
                std::memcmp(b.Bytes, "NETSCAPE2.0", 11) == 0) {
                const ExtensionBlock& sub = im.ExtensionBlocks[e + 1];
                out.loops = sub.ByteCount == 3 && sub.Bytes[0] == 1 && sub.Bytes[1] == 0 && sub.Bytes[2] == 0;
            }
        }
        GraphicsControlBlock gcb{};
        DGifSavedExtensionToGCB(gif, i, &gcb);
        out.delays_cs.push_back(gcb.DelayTime);
        const ColorMapObject* map = im.ImageDesc.ColorMap ? im.ImageDesc.ColorMap : gif->SColorMap;
        const GifImageDesc& d = im.ImageDesc;
        for (int y = 0; y < d.Height; ++y)
            for (int x = 0; x < d.Width; ++x) {
                const GifByteType idx = im.RasterBits[y * d.Width + x];
                if (idx == gcb.TransparentColor) continue;
                std::uint8_t* p = canvas.pixel(d.Left + x, d.Top + y);
                p[0] = map->Colors[idx].Red;
                p[1] = map->Colors[idx].Green;
                p[2] = map->Colors[idx].Blue;
                p[3] = 255;
            }
        out.frames.push_back(canvas);
    }
    DGifCloseFile(gif, &error);
    return out;
}

struct DecodedVideo {
    std::string error;
    std::string container, codec, pix_fmt;
    int width = 0, height = 0;
    double fps = 0;
    std::vector<gfx::Image> frames;
};

inline DecodedVideo decode_video(const std::string& path) {
    DecodedVideo out;
    AVFormatContext* fmt = nullptr;
    if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0) {
        out.error = "cannot open " + path;
        return out;
    }
    out.container = fmt->iformat->name;
    if (avformat_find_stream_info(fmt, nullptr) < 0) out.error = "no stream info";
    const int s = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (s < 0) {
        out.error = "no video stream";
        avformat_close_input(&fmt);
        return out;
    }
    AVStream* st = fmt->streams[s];
    const AVCodec* dec = avcodec_find_decoder(st->codecpar->codec_id);
    out.codec = avcodec_get_name(st->codecpar->codec_id);
    out.width = st->codecpar->width;
    out.height = st->codecpar->height;
    out.fps = av_q2d(st->avg_frame_rate);
    const char* pf = av_get_pix_fmt_name(static_cast<AVPixelFormat>(st->codecpar->format));
    out.pix_fmt = pf ? pf : "";
    AVCodecContext* c = avcodec_alloc_context3(dec);
    avcodec_parameters_to_context(c, st->codecpar);
    if (!dec || avcodec_open2(c, dec, nullptr) < 0) {
        out.error = "no decoder";
        avcodec_free_context(&c);
        avformat_close_input(&fmt);
        return out;
    }
    AVPacket* pkt = av_packet_alloc();
    AVFrame* f = av_frame_alloc();
    SwsContext* sws = nullptr;
    auto drain = [&] {
        while (avcodec_receive_frame(c, f) == 0) {
            sws = sws_getCachedContext(sws, f->width, f->height, static_cast<AVPixelFormat>(f->format),
                                       f->width, f->height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr, nullptr,
                                       nullptr);
            gfx::Image img(f->width, f->height);
            std::uint8_t* dst[1] = {img.rgba.data()};
            const int stride[1] = {img.width * 4};
            sws_scale(sws, f->data, f->linesize, 0, f->height, dst, stride);
            out.frames.push_back(std::move(img));
        }
    };
    while (av_read_frame(fmt, pkt) >= 0) {
        if (pkt->stream_index == s && avcodec_send_packet(c, pkt) == 0) drain();
        av_packet_unref(pkt);
    }
    avcodec_send_packet(c, nullptr);
    drain();
    sws_freeContext(sws);
    av_frame_free(&f);
    av_packet_free(&pkt);
    avcodec_free_context(&c);
    avformat_close_input(&fmt);
    return out;
}

// Mean absolute difference per channel (RGB) of two images of one size, in [0, 255].
inline double mean_abs_diff(const gfx::Image& a, const gfx::Image& b) {
    double sum = 0;
    const std::size_t n = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
    for (std::size_t k = 0; k < n; ++k)
        for (int c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[4 * k + c]) - int(b.rgba[4 * k + c]));
    return sum / (3.0 * static_cast<double>(n));
}

} // namespace fv::test
