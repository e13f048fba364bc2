#include "gif_encoder.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace fv::anim {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr std::uint32_t pack(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) << 16 | static_cast<std::uint32_t>(p[1]) << 8 | p[2];
}

struct Weighted {
    std::uint32_t rgb;
    std::uint64_t count;
    int channel(int c) const { return static_cast<int>(rgb >> (16 - 8 * c) & 0xFF); }
};

// One box of the median cut: a range of `colors`.
struct Box {
    std::size_t begin, end;
    std::uint64_t pixels = 0;
    int longest = 0, span = 0;
};

void measure(Box& b, const std::vector<Weighted>& colors) {
    int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
    b.pixels = 0;
    for (std::size_t k = b.begin; k < b.end; ++k) {
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], colors[k].channel(c));
            hi[c] = std::max(hi[c], colors[k].channel(c));
        }
        b.pixels += colors[k].count;
    }
    b.span = -1;
    for (int c = 0; c < 3; ++c)
        if (hi[c] - lo[c] > b.span) b.span = hi[c] - lo[c], b.longest = c;
}

Rgb mean_of(const Box& b, const std::vector<Weighted>& colors) {
    double sum[3] = {0, 0, 0}, n = 0;
    for (std::size_t k = b.begin; k < b.end; ++k) {
        const double w = static_cast<double>(colors[k].count);
        for (int c = 0; c < 3; ++c) sum[c] += w * colors[k].channel(c);
        n += w;
    }
    Rgb out{};
    for (int c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(std::lround(sum[c] / n));
    return out;
}

// Splits the remaining colours into at most `boxes` boxes: always the box with the widest channel range
// weighted by the square root of its pixel count (so that rare anti-aliasing shades still get a few
// entries), at the pixel-weighted median of that channel.
std::vector<Rgb> median_cut(std::vector<Weighted> colors, std::size_t boxes) {
    std::vector<Rgb> out;
    if (colors.empty() || boxes == 0) return out;
    std::vector<Box> work{{0, colors.size()}};
    measure(work[0], colors);
    while (work.size() < boxes) {
        std::size_t best = work.size();
        double best_score = 0;
        for (std::size_t k = 0; k < work.size(); ++k) {
            if (work[k].end - work[k].begin < 2 || work[k].span == 0) continue;
            const double score = work[k].span * std::sqrt(static_cast<double>(work[k].pixels));
            if (score > best_score) best_score = score, best = k;
        }
        if (best == work.size()) break;
        Box b = work[best];
        const int c = b.longest;
        std::sort(colors.begin() + static_cast<std::ptrdiff_t>(b.begin),
                  colors.begin() + static_cast<std::ptrdiff_t>(b.end),
                  [c](const Weighted& x, const Weighted& y) { return x.channel(c) < y.channel(c); });
        std::uint64_t acc = 0;
        std::size_t cut = b.begin + 1;
        for (std::size_t k = b.begin; k + 1 < b.end; ++k) {
            acc += colors[k].count;
            cut = k + 1;
            if (2 * acc >= b.pixels) break;
        }
        Box lo{b.begin, cut}, hi{cut, b.end};
        measure(lo, colors);
        measure(hi, colors);
        work[best] = lo;
        work.push_back(hi);
    }
    for (const Box& b : work) out.push_back(mean_of(b, colors));
    return out;
}

int write_to_string(GifFileType* gif, const GifByteType* data, int len) {
    static_cast<std::string*>(gif->UserData)
        ->append(reinterpret_cast<const char*>(data), static_cast<std::size_t>(len));
    return len;
}

GifFileType* as_gif(void* p) {
    return static_cast<GifFileType*>(p);
}

void check(int result, GifFileType* gif, const char* what) {
    if (result == GIF_ERROR)
        throw std::runtime_error(std::string("GIF encoder: ") + what + ": " + GifErrorString(gif->Error));
}

} // namespace

std::vector<Rgb> build_palette(const std::vector<const gfx::Image*>& samples) {
    std::unordered_map<std::uint32_t, std::uint64_t> counts;
    std::uint64_t total = 0;
    for (const gfx::Image* img : samples) {
        const std::size_t n = static_cast<std::size_t>(img->width) * static_cast<std::size_t>(img->height);
        for (std::size_t k = 0; k < n; ++k) ++counts[pack(&img->rgba[4 * k])];
        total += n;
    }
    std::vector<Weighted> colors;
    colors.reserve(counts.size());
    for (const auto& [rgb, count] : counts) colors.push_back({rgb, count});
    std::sort(colors.begin(), colors.end(), [](const Weighted& a, const Weighted& b) {
        return a.count != b.count ? a.count > b.count : a.rgb < b.rgb;
    });
    std::vector<Rgb> palette;
    auto unpack = [](std::uint32_t rgb) {
        return Rgb{static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8),
                   static_cast<std::uint8_t>(rgb)};
    };
    // 255 colours: the last index of the table is the transparent one (pixels that did not change).
    if (colors.size() <= 255) {
        for (const Weighted& c : colors) palette.push_back(unpack(c.rgb));
        return palette;
    }
    // Flat colours exactly: what covers at least 1/2000 of the pixels.
    constexpr std::size_t kMaxExact = 96;
    std::size_t exact = 0;
    while (exact < kMaxExact && exact < colors.size() && colors[exact].count * 2000 >= total) ++exact;
    for (std::size_t k = 0; k < exact; ++k) palette.push_back(unpack(colors[k].rgb));
    std::vector<Weighted> rest(colors.begin() + static_cast<std::ptrdiff_t>(exact), colors.end());
    for (const Rgb& c : median_cut(std::move(rest), 255 - exact)) palette.push_back(c);
    return palette;
}

