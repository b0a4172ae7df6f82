#pragma once
// Comparing a rendered image against a reference (golden) image.
//
// Per pixel, Δ is the largest difference over the R, G, B and A channels, in 8-bit levels
// (0-255). A comparison summarises Δ over the image: the largest, the mean, the share of
// pixels above a threshold, and the worst pixels for a failure message. The default tolerance
// is the project's golden-image rule for llvmpipe (STYLE.md §5): pass when at most 0.1 % of
// the pixels have Δ > 3 and the mean Δ is at most 0.3. Pure data paths should use
// ImageTolerance::exact().

#include "scenes/scene.h"

#include <string>
#include <vector>

namespace cavewall::metrics {

struct ImageTolerance {
    int badDelta = 3;               // a pixel with Δ above this is "bad"
    double maxBadFraction = 0.001;  // largest allowed share of bad pixels, in [0, 1]
    double maxMeanDelta = 0.3;      // largest allowed mean Δ over all pixels

    static ImageTolerance exact() { return {0, 0.0, 0.0}; }
};

struct PixelDelta {
    int x = 0, y = 0;  // pixel, origin top-left (rows as stored in files)
    int delta = 0;     // Δ, 0-255
    bool operator==(const PixelDelta&) const = default;
};

struct ImageComparison {
    bool sameSize = false;  // false: nothing else is meaningful, and passes() fails
    int maxDelta = 0;
    double meanDelta = 0.0;
    double badFraction = 0.0;       // share of pixels with Δ > tolerance.badDelta
    std::vector<PixelDelta> worst;  // largest Δ first (ties: top-left first), at most `worstCount`
    ImageTolerance tolerance;       // what the comparison was made against

    bool passes() const;
    // One paragraph for test output: sizes or max/mean/bad fraction, then the worst pixels.
    std::string describe() const;
};

// Compares `actual` against `expected` (both 8-bit RGBA, rows top to bottom).
ImageComparison compareImages(const scenes::Image& actual, const scenes::Image& expected, ImageTolerance tolerance = {},
                              int worstCount = 10);

// A picture of the differences, the size of `actual`: grey where Δ ≤ tolerance.badDelta (a
// faded copy of `expected`, to see where things are), red scaled by Δ elsewhere. Opaque.
// Requires images of the same size.
scenes::Image differenceImage(const scenes::Image& actual, const scenes::Image& expected,
                              ImageTolerance tolerance = {});

}  // namespace cavewall::metrics
