#pragma once
// LDR-FLIP: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild, "FLIP: A Difference
// Evaluator for Alternating Images", HPG 2020 (Proc. ACM Comput. Graph. Interact. Tech. 3(2)).
// Written from the paper's description.
//
// FLIP estimates, per pixel, how different two images look to a viewer who flips between them,
// at a given angular resolution: pixels per degree of visual angle (ppd). 0 = no visible
// difference, 1 = the largest. The paper's default, 67 ppd, is a 0.7 m wide 3840-pixel monitor
// seen from 0.7 m; a CAVE wall seen from 1.5 m is about 9 ppd at 1024 pixels and 17 at 1920
// (display/pixel_scale.h, minPixelsPerDegree). Fewer pixels per degree make each pixel larger to
// the eye, so the same pixel pattern is at a lower spatial frequency, passes the contrast
// sensitivity filters and counts more.
//
// Colour pipeline, per image:
//  1. R, G, B decoded to linear (sRGB primaries, D65 white), to CIE XYZ, then to the linear
//     opponent space YyCxCz: Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn),
//     white (Xn, Yn, Zn) = XYZ of linear RGB (1, 1, 1).
//  2. Each channel filtered by the spatial kernel of its contrast sensitivity function. The CSFs
//     are Gaussians in spatial frequency f (cycles per degree): achromatic exp(-0.0047 f²),
//     red-green exp(-0.0053 f²), blue-yellow 34.1 exp(-0.04 f²) + 13.5 exp(-0.025 f²). A term
//     a exp(-b f²) becomes the kernel a sqrt(pi / b) exp(-pi² d² / b), d the distance from the
//     kernel's centre in degrees (pixels / ppd); each channel's kernel is normalised to sum 1.
//  3. Back to linear RGB, clamped to [0, 1] (filtering can leave the gamut), then to CIELAB
//     (same white) with the Hunt adjustment: a* and b* scaled by 0.01 L* (colour fades in the dark).
//  The colour error is HyAB, |dL*| + sqrt(da*² + db*²), raised to qc = 0.7 and mapped onto [0, 1]
//  against cmax = HyAB(Hunt green, Hunt blue)^qc, the largest difference within the gamut: from 0
//  to pt = 0.95 linearly over [0, pc cmax), pc = 0.4, then from pt to 1 over [pc cmax, cmax]
//  (clamped to 1 beyond), so small and medium differences use most of the scale.
//
// Feature pipeline, on the achromatic channel of the unfiltered images (Y/Yn, linear luminance):
//  edges are the gradient magnitude from first derivatives of a Gaussian, points the magnitude of
//  the pair of second derivatives along x and y; Gaussian sigma = 0.5 w ppd pixels with
//  w = 0.082 degrees. Each kernel's positive weights sum to 1 and its negative weights to -1, so
//  a flat area gives 0 and a unit step an edge magnitude of 1 beside it. The feature error is
//  (max(| |edge_ref| - |edge_test| |, | |point_ref| - |point_test| |) / sqrt 2)^qf, qf = 0.5.
//
// FLIP = colourError^(1 - featureError): a feature difference pulls the colour error towards 1.
//
// Checked against the paper (its text as summarised in public notes on it, and the constants of
// NVIDIA's published reference header, read for the numbers only): the CSF terms (a, b) =
// (1, 0.0047), (1, 0.0053), (34.1, 0.04) + (13.5, 0.025) (the reference lists the single-term
// channels with a second term of weight 0), the CSF kernel radius ceil(3 sigma_max ppd) with
// sigma_max from b = 0.04, qc = 0.7, pc = 0.4, pt = 0.95, w = 0.082 degrees, qf = 0.5, the
// feature sigma 0.5 w ppd and radius ceil(3 sigma), the Hunt factor 0.01 L*, HyAB, FLIP =
// colour^(1 - feature), and the default 67 ppd (0.7 m, 3840 px, 0.7 m wide) all agree with what
// is written above; the paper's cmax, HyAB(Hunt green, Hunt blue) = 203 raised to 0.7 = 41.3,
// is what flipColorError computes (tests/metrics/flip_test.cpp). Nothing needed fixing.
//
// Choices where the paper leaves room (this code may differ from NVIDIA's reference code here):
//  - Linear RGB to XYZ: the sRGB (IEC 61966-2-1) matrix to 7 digits; the reference derives
//    its matrix from exact fractions, which differ from these in the 4th significant digit.
//  - Boundaries: clamp to edge (the nearest edge pixel repeated) for every filter.
//  - Truncation: square kernels. CSF kernels of all three channels share the radius
//    ceil(3 sigma_max ppd), sigma_max = sqrt(0.04 / (2 pi²)) degrees, the widest Gaussian (3 sigma
//    of the narrower ones is far inside it); feature kernels have radius ceil(3 sigma).
//  - Evaluation: separably (every kernel is a product of 1-D kernels, blue-yellow the sum of two
//    such products, weighted by their sampled 2-D sums) in 32-bit floats; equal to the 2-D
//    convolution up to rounding.
//  - Input: 8-bit bytes only; sRGB decoding by the exact IEC 61966-2-1 piecewise curve.
//  - Summary: the mean is the paper's single pooled value; p50, p95 and max are nearest-rank
//    percentiles (metrics/image_filter.h).
//  - Error-map colours: the paper shows its maps with the "magma" colour map; flipErrorImage uses
//    a similar black-purple-orange-yellow ramp of its own (see there), not magma's table.

#include "scenes/scene.h"

#include <cstdint>
#include <vector>

namespace cavewall::metrics {

enum class ColorEncoding : std::uint8_t {
    Srgb,    // bytes are sRGB-encoded (what the renderer stores, display/gl/render_targets.h)
    Linear,  // bytes are linear light, value / 255
};

// A 0.7 m wide 3840-pixel monitor seen from 0.7 m: 3840 px over 1 radian = 67.02 per degree.
constexpr double kFlipDefaultPixelsPerDegree = 67.0206;

struct FlipOptions {
    double pixelsPerDegree = kFlipDefaultPixelsPerDegree;  // in [1, 1000]
    ColorEncoding encoding = ColorEncoding::Srgb;          // of both images' R, G and B bytes
};

struct FlipResult {
    int width = 0, height = 0;
    std::vector<float> errors;               // width * height, rows top to bottom, each in [0, 1]
    double mean = 0.0;                       // mean of `errors`: FLIP's single-number summary
    double p50 = 0.0, p95 = 0.0, max = 0.0;  // nearest-rank percentiles of `errors`
};

// The FLIP error map of `test` against `reference` (8-bit RGBA, rows top to bottom; alpha is
// ignored). Symmetric in its two images. Throws cavewall::Error naming both images when their
// sizes differ or either is empty. pixelsPerDegree outside [1, 1000] is a programmer error
// (assert). Cost per pixel: the filters take about 600 multiply-adds at 67 ppd and 210 at 17 ppd
// (kernel widths grow with ppd), plus two colour conversions to CIELAB; one 1024 x 1024 pair
// took 0.2-0.35 s of CPU on the project's shared 2-core machine (bench/image_metrics_bench.cpp).
// Memory: the result, plus rows of the images as wide as the kernels are tall.
FlipResult flip(const scenes::Image& test, const scenes::Image& reference, const FlipOptions& options = {});

// The error map as an opaque 8-bit image for PNG output (name "flip"): each pixel's error mapped
// through a ramp black (0) - purple (0.25) - red (0.5) - orange (0.75) - pale yellow (1),
// interpolated linearly between those stops in sRGB bytes.
scenes::Image flipErrorImage(const FlipResult& result);

}  // namespace cavewall::metrics
