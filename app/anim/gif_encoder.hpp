// Animated GIF in memory through giflib: one global palette for every frame (the picture's flat colours
// exactly, median cut for the rest: no dithering, so flat areas stay flat and do not flicker), each frame
// after the first only the rectangle that changed, unchanged pixels in it transparent, looping forever
// (NETSCAPE2.0).
#pragma once

#include "fv/gfx/image.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fv::anim {

// At most 255 RGB colours (the 256th index is transparency) for the frames `samples` (all of the size of the
// animation): every colour that covers at least 0.05 % of the sampled pixels exactly (up to 96 of them:
// backgrounds, fills, lines), the other pixels' colours median-cut into what is left, each box its pixels'
// mean.
std::vector<std::array<std::uint8_t, 3>> build_palette(const std::vector<const gfx::Image*>& samples);

class GifEncoder {
  public:
    // Throws std::runtime_error when giflib fails (out of memory).
    GifEncoder(int width, int height, std::vector<std::array<std::uint8_t, 3>> palette);
    ~GifEncoder();
    GifEncoder(const GifEncoder&) = delete;
    GifEncoder& operator=(const GifEncoder&) = delete;

    // Appends a frame (of the encoder's size) shown for delay_cs hundredths of a second. Throws
    // std::runtime_error on a giflib error.
    void add(const gfx::Image& frame, int delay_cs);
    // Ends the file; returns its bytes. Throws std::runtime_error on a giflib error.
    std::string finish();

  private:
    std::uint8_t index_of(const std::uint8_t* rgb);

    int w_, h_;
    std::vector<std::array<std::uint8_t, 3>> palette_;
    std::vector<std::uint16_t> lookup_; // 2^24 entries: palette index of an RGB colour, 0xFFFF unknown
    std::vector<std::uint8_t> previous_, current_, line_;
    int transparent_ = 255; // the colour table's last index: unchanged pixels
    int frames_ = 0;
    void* gif_ = nullptr; // GifFileType
    std::string out_;
};

// GIF frame delays in hundredths of a second for `fps`, rounded so that the sum over frames keeps the frame
// rate (30 fps: 3, 3, 4, 3, 3, 4, ... cs) rather than drifting to 33.3 fps.
int gif_delay_cs(int frame, double fps);

} // namespace fv::anim
