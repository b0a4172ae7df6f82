#pragma once
// Image planes and separable convolution: the filtering under the image metrics
// (metrics/flip.h, metrics/ssim.h), plus their percentiles and size check.
//
// A plane is one channel of float (Plane) or double (PlaneDouble) values, rows top to bottom, in
// whatever unit its producer states.
// Kernels are odd-length, centred, applied as correlation (kernel[k] weighs the sample at offset
// k - radius); the metrics use symmetric or antisymmetric kernels, for which the sign convention
// only flips the sign of an antisymmetric response. Outside the plane, the nearest edge sample is
// repeated (clamp to edge).

#include "scenes/scene.h"

#include <cstddef>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

namespace cavewall::metrics {

template <typename T>
struct BasicPlane {
    int width = 0, height = 0;
    std::vector<T> values;  // width * height, row-major

    BasicPlane() = default;
    BasicPlane(int w, int h, T fill = T(0)) : width(w), height(h), values(static_cast<std::size_t>(w) * h, fill) {}
    T& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }
    T at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
};
using Plane = BasicPlane<float>;         // FLIP: speed
using PlaneDouble = BasicPlane<double>;  // SSIM: second moments without cancellation

// `in` filtered along rows by `horizontal` and along columns by `vertical` (both odd-length;
// an empty span means "leave that direction alone"). Clamp-to-edge boundaries; same size as `in`.
// Cost: width * height * (|horizontal| + |vertical|) multiply-adds (zero taps skipped), one
// output plane and no full-size intermediate. T is float or double (the kernels' type follows
// the plane's).
template <typename T>
BasicPlane<T> convolveSeparable(const BasicPlane<T>& in, std::type_identity_t<std::span<const T>> horizontal,
                                std::type_identity_t<std::span<const T>> vertical);

// The two halves of convolveSeparable for one output row, for callers that fuse several filters
// of a plane row by row. filterColumns: out[x] = sum_t k[t] rows[t][x] for x < width, rows[t]
// the source row of tap t (already clamped by the caller). filterColumnsAtRow: the same with
// the rows taken from `in` around row y, clamped to the edge; `out` holds in.width values.
// filterRow: out[x] = sum_t k[t] row[clamp(x + t - r)] for x < width; `line` is scratch
// (resized as needed); `out` must not alias `row`.
template <typename T>
void filterColumns(std::span<const T* const> rows, std::type_identity_t<std::span<const T>> k, int width, T* out);
template <typename T>
void filterColumnsAtRow(const BasicPlane<T>& in, int y, std::type_identity_t<std::span<const T>> k, T* out);
template <typename T>
void filterRow(const T* row, int width, std::type_identity_t<std::span<const T>> k, std::vector<T>& line, T* out);

// Samples exp(-x² / (2 sigma²)) at the integers -radius..radius, scaled to sum to 1; weights
// below 1e-12 of the sum are set to 0 (they would be denormal floats, slow and meaningless).
// sigma > 0 and radius >= 0 (pixels). T is float or double.
template <typename T = float>
std::vector<T> gaussianKernel(double sigma, int radius);

// Nearest-rank percentile of `values`, q in [0, 1]: the smallest value v such that at least a
// share q of the values are <= v (q = 0 gives the minimum, q = 1 the maximum). 0 for no values.
// Takes a copy because it reorders.
double percentile(std::vector<float> values, double q);
double percentile(std::vector<double> values, double q);

// Several nearest-rank percentiles of one copy of `values`, `qs` in increasing order; each
// later one only partitions what lies above the previous (cheaper than separate calls).
std::vector<double> percentiles(std::vector<float> values, std::span<const double> qs);

// Throws cavewall::Error "<what>: comparing 'a' with 'b': expected two non-empty RGBA images of
// the same size, got WxH and WxH" unless both are non-empty, hold width * height * 4 bytes and
// have the same size.
void expectComparableImages(std::string_view what, const scenes::Image& a, const scenes::Image& b);

}  // namespace cavewall::metrics
