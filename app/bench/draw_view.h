#pragma once
// The fixed view of `cavewall draw-bench`: the view OpenSceneGraph's osgviewer opens
// a model with, so that both draw the same pixels, and the statistics of the timed frames.
//
// osgviewer's home position (osgGA::StandardManipulator::home with its default
// COMPUTE_HOME_USING_BBOX): the bounding sphere of the model's bounding box (centre c, radius
// r = half the box diagonal), the eye at c + (0, -d, 0) in OSG's Z-up frame looking at c with
// +Z up, where d = r / sin(atan(t)) and t = the smaller of the frustum's horizontal and
// vertical half-extents at unit distance (the whole sphere fits). osgviewer's default view is
// 29.15° vertical (atan2(0.13, 0.5) x 2: DisplaySettings' 0.26 m high screen at 0.5 m), and
// its OBJ reader turns Y-up files to Z-up ((x, y, z) -> (x, -z, y)), so in cavewall's Y-up
// world the eye is at c + (0, 0, d) looking down -Z with +Y up.

#include "display/off_axis.h"
#include "scenes/scene.h"

#include <span>
#include <vector>

namespace cavewall::bench {

inline constexpr double kOsgViewerFovDeg = 29.148;  // 2 atan(0.13 / 0.5), degrees

struct HomeView {
    glm::dvec3 eye{0.0};         // world, metres
    double distance = 0.0;       // eye to the bounding sphere's centre, metres
    double radius = 0.0;         // of the bounding sphere, metres
    display::ScreenQuad screen;  // world; 1 m in front of the eye, symmetric about the view axis
};

// The home view of `bounds` (world, Y-up; not empty) for a symmetric frustum of
// `verticalFovDeg` (in (0, 180)) and `aspect` = width / height (> 0).
HomeView osgHomeView(const scenes::Bounds& bounds, double verticalFovDeg = kOsgViewerFovDeg, double aspect = 1.0);

// Frame times of one configuration and what they give per second. Wall-clock time is what a
// viewer sees; process CPU time (every thread, llvmpipe's included) is what the frame cost,
// and holds still when other processes share the cores.
struct DrawTiming {
    double medianMs = 0.0, p90Ms = 0.0;  // wall clock, nearest-rank (display/timing.h)
    double cpuMedianMs = 0.0;            // process CPU time per frame, median
    double mtrianglesPerS = 0.0;         // triangles submitted per frame / median, millions
    double mpixelsPerS = 0.0;            // pixels of the view per frame / median, millions
};

// `frameMs` (wall, at least one) and `cpuMs` (process CPU time, may be empty) of frames that
// each submitted `triangles` and filled `pixels`.
DrawTiming drawTiming(std::span<const double> frameMs, std::span<const double> cpuMs, std::size_t triangles,
                      std::size_t pixels);

}  // namespace cavewall::bench
