#include "metrics/flip.h"

#include "metrics/flip_color.h"
#include "metrics/image_filter.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

namespace cavewall::metrics {

namespace {

constexpr double kPi = std::numbers::pi;

// One Gaussian term a exp(-b f²) of a contrast sensitivity function.
struct CsfTerm {
    double a, b;
};
constexpr CsfTerm kAchromatic{1.0, 0.0047}, kRedGreen{1.0, 0.0053};
constexpr std::array<CsfTerm, 2> kBlueYellow{{{34.1, 0.04}, {13.5, 0.025}}};
constexpr double kWidestB = 0.04;

constexpr double kFeatureWidth = 0.082;  // degrees; the feature exponent qf = 0.5 is a sqrt

// The rows of an image in YyCxCz that the filters of one output row read: a ring of 2R + 1 rows
// per channel, R the largest kernel radius, converted from the image as the output row advances
// (full-size planes cost more in fresh memory than in arithmetic). Channel 0 is Yy, 1 Cx, 2 Cz.
// The relative luminance Y/Yn, the feature pipeline's input, is (Yy + 16) / 116: the feature
// kernels sum to 0, so they see Yy / 116.
class OpponentRows {
public:
    OpponentRows(const scenes::Image& image, const std::array<float, 256>& decode, int radius)
        : _image(image), _decode(decode), _slots(2 * radius + 1), _radius(radius) {
        for (std::vector<float>& c : _channels) c.resize(static_cast<std::size_t>(_slots) * image.width);
    }

    // Makes rows y - R .. y + R (those inside the image) available; y increases call by call.
    void advanceTo(int y) {
        for (; _next <= std::min(y + _radius, _image.height - 1); ++_next) convert(_next);
    }

    // The source rows of the taps of a kernel of `size` taps centred on row y, clamped to the
    // image edge, as filterColumns wants them.
    std::span<const float* const> taps(int channel, int y, std::size_t size) {
        const int r = static_cast<int>(size / 2);
        _taps.resize(size);
        for (std::size_t t = 0; t < size; ++t)
            _taps[t] = row(channel, std::clamp(y + static_cast<int>(t) - r, 0, _image.height - 1));
        return _taps;
    }

    int width() const { return _image.width; }

private:
    const float* row(int channel, int y) const {
        return &_channels[channel][static_cast<std::size_t>(y % _slots) * _image.width];
    }

    void convert(int y) {
        float* yy = &_channels[0][static_cast<std::size_t>(y % _slots) * _image.width];
        float* cx = &_channels[1][static_cast<std::size_t>(y % _slots) * _image.width];
        float* cz = &_channels[2][static_cast<std::size_t>(y % _slots) * _image.width];
        for (int x = 0; x < _image.width; ++x) {
            const std::uint8_t* p = &_image.rgba[(static_cast<std::size_t>(y) * _image.width + x) * 4];
            const glm::dvec3 o = opponentFromLinear({_decode[p[0]], _decode[p[1]], _decode[p[2]]});
            yy[x] = static_cast<float>(o.x);
            cx[x] = static_cast<float>(o.y);
            cz[x] = static_cast<float>(o.z);
        }
    }

    const scenes::Image& _image;
    const std::array<float, 256>& _decode;
    int _slots, _radius, _next = 0;
    std::array<std::vector<float>, 3> _channels;
    std::vector<const float*> _taps;
};

// The sampled CSF kernel of `terms`: one normalised 1-D Gaussian per term and the share of the
// 2-D kernel's sum it carries (the 2-D sum of a product of 1-D samples is their 1-D sum squared).
struct CsfKernel {
    std::vector<std::vector<float>> gaussians;
    std::vector<double> shares;
};

CsfKernel csfKernel(std::span<const CsfTerm> terms, double ppd) {
    const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(kWidestB / (2.0 * kPi * kPi)) * ppd));
    CsfKernel k;
    double total = 0.0;
    for (const CsfTerm& t : terms) {
        // exp(-pi² d² / b) is a Gaussian of sigma = sqrt(b / (2 pi²)) degrees.
        const double sigma = std::sqrt(t.b / (2.0 * kPi * kPi)) * ppd;
        double sum1d = 0.0;
        for (int i = -radius; i <= radius; ++i) sum1d += std::exp(-0.5 * i * i / (sigma * sigma));
        k.gaussians.push_back(gaussianKernel(sigma, radius));
        k.shares.push_back(t.a * std::sqrt(kPi / t.b) * sum1d * sum1d);
        total += k.shares.back();
    }
    for (double& s : k.shares) s /= total;
    return k;
}

