#pragma once
// Squared error of rendered images against their references, pooled over frames: the bench's
// headline PSNR.
//
// Error is measured on R, G and B (screens are opaque; alpha carries no picture), on the bytes
// as stored (sRGB-encoded), in [0, 1] units (byte / 255). PSNR = 10 log10(1 / MSE) dB, +infinity
// for MSE 0.
//
// Pooling: the pooled MSE of a set of frames is the squared error summed over every compared
// sample of every frame, divided by the number of samples: each pixel counts once, whatever
// frame it is in, and a frame equal to its reference adds samples but no error. The mean of
// per-frame PSNRs is not used for ranking: a frame equal to its reference has infinite PSNR, so
// it must be capped, and the capped values (58.9 dB for identical frames) lift the mean far
// above what the bad frames show (a control that drops whole cells scored 37 dB by that mean).

#include "scenes/scene.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace cavewall::metrics {

// PSNR of uniform 8-bit quantisation noise, 10 log10(12 * 255²): the cap of the labelled
// per-frame mean below.
constexpr double kQuantisationPsnrDb = 58.92262;

// PSNR in dB of a mean squared error in [0, 1] units; +infinity for 0.
double psnrFromMse(double mse);

struct SquaredError {
    double sum = 0.0;           // sum of (test - reference)² over R, G, B samples, [0, 1] units
    std::uint64_t samples = 0;  // R, G, B values compared: 3 per pixel

    double mse() const { return samples > 0 ? sum / static_cast<double>(samples) : 0.0; }
    double psnrDb() const { return psnrFromMse(mse()); }
    SquaredError& operator+=(const SquaredError& o) {
        sum += o.sum;
        samples += o.samples;
        return *this;
    }
};

// The squared error of `test` against `reference` (8-bit RGBA). Throws cavewall::Error naming
// both when their sizes differ or either is empty.
SquaredError squaredError(const scenes::Image& test, const scenes::Image& reference);

struct PooledErrorSummary {
    std::size_t frames = 0;
    double mse = 0.0;  // pooled: all squared errors over all samples of all frames
    double psnrDb = std::numeric_limits<double>::infinity();            // from the pooled MSE: the headline
    double worstFramePsnrDb = std::numeric_limits<double>::infinity();  // the lowest per-frame PSNR
    std::int64_t worstFrame = -1;  // its frame id (the first added on ties); -1 without frames
    // 5th percentile (nearest rank) of per-frame PSNR: at least 95 % of frames are this good.
    double p5FramePsnrDb = std::numeric_limits<double>::infinity();
    // Mean of per-frame PSNRs, each capped at kQuantisationPsnrDb. Flatters (see the header
    // comment): print it only labelled as such, never rank by it. 0 without frames.
    double cappedMeanPsnrDb = 0.0;
};

// Accumulates frames of one series (e.g. one bench mode on one screen) and summarises them.
class PooledError {
public:
    // Adds one frame's error: one image's squaredError, or several images' (screens, eyes)
    // summed with += when a frame is everything shown at one instant. `frameId` is the caller's
    // name for the frame, reported back as worstFrame.
    void addFrame(std::int64_t frameId, const SquaredError& error);

    PooledErrorSummary summary() const;
    std::size_t frames() const { return _frames.size(); }

private:
    struct Frame {
        std::int64_t id;
        double psnrDb;
    };
    SquaredError _total;
    std::vector<Frame> _frames;
};

}  // namespace cavewall::metrics
