#pragma once
// Stereo error: how far the depth a viewer perceives with two eyes in a rendered image departs
// from the reference's, per pixel, as an angle of binocular disparity.
//
// Definition. Each eye's image comes with a depth image: per pixel, the distance z (metres)
// from that eye to the surface the pixel shows. A surface at distance z seen by eyes an
// interocular distance b apart subtends the vergence angle
//     v(z) = 2 atan(b / (2 z))        (radians; about b / z once z >> b)
// and v(inf) = 0: the background (and anything at infinite depth) has no disparity. The
// disparity error of a pixel is |v(z_test) - v(z_ref)|, in arc minutes. Relative disparity is
// what stereopsis resolves (Howard & Rogers 2012, "Perceiving in Depth"), and the vergence
// difference between two depths is exactly the relative disparity between them, so the error is
// the disparity a viewer would have to resolve to see that the test's depth is wrong. Every
// pixel of every eye counts once.
//
// Why it tells walls apart: a flat virtual wall (Ebbesmeyer 1997) shows all it stands for at
// the wall's own depth, so a scene 3..30 m behind a wall at 3 m is seen at 3 m (v = 73 arcmin
// for b = 64 mm) instead of at 7 to 73 arcmin; a depth wall reprojects each texel to its own
// depth and keeps the error at what its depths and march miss.
//
// Threshold. The share of pixels whose error exceeds `thresholdArcmin` (default 1 arcmin) is
// reported beside the mean. Coutant & Westheimer (1993) measured stereoacuity in a population:
// about 80 % resolve 0.5 arcmin and 97 % resolve 2.3 arcmin. 1 arcmin sits between, a
// threshold most viewers of a CAVE can resolve; errors below it pass for most of them.
//
// Invalid depths. A depth that is NaN, negative or zero (not a distance) makes its pixel
// invalid: it is left out of the mean and the share and counted in `invalidPixels`. +infinity
// is valid (background). Both images of a pair must have the same size.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::metrics {

// Distances from one eye to the surface each pixel shows, metres, rows top to bottom.
struct DepthImage {
    std::string name;  // for messages
    int width = 0, height = 0;
    std::vector<float> metres;  // width * height; +inf: background
};

struct StereoErrorOptions {
    double interocularMetres = 0.064;  // b, > 0 and finite
    double thresholdArcmin = 1.0;      // stereoacuity threshold of the share, >= 0
};

// The vergence angle v(z) = 2 atan(b / (2 z)) in arc minutes for a distance z (metres) and
// interocular distance b; 0 for z = +inf. z must be > 0 (callers filter invalid depths).
double vergenceArcmin(double metres, double interocularMetres);

// Pooled over any number of image pairs (eyes, screens, frames).
struct StereoError {
    std::uint64_t pixels = 0;         // valid pixels compared
    std::uint64_t invalidPixels = 0;  // left out: an invalid depth in the test or the reference
    double sumArcmin = 0.0;           // of the per-pixel errors
    std::uint64_t beyond = 0;         // pixels whose error is > thresholdArcmin
    double maxArcmin = 0.0;

    double meanArcmin() const { return pixels > 0 ? sumArcmin / static_cast<double>(pixels) : 0.0; }
    double shareBeyond() const { return pixels > 0 ? static_cast<double>(beyond) / static_cast<double>(pixels) : 0.0; }
    StereoError& operator+=(const StereoError& o);
};

// The stereo error of one eye's `test` depth against the `reference` depth of the same eye,
// frame and screen. Throws cavewall::Error naming both images when their sizes differ or are
// empty, when a depth image's size does not match its data, and for options out of range.
StereoError stereoError(const DepthImage& test, const DepthImage& reference, const StereoErrorOptions& options = {});

}  // namespace cavewall::metrics
