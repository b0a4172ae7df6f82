#include "metrics/image_filter.h"

#include "config/error.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace cavewall::metrics {

namespace {

// Nearest rank: the ceil(q n)-th smallest (1-based), at least the first, as a 0-based index;
// 1e-9 so that 0.95 * 20, which rounds above 19, is still rank 19.
std::ptrdiff_t rankIndex(std::size_t n, double q) {
    assert(q >= 0.0 && q <= 1.0 && n > 0);
    return static_cast<std::ptrdiff_t>(std::max(1.0, std::ceil(q * static_cast<double>(n) - 1e-9))) - 1;
}

template <typename T>
double nearestRank(std::vector<T> values, double q) {
    if (values.empty()) return 0.0;
    const auto nth = values.begin() + rankIndex(values.size(), q);
    std::nth_element(values.begin(), nth, values.end());
    return *nth;
}

}  // namespace

// Both halves loop taps outside and pixels inside, so the inner loop is a plain multiply-add
// over contiguous memory that the compiler vectorises.
template <typename T>
void filterColumns(std::span<const T* const> rows, std::type_identity_t<std::span<const T>> k, int width, T* out) {
    assert(rows.size() == k.size());
    std::fill(out, out + width, T(0));
    for (std::size_t t = 0; t < k.size(); ++t) {
        if (k[t] == T(0)) continue;
        const T kt = k[t];
        const T* s = rows[t];
        for (int x = 0; x < width; ++x) out[x] += kt * s[x];
    }
}

template <typename T>
void filterColumnsAtRow(const BasicPlane<T>& in, int y, std::type_identity_t<std::span<const T>> k, T* out) {
    const int r = static_cast<int>(k.size() / 2);
    std::vector<const T*> rows(k.size());
    for (std::size_t t = 0; t < k.size(); ++t) {
        const int source = std::clamp(y + static_cast<int>(t) - r, 0, in.height - 1);
        rows[t] = &in.values[static_cast<std::size_t>(source) * in.width];
    }
    filterColumns<T>(rows, k, in.width, out);
}

template <typename T>
void filterRow(const T* row, int width, std::type_identity_t<std::span<const T>> k, std::vector<T>& line, T* out) {
    const int r = static_cast<int>(k.size() / 2);
    // A clamped, padded copy of the row, so that the inner loop has no branches.
    line.resize(static_cast<std::size_t>(width + 2 * r));
    for (int i = 0; i < width + 2 * r; ++i) line[i] = row[std::clamp(i - r, 0, width - 1)];
    std::fill(out, out + width, T(0));
    for (std::size_t t = 0; t < k.size(); ++t) {
        if (k[t] == T(0)) continue;
        const T kt = k[t];
        const T* s = line.data() + t;
        for (int x = 0; x < width; ++x) out[x] += kt * s[x];
    }
}

template <typename T>
BasicPlane<T> convolveSeparable(const BasicPlane<T>& in, std::type_identity_t<std::span<const T>> horizontal,
                                std::type_identity_t<std::span<const T>> vertical) {
    assert(horizontal.size() % 2 == 1 || horizontal.empty());
    assert(vertical.size() % 2 == 1 || vertical.empty());
    if (horizontal.empty() && vertical.empty()) return in;
    BasicPlane<T> out(in.width, in.height);
    std::vector<T> column(static_cast<std::size_t>(in.width)), line;
    for (int y = 0; y < in.height; ++y) {
        T* dst = &out.values[static_cast<std::size_t>(y) * in.width];
        const T* row = &in.values[static_cast<std::size_t>(y) * in.width];
        if (!vertical.empty()) {
            filterColumnsAtRow(in, y, vertical, horizontal.empty() ? dst : column.data());
            row = column.data();
        }
        if (!horizontal.empty()) filterRow(row, in.width, horizontal, line, dst);
    }
    return out;
}

template void filterColumns(std::span<const float* const>, std::span<const float>, int, float*);
template void filterColumns(std::span<const double* const>, std::span<const double>, int, double*);
template void filterColumnsAtRow(const Plane&, int, std::span<const float>, float*);
template void filterColumnsAtRow(const PlaneDouble&, int, std::span<const double>, double*);
template void filterRow(const float*, int, std::span<const float>, std::vector<float>&, float*);
template void filterRow(const double*, int, std::span<const double>, std::vector<double>&, double*);
template Plane convolveSeparable(const Plane&, std::span<const float>, std::span<const float>);
template PlaneDouble convolveSeparable(const PlaneDouble&, std::span<const double>, std::span<const double>);

template <typename T>
std::vector<T> gaussianKernel(double sigma, int radius) {
    assert(sigma > 0.0 && radius >= 0);
    std::vector<double> w(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) sum += w[i + radius] = std::exp(-0.5 * i * i / (sigma * sigma));
    std::vector<T> k(w.size());
    for (std::size_t i = 0; i < w.size(); ++i) k[i] = w[i] < 1e-12 * sum ? T(0) : static_cast<T>(w[i] / sum);
    return k;
}

template std::vector<float> gaussianKernel(double, int);
template std::vector<double> gaussianKernel(double, int);

double percentile(std::vector<float> values, double q) { return nearestRank(std::move(values), q); }

double percentile(std::vector<double> values, double q) { return nearestRank(std::move(values), q); }

std::vector<double> percentiles(std::vector<float> values, std::span<const double> qs) {
    std::vector<double> out(qs.size(), 0.0);
    auto from = values.begin();
    for (std::size_t i = 0; i < qs.size() && !values.empty(); ++i) {
        assert(i == 0 || qs[i] >= qs[i - 1]);
        const auto nth = values.begin() + rankIndex(values.size(), qs[i]);
        std::nth_element(from, nth, values.end());
        out[i] = *nth;
        from = nth;
    }
    return out;
}

void expectComparableImages(std::string_view what, const scenes::Image& a, const scenes::Image& b) {
    const auto valid = [](const scenes::Image& i) {
        return i.width > 0 && i.height > 0 && i.rgba.size() == static_cast<std::size_t>(i.width) * i.height * 4;
    };
    if (valid(a) && valid(b) && a.width == b.width && a.height == b.height) return;
    throw Error(std::string(what) + ": comparing '" + a.name + "' with '" + b.name +
                "': expected two non-empty RGBA images of the same size, got " + std::to_string(a.width) + "x" +
                std::to_string(a.height) + " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
}

}  // namespace cavewall::metrics
