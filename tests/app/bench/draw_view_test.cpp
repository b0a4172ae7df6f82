// The draw bench's fixed view (osgviewer's home position) and its frame statistics.
#include "app/bench/draw_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cavewall::bench {
namespace {

scenes::Bounds cube() {
    scenes::Bounds b;
    b.add(glm::dvec3(-1.0));
    b.add(glm::dvec3(1.0));
    return b;
}

TEST(OsgHomeView, DefaultFieldOfViewIsOsgViewersScreenAtHalfAMetre) {
    // DisplaySettings: a 0.26 m high screen seen from 0.5 m: half-angle atan(0.13 / 0.5).
    EXPECT_NEAR(kOsgViewerFovDeg, 2.0 * glm::degrees(std::atan(0.26)), 1e-3);
}

TEST(OsgHomeView, EyeOnThePlusZAxisAtTheDistanceThatFitsTheSphere) {
    const HomeView v = osgHomeView(cube(), 2.0 * glm::degrees(std::atan(0.26)), 1.0);
    // The box's sphere: radius = half the diagonal of a 2 m cube = sqrt(3).
    EXPECT_NEAR(v.radius, std::sqrt(3.0), 1e-12);
    // d = r / sin(atan(t)) = r sqrt(1 + t^2) / t with t = 0.26.
    const double d = std::sqrt(3.0) * std::sqrt(1.0 + 0.26 * 0.26) / 0.26;
    EXPECT_NEAR(v.distance, d, 1e-9);
    EXPECT_NEAR(glm::length(v.eye - glm::dvec3(0.0, 0.0, d)), 0.0, 1e-9);
    // The screen is 1 m in front, 2 t wide and high, centred on the view axis.
    EXPECT_NEAR(v.screen.lowerLeft.z, d - 1.0, 1e-12);
    EXPECT_NEAR(v.screen.lowerRight.x - v.screen.lowerLeft.x, 0.52, 1e-12);
    EXPECT_NEAR(v.screen.upperLeft.y - v.screen.lowerLeft.y, 0.52, 1e-12);
    EXPECT_NEAR(v.screen.lowerLeft.x + v.screen.lowerRight.x, 0.0, 1e-12);
}

TEST(OsgHomeView, TheSphereTouchesTheNarrowerPairOfSidePlanes) {
    scenes::Bounds hall;
    hall.add(glm::dvec3(-30.0, 0.0, -15.0));
    hall.add(glm::dvec3(30.0, 8.0, 15.0));
    for (double aspect : {1.0, 1.6, 0.5}) {
        SCOPED_TRACE(aspect);
        const HomeView v = osgHomeView(hall, 29.148, aspect);
        const double halfTan = std::tan(glm::radians(0.5 * 29.148));
        // Distance from the centre to a side plane through the eye at half-angle a is
        // d sin(a); the narrower pair (smaller half-angle) is tangent to the sphere.
        const double narrow = std::atan(std::min(halfTan, halfTan * aspect));
        EXPECT_NEAR(v.distance * std::sin(narrow), v.radius, 1e-9);
        EXPECT_NEAR(v.eye.x, 0.0, 1e-12);
        EXPECT_NEAR(v.eye.y, 4.0, 1e-12);
    }
}

TEST(DrawTiming, MedianPercentileAndRatesAtTheMedian) {
    const std::vector<double> wall{40.0, 10.0, 30.0, 20.0}, cpu{35.0, 25.0, 15.0};
    const DrawTiming t = drawTiming(wall, cpu, 2'000'000, 1024 * 1024);
    // Nearest rank: the median of four is the 2nd smallest (20), p90 the ceil(3.6) = 4th (40).
    EXPECT_DOUBLE_EQ(t.medianMs, 20.0);
    EXPECT_DOUBLE_EQ(t.p90Ms, 40.0);
    EXPECT_DOUBLE_EQ(t.cpuMedianMs, 25.0);
    // 2 M triangles in 20 ms: 100 M per second; 1024^2 pixels in 20 ms: 52.4288 M per second.
    EXPECT_NEAR(t.mtrianglesPerS, 100.0, 1e-9);
    EXPECT_NEAR(t.mpixelsPerS, 52.4288, 1e-9);
}

}  // namespace
}  // namespace cavewall::bench