// 1-D feature kernels: the Gaussian, its first derivative and its second derivative, the last
// two with positive weights summing to 1 and negative weights to -1.
struct FeatureKernels {
    std::vector<float> gaussian, edge, point;
};

std::vector<float> splitNormalised(const std::vector<double>& w) {
    double positive = 0.0, negative = 0.0;
    for (double v : w) (v > 0 ? positive : negative) += v;
    std::vector<float> k(w.size());
    // Weights below 1e-12 of their half are dropped: as floats they would be denormal (slow).
    for (std::size_t i = 0; i < w.size(); ++i) {
        const double v = w[i] > 0 ? w[i] / positive : w[i] < 0 ? -w[i] / negative : 0.0;
        k[i] = std::abs(v) < 1e-12 ? 0.0f : static_cast<float>(v);
    }
    return k;
}

FeatureKernels featureKernels(double ppd) {
    const double sigma = 0.5 * kFeatureWidth * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> edge, point;
    for (int i = -radius; i <= radius; ++i) {
        const double g = std::exp(-0.5 * i * i / (sigma * sigma));
        edge.push_back(-i * g);
        point.push_back((i * i / (sigma * sigma) - 1.0) * g);
    }
    return {gaussianKernel(sigma, radius), splitNormalised(edge), splitNormalised(point)};
}

// One row of everything FLIP needs from one image: the CSF-filtered opponent channels and the
// edge and point magnitudes. Filled row by row, so that no full-size intermediate is stored.
struct FilteredRow {
    std::vector<float> yy, cx, cz, edges, points;
};

// The scratch rows of one pass and the kernels, sized once.
struct RowFilter {
    CsfKernel achromatic, redGreen, blueYellow;
    FeatureKernels features;
    std::vector<float> column, row, line, columnG, columnD, columnDD;

    RowFilter(double ppd, int width)
        : achromatic(csfKernel({&kAchromatic, 1}, ppd)), redGreen(csfKernel({&kRedGreen, 1}, ppd)),
          blueYellow(csfKernel(kBlueYellow, ppd)), features(featureKernels(ppd)), column(width), row(width),
          columnG(width), columnD(width), columnDD(width) {}

    // The largest radius of all kernels: the rows OpponentRows must hold around the output row.
    int radius() const {
        const std::size_t taps = std::max({achromatic.gaussians[0].size(), redGreen.gaussians[0].size(),
                                           blueYellow.gaussians[0].size(), features.gaussian.size()});
        return static_cast<int>(taps / 2);
    }

    // Row y of opponent channel `c` filtered by the CSF kernel `k` into `out`.
    void csf(OpponentRows& rows, int c, int y, const CsfKernel& k, std::vector<float>& out) {
        std::fill(out.begin(), out.end(), 0.0f);
        for (std::size_t t = 0; t < k.gaussians.size(); ++t) {
            filterColumns<float>(rows.taps(c, y, k.gaussians[t].size()), k.gaussians[t], rows.width(), column.data());
            filterRow(column.data(), rows.width(), k.gaussians[t], line, row.data());
            const auto share = static_cast<float>(k.shares[t]);
            for (std::size_t x = 0; x < out.size(); ++x) out[x] += share * row[x];
        }
    }

    // Row y of the edge and point magnitudes of the luminance Y/Yn = (Yy + 16) / 116.
    void featureRow(OpponentRows& rows, int y, FilteredRow& out) {
        const FeatureKernels& k = features;
        const int w = rows.width();
        filterColumns<float>(rows.taps(0, y, k.gaussian.size()), k.gaussian, w, columnG.data());
        filterColumns<float>(rows.taps(0, y, k.edge.size()), k.edge, w, columnD.data());
        filterColumns<float>(rows.taps(0, y, k.point.size()), k.point, w, columnDD.data());
        filterRow(columnG.data(), w, k.edge, line, out.edges.data());  // d/dx
        filterRow(columnD.data(), w, k.gaussian, line, row.data());    // d/dy
        for (int x = 0; x < w; ++x) out.edges[x] = std::sqrt(out.edges[x] * out.edges[x] + row[x] * row[x]) / 116.0f;
        filterRow(columnG.data(), w, k.point, line, out.points.data());  // d²/dx²
        filterRow(columnDD.data(), w, k.gaussian, line, row.data());     // d²/dy²
        for (int x = 0; x < w; ++x) out.points[x] = std::sqrt(out.points[x] * out.points[x] + row[x] * row[x]) / 116.0f;
    }