int gif_delay_cs(int frame, double fps) {
    const auto at = [fps](int k) { return std::lround(100.0 * k / fps); };
    return static_cast<int>(at(frame + 1) - at(frame));
}

GifEncoder::GifEncoder(int width, int height, std::vector<Rgb> palette)
    : w_(width), h_(height), palette_(std::move(palette)), lookup_(std::size_t{1} << 24, 0xFFFF) {
    if (palette_.empty()) palette_.push_back({255, 255, 255});
    int error = 0;
    GifFileType* gif = EGifOpen(&out_, write_to_string, &error);
    if (!gif) throw std::runtime_error(std::string("GIF encoder: ") + GifErrorString(error));
    gif_ = gif;
    EGifSetGifVersion(gif, true); // GIF89a: graphics control and application extensions
    // The colour table has a power-of-two size: unused entries repeat the last colour.
    int bits = 1;
    while ((1 << bits) < static_cast<int>(palette_.size()) + 1) ++bits; // + the transparent index
    transparent_ = (1 << bits) - 1;
    std::vector<GifColorType> table(std::size_t{1} << bits);
    for (std::size_t k = 0; k < table.size(); ++k) {
        const Rgb& c = palette_[std::min(k, palette_.size() - 1)];
        table[k] = {c[0], c[1], c[2]};
    }
    ColorMapObject* map = GifMakeMapObject(static_cast<int>(table.size()), table.data());
    if (!map) throw std::runtime_error("GIF encoder: out of memory");
    const int r = EGifPutScreenDesc(gif, w_, h_, bits, 0, map);
    GifFreeMapObject(map);
    check(r, gif, "screen descriptor");
    // Loop forever: NETSCAPE2.0 with a repeat count of 0.
    const GifByteType loop[3] = {1, 0, 0};
    check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif, "loop extension");
    check(EGifPutExtensionBlock(gif, 11, "NETSCAPE2.0"), gif, "loop extension");
    check(EGifPutExtensionBlock(gif, 3, loop), gif, "loop extension");
    check(EGifPutExtensionTrailer(gif), gif, "loop extension");
}

GifEncoder::~GifEncoder() {
    if (gif_) EGifCloseFile(as_gif(gif_), nullptr);
}

std::uint8_t GifEncoder::index_of(const std::uint8_t* rgb) {
    std::uint16_t& slot = lookup_[pack(rgb)];
    if (slot == 0xFFFF) {
        // The nearest palette colour, distances weighted roughly by the eye's sensitivity.
        long best = std::numeric_limits<long>::max();
        for (std::size_t k = 0; k < palette_.size(); ++k) {
            const long dr = rgb[0] - palette_[k][0], dg = rgb[1] - palette_[k][1],
                       db = rgb[2] - palette_[k][2];
            const long d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
            if (d < best) best = d, slot = static_cast<std::uint16_t>(k);
        }
    }
    return static_cast<std::uint8_t>(slot);
}

void GifEncoder::add(const gfx::Image& frame, int delay_cs) {
    GifFileType* gif = as_gif(gif_);
    if (frame.width != w_ || frame.height != h_) throw std::runtime_error("GIF encoder: frame size changed");
    const std::size_t n = static_cast<std::size_t>(w_) * static_cast<std::size_t>(h_);
    current_.resize(n);
    for (std::size_t k = 0; k < n; ++k) current_[k] = index_of(&frame.rgba[4 * k]);
    // Only the rectangle that changed since the previous frame (which stays: disposal "do not dispose").
    int x0 = 0, y0 = 0, x1 = w_ - 1, y1 = h_ - 1;
    if (frames_ > 0) {
        x0 = w_, y0 = h_, x1 = -1, y1 = -1;
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x) {
                const std::size_t k =
                    static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x);
                if (current_[k] == previous_[k]) continue;
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        if (x1 < 0) x0 = y0 = x1 = y1 = 0; // nothing changed: one pixel, held for the delay
    }
    GraphicsControlBlock gcb{};
    gcb.DisposalMode = DISPOSE_DO_NOT;
    gcb.DelayTime = delay_cs;
    // Inside the rectangle, what did not change is transparent: long runs of one index compress well.
    gcb.TransparentColor = frames_ > 0 ? transparent_ : NO_TRANSPARENT_COLOR;
    GifByteType ext[4];
    const std::size_t len = EGifGCBToExtension(&gcb, ext);
    check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(len), ext), gif, "frame delay");
    const int rw = x1 - x0 + 1, rh = y1 - y0 + 1;
    check(EGifPutImageDesc(gif, x0, y0, rw, rh, false, nullptr), gif, "image descriptor");
    line_.resize(static_cast<std::size_t>(rw));
    for (int y = y0; y <= y1; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(w_);
        for (int x = x0; x <= x1; ++x) {
            const std::size_t k = row + static_cast<std::size_t>(x);
            line_[static_cast<std::size_t>(x - x0)] = frames_ > 0 && current_[k] == previous_[k]
                                                          ? static_cast<std::uint8_t>(transparent_)
                                                          : current_[k];
        }
        check(EGifPutLine(gif, line_.data(), rw), gif, "pixels");
    }
    previous_.swap(current_);
    ++frames_;
}

std::string GifEncoder::finish() {
    int error = 0;
    GifFileType* gif = as_gif(gif_);
    gif_ = nullptr;
    if (EGifCloseFile(gif, &error) == GIF_ERROR)
        throw std::runtime_error(std::string("GIF encoder: ") + GifErrorString(error));
    return std::move(out_);
}

} // namespace fv::anim
