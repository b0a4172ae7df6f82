#include "app/bench/metrics.h"

#include "config/error.h"
#include "display/timing.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cavewall::bench {

namespace {

// Wraps the pixels without copying; OIIO only reads them.
OIIO::ImageBuf wrap(const scenes::Image& image) {
    const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    return OIIO::ImageBuf(spec, const_cast<std::uint8_t*>(image.rgba.data()));
}

std::vector<double> luminance(const scenes::Image& image) {
    std::vector<double> y(static_cast<std::size_t>(image.width) * image.height);
    for (std::size_t i = 0; i < y.size(); ++i) {
        const std::uint8_t* p = &image.rgba[i * 4];
        y[i] = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    }
    return y;
}

// SSIM of one window [x0, x0 + w) x [y0, y0 + h).
double windowSsim(const std::vector<double>& a, const std::vector<double>& b, int width, int x0, int y0, int w,
                  int h) {
    constexpr double kC1 = (0.01 * 255) * (0.01 * 255), kC2 = (0.03 * 255) * (0.03 * 255);
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) {
            const double va = a[static_cast<std::size_t>(y) * width + x], vb = b[static_cast<std::size_t>(y) * width + x];
            sa += va, sb += vb, saa += va * va, sbb += vb * vb, sab += va * vb;
        }
    const double n = static_cast<double>(w) * h;
    const double ma = sa / n, mb = sb / n;
    // Sample (co)variances, as in the reference implementation; clamped against rounding.
    const double denom = n > 1 ? n - 1 : 1;
    const double va = std::max(0.0, (saa - n * ma * ma) / denom), vb = std::max(0.0, (sbb - n * mb * mb) / denom);
    const double cov = (sab - n * ma * mb) / denom;
    return ((2 * ma * mb + kC1) * (2 * cov + kC2)) / ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
}

void expectSameSize(const scenes::Image& a, const scenes::Image& b) {
    if (a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size() &&
        a.rgba.size() == static_cast<std::size_t>(a.width) * a.height * 4 && a.width > 0 && a.height > 0)
        return;
    throw Error("bench: comparing '" + a.name + "' with '" + b.name + "': expected two RGBA images of the same size, got " +
                std::to_string(a.width) + "x" + std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                std::to_string(b.height));
}

}  // namespace

double psnrFromMse(double mse) {
    return mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity();
}

double ssimLuminance(const scenes::Image& a, const scenes::Image& b) {
    expectSameSize(a, b);
    const std::vector<double> la = luminance(a), lb = luminance(b);
    constexpr int kWindow = 8, kStride = 4;
    const int w = std::min(kWindow, a.width), h = std::min(kWindow, a.height);
    double sum = 0.0;
    long count = 0;
    for (int y = 0; y + h <= a.height; y += kStride)
        for (int x = 0; x + w <= a.width; x += kStride) {
            sum += windowSsim(la, lb, a.width, x, y, w, h);
            ++count;
        }
    return sum / static_cast<double>(count);
}

ImageError compareForBench(const scenes::Image& actual, const scenes::Image& reference) {
    expectSameSize(actual, reference);
    const OIIO::ImageBuf a = wrap(actual), b = wrap(reference);
    OIIO::ROI rgb = a.roi();
    rgb.chbegin = 0, rgb.chend = 3;
    const OIIO::ImageBufAlgo::CompareResults c = OIIO::ImageBufAlgo::compare(a, b, 1.0f, 1.0f, rgb);
    if (c.error) throw Error("bench: OpenImageIO could not compare '" + actual.name + "' with '" + reference.name + "'");
    ImageError e;
    e.rmse = c.rms_error;
    e.mse = e.rmse * e.rmse;
    e.psnrDb = psnrFromMse(e.mse);
    e.meanPsnrDb = std::min(e.psnrDb, kQuantisationPsnrDb);
    e.ssim = ssimLuminance(actual, reference);
    return e;
}

void ErrorPool::add(const ImageError& e) {
    _mse += e.mse;
    _ssim += e.ssim;
    _psnr += std::min(e.psnrDb, kQuantisationPsnrDb);
    ++_count;
}

ImageError ErrorPool::result() const {
    ImageError e;
    if (_count == 0) {
        e.psnrDb = psnrFromMse(0.0);
        e.meanPsnrDb = kQuantisationPsnrDb;
        return e;
    }
    e.mse = _mse / static_cast<double>(_count);
    e.rmse = std::sqrt(e.mse);
    e.psnrDb = psnrFromMse(e.mse);
    e.ssim = _ssim / static_cast<double>(_count);
    e.meanPsnrDb = _psnr / static_cast<double>(_count);
    return e;
}

TimeStats timeStats(const std::vector<double>& samples) {
    TimeStats s;
    if (samples.empty()) return s;
    s.p50 = display::percentile(samples, 0.50);
    s.p95 = display::percentile(samples, 0.95);
    s.p99 = display::percentile(samples, 0.99);
    for (double v : samples) s.mean += v;
    s.mean /= static_cast<double>(samples.size());
    return s;
}

std::vector<std::size_t> paretoFront(const std::vector<TradeOff>& points) {
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < points.size(); ++i) {
        bool dominated = false;
        for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
            const TradeOff &p = points[i], &q = points[j];
            dominated = q.time <= p.time && q.error <= p.error && (q.time < p.time || q.error < p.error);
        }
        if (!dominated) front.push_back(i);
    }
    std::stable_sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return points[a].time < points[b].time; });
    return front;
}

}  // namespace cavewall::bench
