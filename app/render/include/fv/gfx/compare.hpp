#pragma once
// Image comparison for snapshot tests: tolerant of tiny rasterisation differences, with a
// diff image that shows where the pictures differ.
#include "fv/gfx/image.hpp"

namespace fv::gfx {

struct ImageComparison {
    int max_channel_diff =
        0; ///< Largest |actual - expected| over all pixels and channels (255 if sizes differ).
    double differing_share = 0; ///< Share of pixels whose largest channel difference exceeds the threshold.
    bool same_size = true;
    bool passed = false; ///< same_size && differing_share <= max_diff_share.
    Image diff;          ///< Expected in faint grey, differing pixels in red (empty if sizes differ).
};

/// A pixel "differs" when one of its channels differs by more than `max_channel_diff`.
/// The comparison passes when at most `max_diff_share` (0..1) of the pixels differ.
ImageComparison compare_images(const Image& actual, const Image& expected, int max_channel_diff,
                               double max_diff_share);

} // namespace fv::gfx
