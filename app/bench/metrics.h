#pragma once
// Image error and trade-off metrics of `cavewall bench` (app/bench/gl/driver.h).
//
// Images are 8-bit RGBA (scenes::Image, rows top to bottom), each compared with the
// full-geometry image of the same frame, eye and screen. A compared frame is every image shown
// at that instant (all screens and eyes); ErrorPool pools a mode's compared frames, over all
// screens and per screen:
//  - PSNR (metrics/image_error.h): the headline is the pooled PSNR, from the squared error of all
//    compared R, G, B samples of all frames; beside it the worst frame's PSNR and the 5th
//    percentile of per-frame PSNR. The mean of per-frame PSNRs capped at 58.9 dB (8-bit
//    quantisation) is kept only as a labelled column: it flatters, never rank by it.
//  - SSIM (metrics/ssim.h, 11x11 Gaussian window): the mean over compared images.
//  - FLIP (metrics/flip.h, LDR-FLIP) of every image at the pixels per degree the caller gives
//    (the bench: display::minPixelsPerDegree of the image's screen seen from the frame's
//    cyclopean eye). The mean is that of all compared pixels; beside it the share of all
//    compared pixels whose FLIP exceeds kFlipThreshold. A share, not a percentile: most compared
//    pixels match exactly, so FLIP's p95 (and often its p99) is 0 whatever the rest shows. The
//    image with the highest FLIP mean is kept as an error map (metrics::flipErrorImage).
//  - Popping (metrics/popping.h): one PoppingMeter per screen and eye, fed the consecutive
//    *compared* frames (every compareEvery-th frame, not every frame: a cross-fade shorter than
//    that interval scores as a hard switch). Peak: the largest pair over all screens; RMS over
//    all pairs of all screens.
//  - Stereo error (metrics/stereo_error.h), on stereo displays: per eye and pixel, the
//    disparity error in arc minutes of the eye's depth against the reference's (the viewer's
//    interocular distance), mean and share beyond 1 arcmin, over all compared pixels.

#include "metrics/image_error.h"
#include "metrics/popping.h"
#include "metrics/stereo_error.h"
#include "scenes/scene.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace cavewall::bench {

using metrics::kQuantisationPsnrDb;
using metrics::psnrFromMse;

// FLIP 0.1 is a colour difference, after the contrast sensitivity filters, of about 2.2 HyAB
// units (metrics/flip.h: 0.1 = 0.95 HyAB^0.7 / (0.4 * 41.3)), near CIELAB's just-noticeable
// difference of about 2.3: a pixel above it likely differs visibly to a viewer flipping the
// images (feature differences only raise FLIP).
constexpr double kFlipThreshold = 0.1;

// A set of comparisons, summarised.
struct ImageError {
    std::size_t frames = 0;  // compared frames
    double mse = 0.0;        // pooled over R, G, B of every compared pixel, [0, 1] units
    double rmse = 0.0;       // sqrt(mse)
    double psnrDb = std::numeric_limits<double>::infinity();  // pooled: the headline
    double worstFramePsnrDb = std::numeric_limits<double>::infinity();
    std::int64_t worstFrame = -1;                                    // its frame; -1 without frames
    double p5FramePsnrDb = std::numeric_limits<double>::infinity();  // 5th percentile per frame
    double meanPsnrDb = kQuantisationPsnrDb;                         // labelled only: capped mean of per-frame PSNRs
    double ssim = 1.0;                                               // mean over compared images, 1 = identical
    double flipMean = 0.0;                                           // over all compared pixels, [0, 1]
    double flipOverThreshold = 0.0;  // share of compared pixels with FLIP > kFlipThreshold, [0, 1]
    double poppingPeak = 0.0, poppingRms = 0.0;
    // On a stereo display: the stereo error (metrics/stereo_error.h) of every eye's depth
    // against the reference's at the same frame, eye and screen, pooled over all compared
    // pixels (the bench's ModeAccumulator fills it). Not measured in mono.
    bool stereoMeasured = false;
    metrics::StereoError stereo;
};

// One image of a compared frame. The images are only read during ErrorPool::addFrame.
struct ComparedImage {
    int screen = 0;  // index of the display screen, < the pool's screen count
    int image = 0;   // eye (RenderTargets image index)
    const scenes::Image* test = nullptr;
    const scenes::Image* reference = nullptr;
    double pixelsPerDegree = 0.0;  // FLIP's angular resolution for this image, in [1, 1000]
};

// The worst image's FLIP map.
struct FlipMap {
    scenes::Image image;  // metrics::flipErrorImage; empty when nothing was compared
    std::int64_t frame = -1;
    int screen = -1, eye = 0;
    double mean = 0.0;  // that image's FLIP mean
    // The two images compared: the mode's and full geometry's (the bench writes them with
    // --save-worst).
    scenes::Image test, reference;
};

// One compared image's error, as bench_compared.csv lists it.
struct ImageErrorRecord {
    std::int64_t frame = 0;
    int screen = 0, eye = 0;
    double psnrDb = 0.0, flipMean = 0.0;
};

// Accumulates a mode's compared frames (see the header comment).
class ErrorPool {
public:
    explicit ErrorPool(std::size_t screens);

    // Adds one compared frame. Throws cavewall::Error naming the images when a test image and
    // its reference differ in size; a screen out of range is a programmer error (assert).
    void addFrame(std::int64_t frame, const std::vector<ComparedImage>& images);

    ImageError result() const;  // all screens
    ImageError screenResult(std::size_t screen) const;
    const FlipMap& worstFlip() const { return _worst; }
    const std::vector<ImageErrorRecord>& images() const { return _images; }  // every compared image, in order

private:
    struct Series {
        metrics::PooledError psnr;
        double ssimSum = 0.0, flipSum = 0.0;
        std::size_t images = 0;
        std::uint64_t pixels = 0;
        std::uint64_t flipOver = 0;  // pixels with FLIP > kFlipThreshold
        metrics::PoppingSummary popping;
        double poppingSquares = 0.0;
    };
    static ImageError summarise(const Series& s);

    Series _all;
    std::vector<Series> _screens;
    std::map<std::pair<int, int>, metrics::PoppingMeter> _meters;  // (screen, eye)
    FlipMap _worst;
    std::vector<ImageErrorRecord> _images;
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
