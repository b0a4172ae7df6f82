#include "metrics/image_compare.h"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <sstream>

namespace cavewall::metrics {

namespace {

int pixelDelta(const scenes::Image& a, const scenes::Image& b, std::size_t pixel) {
    int d = 0;
    for (std::size_t c = 0; c < 4; ++c)
        d = std::max(d, std::abs(int(a.rgba[pixel * 4 + c]) - int(b.rgba[pixel * 4 + c])));
    return d;
}

bool sameSize(const scenes::Image& a, const scenes::Image& b) {
    return a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size() &&
           a.rgba.size() == static_cast<std::size_t>(a.width) * a.height * 4;
}

}  // namespace

bool ImageComparison::passes() const {
    return sameSize && badFraction <= tolerance.maxBadFraction && meanDelta <= tolerance.maxMeanDelta;
}

std::string ImageComparison::describe() const {
    std::ostringstream s;
    if (!sameSize) return "images differ in size";
    s << "max Δ " << maxDelta << ", mean Δ " << meanDelta << " (allowed " << tolerance.maxMeanDelta
      << "), share of pixels with Δ > " << tolerance.badDelta << ": " << 100.0 * badFraction << " % (allowed "
      << 100.0 * tolerance.maxBadFraction << " %)";
    if (!worst.empty()) s << "; worst pixels (x, y: Δ):";
    for (const PixelDelta& p : worst) s << " (" << p.x << ", " << p.y << ": " << p.delta << ")";
    return s.str();
}

ImageComparison compareImages(const scenes::Image& actual, const scenes::Image& expected, ImageTolerance tolerance,
                              int worstCount) {
    ImageComparison r;
    r.tolerance = tolerance;
    r.sameSize = sameSize(actual, expected);
    if (!r.sameSize || actual.rgba.empty()) return r;
    const std::size_t pixels = actual.rgba.size() / 4;
    std::vector<PixelDelta> all;
    std::size_t bad = 0;
    double sum = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const int d = pixelDelta(actual, expected, i);
        sum += d;
        r.maxDelta = std::max(r.maxDelta, d);
        if (d > tolerance.badDelta) ++bad;
        if (d > 0) all.push_back({static_cast<int>(i % actual.width), static_cast<int>(i / actual.width), d});
    }
    r.meanDelta = sum / static_cast<double>(pixels);
    r.badFraction = static_cast<double>(bad) / static_cast<double>(pixels);
    // Stable: equal Δ keep row-major order, so the report is deterministic.
    std::stable_sort(all.begin(), all.end(),
                     [](const PixelDelta& a, const PixelDelta& b) { return a.delta > b.delta; });
    all.resize(std::min(all.size(), static_cast<std::size_t>(std::max(worstCount, 0))));
    r.worst = std::move(all);
    return r;
}

scenes::Image differenceImage(const scenes::Image& actual, const scenes::Image& expected, ImageTolerance tolerance) {
    assert(sameSize(actual, expected));
    scenes::Image out{"diff", actual.width, actual.height, std::vector<std::uint8_t>(actual.rgba.size(), 255)};
    for (std::size_t i = 0; i < actual.rgba.size() / 4; ++i) {
        std::uint8_t* q = &out.rgba[i * 4];
        const int d = pixelDelta(actual, expected, i);
        if (d > tolerance.badDelta) {
            q[0] = static_cast<std::uint8_t>(std::min(255, 96 + 4 * d));
            q[1] = q[2] = 0;
        } else {
            const std::uint8_t* e = &expected.rgba[i * 4];
            q[0] = q[1] = q[2] = static_cast<std::uint8_t>(32 + (e[0] + e[1] + e[2]) / 12);
        }
    }
    return out;
}

}  // namespace cavewall::metrics
