#pragma once
// Image error and trade-off metrics of `cavewall bench` (app/bench/gl/driver.h).
//
// Images are 8-bit RGBA (scenes::Image, rows top to bottom). Error is measured on R, G and B
// (screens are opaque; alpha carries no picture), as stored (sRGB-encoded), in [0, 1] units:
//  - RMSE and PSNR come from OpenImageIO's ImageBufAlgo::compare; PSNR = 20 log10(1 / RMSE) dB,
//    +infinity for identical images.
//  - SSIM (Wang et al. 2004) on luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (levels 0-255),
//    over 8x8 windows at a stride of 4 pixels with uniform weights, C1 = (0.01 * 255)^2,
//    C2 = (0.03 * 255)^2; the mean over windows. 1 for identical images. An image smaller than
//    8 pixels on a side is one window.
// Several comparisons pool by averaging the squared error (so RMSE/PSNR of a set is that of
// all its pixels together) and the SSIM. The mean PSNR of a set is the mean of its images'
// PSNRs (the target), each capped at kQuantisationPsnrDb so that an image equal to its
// reference counts as 8-bit quantisation noise rather than infinity; it is never below the
// pooled PSNR (Jensen), which is the stricter figure.

#include "scenes/scene.h"

#include <cstddef>
#include <vector>

namespace cavewall::bench {

struct ImageError {
    double mse = 0.0;       // mean squared error over R, G, B, [0, 1] units
    double rmse = 0.0;      // sqrt(mse)
    double psnrDb = 0.0;    // 20 log10(1 / rmse), +infinity when rmse == 0
    double ssim = 1.0;      // in [-1, 1], 1 = identical
    double meanPsnrDb = 0.0;  // pooled sets: mean per-image PSNR (capped); one image: its capped PSNR
};

// PSNR of uniform 8-bit quantisation noise: 10 log10(12 * 255^2) = 58.9 dB.
constexpr double kQuantisationPsnrDb = 58.92262;

// Compares `actual` against `reference`; throws cavewall::Error naming both when the sizes
// differ.
ImageError compareForBench(const scenes::Image& actual, const scenes::Image& reference);

// SSIM of the luminance of two same-sized images (see the header comment).
double ssimLuminance(const scenes::Image& a, const scenes::Image& b);

// PSNR in dB of a mean squared error in [0, 1] units (+infinity for 0).
double psnrFromMse(double mse);

// Pools several comparisons (mean MSE and mean SSIM); an empty set is "identical".
class ErrorPool {
public:
    void add(const ImageError& e);
    ImageError result() const;
    std::size_t count() const { return _count; }

private:
    double _mse = 0.0, _ssim = 0.0, _psnr = 0.0;
    std::size_t _count = 0;
};

// Frame-time percentiles (milliseconds), nearest-rank (display/timing.h); 0 for none.
struct TimeStats {
    double p50 = 0.0, p95 = 0.0, p99 = 0.0, mean = 0.0;
};
TimeStats timeStats(const std::vector<double>& samples);

// A point of the error-against-time trade-off: lower is better on both axes.
struct TradeOff {
    double time = 0.0;
    double error = 0.0;
};

// Indices of the points no other point dominates (another point is no worse on both axes
// and better on one), sorted by time. Equal points are all kept.
std::vector<std::size_t> paretoFront(const std::vector<TradeOff>& points);

}  // namespace cavewall::bench