    void filter(OpponentRows& rows, int y, FilteredRow& out) {
        rows.advanceTo(y);
        csf(rows, 0, y, achromatic, out.yy);
        csf(rows, 1, y, redGreen, out.cx);
        csf(rows, 2, y, blueYellow, out.cz);
        featureRow(rows, y, out);
    }
};

FilteredRow filteredRow(int width) {
    const std::vector<float> row(static_cast<std::size_t>(width));
    return {row, row, row, row, row};
}

// FLIP of pixel x of two filtered rows: the colour error raised to 1 - feature error.
double pixelError(const FilteredRow& t, const FilteredRow& r, int x) {
    const double colour = flipColorError(
        hyab(huntLabFromOpponent({t.yy[x], t.cx[x], t.cz[x]}), huntLabFromOpponent({r.yy[x], r.cx[x], r.cz[x]})));
    const double edge = std::abs(t.edges[x] - r.edges[x]), point = std::abs(t.points[x] - r.points[x]);
    const double feature = std::min(1.0, std::sqrt(std::max(edge, point) / std::numbers::sqrt2));  // qf = 0.5
    return feature > 0.0 ? std::pow(static_cast<float>(colour), static_cast<float>(1.0 - feature)) : colour;
}

void summarise(FlipResult& result) {
    double sum = 0.0;
    for (float e : result.errors) sum += e;
    result.mean = sum / static_cast<double>(result.errors.size());
    constexpr std::array<double, 3> kQs{0.5, 0.95, 1.0};
    const std::vector<double> p = percentiles(result.errors, kQs);
    result.p50 = p[0];
    result.p95 = p[1];
    result.max = p[2];
}

}  // namespace

FlipResult flip(const scenes::Image& test, const scenes::Image& reference, const FlipOptions& options) {
    expectComparableImages("flip", test, reference);
    const double ppd = options.pixelsPerDegree;
    assert(ppd >= 1.0 && ppd <= 1000.0);
    const std::array<float, 256> decode = decodeTable(options.encoding);
    const int w = test.width;
    RowFilter filter(ppd, w);
    OpponentRows t(test, decode, filter.radius()), r(reference, decode, filter.radius());
    FilteredRow rowT = filteredRow(w), rowR = filteredRow(w);
    FlipResult result{w, test.height, std::vector<float>(static_cast<std::size_t>(w) * test.height)};
    for (int y = 0; y < test.height; ++y) {
        filter.filter(t, y, rowT);
        filter.filter(r, y, rowR);
        float* out = &result.errors[static_cast<std::size_t>(y) * w];
        for (int x = 0; x < w; ++x) out[x] = static_cast<float>(pixelError(rowT, rowR, x));
    }
    summarise(result);
    return result;
}

scenes::Image flipErrorImage(const FlipResult& result) {
    assert(result.errors.size() == static_cast<std::size_t>(result.width) * result.height);
    // Stops at 0, 0.25, 0.5, 0.75 and 1 (see the header).
    static constexpr std::array<std::array<double, 3>, 5> kStops{
        {{0, 0, 0}, {72, 16, 120}, {184, 50, 110}, {250, 140, 80}, {255, 250, 190}}};
    scenes::Image image{"flip", result.width, result.height, std::vector<std::uint8_t>(result.errors.size() * 4, 255)};
    for (std::size_t i = 0; i < result.errors.size(); ++i) {
        const double s = std::clamp(static_cast<double>(result.errors[i]), 0.0, 1.0) * 4.0;
        const int lo = std::min(static_cast<int>(s), 3);
        const double f = s - lo;
        for (int c = 0; c < 3; ++c)
            image.rgba[i * 4 + c] =
                static_cast<std::uint8_t>(std::lround(kStops[lo][c] + f * (kStops[lo + 1][c] - kStops[lo][c])));
    }
    return image;
}

}  // namespace cavewall::metrics
