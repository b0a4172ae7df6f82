#include "metrics/stereo_error.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>

namespace cavewall::metrics {

namespace {

constexpr double kArcminPerRadian = 180.0 * 60.0 / 3.14159265358979323846;

std::string sizeOf(const DepthImage& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

void expectComparable(const DepthImage& test, const DepthImage& reference) {
    const std::string where = "stereo error: '" + test.name + "' against '" + reference.name + "'";
    for (const DepthImage* image : {&test, &reference})
        if (image->width <= 0 || image->height <= 0 ||
            image->metres.size() != static_cast<std::size_t>(image->width) * static_cast<std::size_t>(image->height))
            throw Error(where + ": depth image '" + image->name + "' is " + sizeOf(*image) + " with " +
                        std::to_string(image->metres.size()) +
                        " depths (expected a non-empty image with one depth per pixel)");
    if (test.width != reference.width || test.height != reference.height)
        throw Error(where + ": sizes differ (expected " + sizeOf(reference) + ", got " + sizeOf(test) + ")");
}

void expectOptions(const StereoErrorOptions& o) {
    if (!(o.interocularMetres > 0.0 && std::isfinite(o.interocularMetres)))
        throw Error("stereo error: interocular distance: expected metres > 0, got " +
                    std::to_string(o.interocularMetres));
    if (!(o.thresholdArcmin >= 0.0 && std::isfinite(o.thresholdArcmin)))
        throw Error("stereo error: threshold: expected arc minutes >= 0, got " + std::to_string(o.thresholdArcmin));
}

// A distance is valid when it is > 0: NaN fails the comparison, +inf (background) passes.
bool validDepth(float metres) { return metres > 0.0f; }

}  // namespace

double vergenceArcmin(double metres, double interocularMetres) {
    if (std::isinf(metres)) return 0.0;
    return 2.0 * std::atan(interocularMetres / (2.0 * metres)) * kArcminPerRadian;
}

StereoError& StereoError::operator+=(const StereoError& o) {
    pixels += o.pixels;
    invalidPixels += o.invalidPixels;
    sumArcmin += o.sumArcmin;
    beyond += o.beyond;
    maxArcmin = std::max(maxArcmin, o.maxArcmin);
    return *this;
}

StereoError stereoError(const DepthImage& test, const DepthImage& reference, const StereoErrorOptions& options) {
    expectOptions(options);
    expectComparable(test, reference);
    StereoError e;
    for (std::size_t i = 0; i < test.metres.size(); ++i) {
        const float t = test.metres[i], r = reference.metres[i];
        if (!validDepth(t) || !validDepth(r)) {
            ++e.invalidPixels;
            continue;
        }
        // Equal depths (both +inf included) are exactly 0, without rounding in the subtraction.
        const double error =
            t == r
                ? 0.0
                : std::abs(vergenceArcmin(t, options.interocularMetres) - vergenceArcmin(r, options.interocularMetres));
        ++e.pixels;
        e.sumArcmin += error;
        e.maxArcmin = std::max(e.maxArcmin, error);
        if (error > options.thresholdArcmin) ++e.beyond;
    }
    return e;
}

}  // namespace cavewall::metrics
