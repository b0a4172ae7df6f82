#pragma once
// Numerical stability of the projection on stiff and extreme cases (the display part of
// `cavewall bench --stability`). Each row runs one case in float (what a naive float
// implementation gets, for contrast) and in cavewall's own path (double on the CPU, eye-relative
// float on the GPU), measures the worst error against a long-double reference, and passes when
// cavewall's error is within the stated tolerance.

#include <string>
#include <vector>

namespace cavewall::display {

struct StabilityRow {
    std::string name;            // the case, e.g. "eye distance 1e-09 m"
    std::string unit;            // unit of the errors, e.g. "px @1024"
    double floatError = 0.0;     // naive float implementation (reported, not judged)
    double cavewallError = 0.0;  // cavewall's path
    double tolerance = 0.0;      // pass when cavewallError <= tolerance
    double condition = 0.0;      // warp cases: the warp's condition number (else 0)
    bool pass() const { return cavewallError <= tolerance; }
};

// Eye distances 1e-9 ... 1e6 m from a 3 m screen: worst NDC error of screen points and of
// points behind them, in pixels of a 1024-pixel screen. Tolerance 1e-6 px.
std::vector<StabilityRow> eyeDistanceCases();

// The same scene offset by 1e3 ... 1e7 m: float world-space maths vs cavewall's eye-relative
// float matrices. Tolerance 1e-3 px.
std::vector<StabilityRow> worldOffsetCases();

// Near/far ratios 1e3 ... 1e9 and an infinite far plane: depth-order inversions among distances
// 0.1 % apart over the whole range, in a 32-bit float depth buffer. "float" is the conventional
// OpenGL [-1, 1] depth mapping, cavewall's is reversed-Z [0, 1]. Tolerance 0 inversions.
std::vector<StabilityRow> depthOrderCases();

// Screens of 1 mm and 1 km with the eye at a proportionate distance. Tolerance 1e-6 px.
std::vector<StabilityRow> screenSizeCases();

// The geometry warp (display/warp.h) as the eye approaches a wall plane (1 m ... 1e-6 m): worst
// pixel error of the warped image of points behind the wall when the warp runs in float on the
// GPU, against double. "float" is the unguarded warp; cavewall's column is what it draws: the
// warp while its condition number is below kMaxWarpCondition, else plain geometry (error 0,
// counted as a fallback). The row's `condition` is the warp's condition number. Tolerance 0.5 px.
std::vector<StabilityRow> warpConditionCases();

// All of the above.
std::vector<StabilityRow> projectionStability();

}  // namespace cavewall::display
