#include "metrics/ssim.h"

#include "metrics/image_filter.h"

#include <algorithm>
#include <span>
#include <vector>

namespace cavewall::metrics {

namespace {

constexpr double kSigma = 1.5;
constexpr int kRadius = 5;  // 11 taps
constexpr double kC1 = (0.01 * 255) * (0.01 * 255), kC2 = (0.03 * 255) * (0.03 * 255);
// Second moments are taken about mid-grey, not 0, so that sums of squares lose less to
// cancellation when the means are subtracted.
constexpr double kCentre = 128.0;

PlaneDouble centredLuma(const scenes::Image& image) {
    PlaneDouble y(image.width, image.height);
    for (std::size_t i = 0; i < y.values.size(); ++i) {
        const std::uint8_t* p = &image.rgba[i * 4];
        y.values[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2] - kCentre;
    }
    return y;
}

// The window's five moments of one output row: the vertical half of the Gaussian (products
// formed on the fly, so no full-size product planes), then the horizontal half.
struct Moments {
    std::vector<double> x, y, xx, yy, xy;
};

void verticalMoments(const PlaneDouble& a, const PlaneDouble& b, int row, std::span<const double> k, Moments& m) {
    for (std::vector<double>* v : {&m.x, &m.y, &m.xx, &m.yy, &m.xy}) std::fill(v->begin(), v->end(), 0.0);
    const int r = static_cast<int>(k.size() / 2);
    for (std::size_t t = 0; t < k.size(); ++t) {
        const std::size_t offset = static_cast<std::size_t>(row + static_cast<int>(t) - r) * a.width;
        const double* pa = &a.values[offset];
        const double* pb = &b.values[offset];
        const double w = k[t];
        for (int i = 0; i < a.width; ++i) {
            m.x[i] += w * pa[i];
            m.y[i] += w * pb[i];
            // w * (a b), not (w a) b: the product is the same whichever image is a (symmetry).
            m.xx[i] += w * (pa[i] * pa[i]);
            m.yy[i] += w * (pb[i] * pb[i]);
            m.xy[i] += w * (pa[i] * pb[i]);
        }
    }
}

void horizontalMoments(const Moments& in, std::span<const double> k, std::vector<double>& line, Moments& out) {
    const int w = static_cast<int>(in.x.size());
    filterRow(in.x.data(), w, k, line, out.x.data());
    filterRow(in.y.data(), w, k, line, out.y.data());
    filterRow(in.xx.data(), w, k, line, out.xx.data());
    filterRow(in.yy.data(), w, k, line, out.yy.data());
    filterRow(in.xy.data(), w, k, line, out.xy.data());
}

double ssimAt(const Moments& m, int i) {
    const double cx = m.x[i], cy = m.y[i];
    const double ux = cx + kCentre, uy = cy + kCentre;
    const double vx = m.xx[i] - cx * cx, vy = m.yy[i] - cy * cy, cov = m.xy[i] - cx * cy;
    return ((2 * ux * uy + kC1) * (2 * cov + kC2)) / ((ux * ux + uy * uy + kC1) * (vx + vy + kC2));
}

}  // namespace

double ssim(const scenes::Image& a, const scenes::Image& b) {
    expectComparableImages("ssim", a, b);
    const int rx = std::min(kRadius, (a.width - 1) / 2), ry = std::min(kRadius, (a.height - 1) / 2);
    const std::vector<double> kx = gaussianKernel<double>(kSigma, rx), ky = gaussianKernel<double>(kSigma, ry);
    const PlaneDouble x = centredLuma(a), y = centredLuma(b);
    const auto row = std::vector<double>(static_cast<std::size_t>(a.width));
    Moments vertical{row, row, row, row, row}, window = vertical;
    std::vector<double> line;
    double sum = 0.0;
    // Only rows and columns where the whole window fits: no boundary rule is needed.
    for (int r = ry; r < a.height - ry; ++r) {
        verticalMoments(x, y, r, ky, vertical);
        horizontalMoments(vertical, kx, line, window);
        for (int c = rx; c < a.width - rx; ++c) sum += ssimAt(window, c);
    }
    return sum / (static_cast<double>(a.width - 2 * rx) * (a.height - 2 * ry));
}

}  // namespace cavewall::metrics
