// H.264 video in an MP4 file, in memory, through FFmpeg's libraries: libx264, yuv420p (what slides, browsers
// and phones play), BT.709 limited range tagged, constant frame rate.
#pragma once

#include "fv/gfx/image.hpp"

#include <memory>
#include <string>

namespace fv::anim {

// Whether this FFmpeg has the libx264 encoder; "" or why not.
std::string h264_unavailable();

class Mp4Encoder {
  public:
    // width and height must be even (4:2:0 chroma). Throws std::runtime_error with a one-line reason.
    Mp4Encoder(int width, int height, double fps);
    ~Mp4Encoder();
    Mp4Encoder(const Mp4Encoder&) = delete;
    Mp4Encoder& operator=(const Mp4Encoder&) = delete;

    // Appends a frame of the encoder's size. Throws std::runtime_error.
    void add(const gfx::Image& frame);
    // Flushes the encoder and ends the file; returns its bytes. Throws std::runtime_error.
    std::string finish();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace fv::anim
