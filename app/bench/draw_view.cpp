#include "app/bench/draw_view.h"

#include "display/timing.h"

#include <cassert>
#include <cmath>

namespace cavewall::bench {

HomeView osgHomeView(const scenes::Bounds& bounds, double verticalFovDeg, double aspect) {
    assert(!bounds.empty() && verticalFovDeg > 0.0 && verticalFovDeg < 180.0 && aspect > 0.0);
    const double halfTan = std::tan(glm::radians(0.5 * verticalFovDeg));
    const double halfWidthTan = halfTan * aspect;
    HomeView v;
    v.radius = 0.5 * glm::length(bounds.max - bounds.min);
    v.distance = v.radius / std::sin(std::atan(std::min(halfTan, halfWidthTan)));
    const glm::dvec3 centre = bounds.centre();
    v.eye = centre + glm::dvec3(0.0, 0.0, v.distance);
    const glm::dvec3 screenCentre = v.eye - glm::dvec3(0.0, 0.0, 1.0);
    v.screen.lowerLeft = screenCentre + glm::dvec3(-halfWidthTan, -halfTan, 0.0);
    v.screen.lowerRight = screenCentre + glm::dvec3(halfWidthTan, -halfTan, 0.0);
    v.screen.upperLeft = screenCentre + glm::dvec3(-halfWidthTan, halfTan, 0.0);
    return v;
}

DrawTiming drawTiming(std::span<const double> frameMs, std::span<const double> cpuMs, std::size_t triangles,
                      std::size_t pixels) {
    assert(!frameMs.empty());
    DrawTiming t;
    t.cpuMedianMs = display::median(cpuMs);
    t.medianMs = display::median(frameMs);
    t.p90Ms = display::percentile(frameMs, 0.9);
    const double seconds = t.medianMs * 1e-3;
    if (seconds > 0.0) {
        t.mtrianglesPerS = static_cast<double>(triangles) / seconds * 1e-6;
        t.mpixelsPerS = static_cast<double>(pixels) / seconds * 1e-6;
    }
    return t;
}

}  // namespace cavewall::bench
