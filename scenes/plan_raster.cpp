#include "scenes/plan_raster.h"

#include <algorithm>
#include <cmath>

namespace cavewall::scenes {

namespace {

// The first (`up`) or last index whose cell centre lies at or beyond / at or before v, clamped
// to [-1, n] before converting so that a far coordinate cannot overflow.
int centreIndex(double v, double origin, double cellSize, int n, bool up) {
    const double k = (v - origin) / cellSize - 0.5;
    return static_cast<int>(std::clamp(up ? std::ceil(k) : std::floor(k), -1.0, static_cast<double>(n)));
}

// Twice the signed area of the triangle p, q, r (positive counter-clockwise in (x, z)).
double edgeFunction(glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
}

enum class Window { Dilate, Erode };

// One pass of a (2 radius + 1) window along x (`alongX`) or z: any (dilate) or all (erode,
// cells beyond the grid counting as set) of the window's cells.
PlanBits windowPass(const PlanGrid& g, const PlanBits& in, int radius, bool alongX, Window op) {
    PlanBits out = g.blank();
    const int n = alongX ? g.nx : g.nz, lines = alongX ? g.nz : g.nx;
    std::vector<int> sums(static_cast<std::size_t>(n) + 1);
    for (int line = 0; line < lines; ++line) {
        auto at = [&](int k) {
            return static_cast<std::size_t>(alongX ? line : k) * g.nx + static_cast<std::size_t>(alongX ? k : line);
        };
        for (int k = 0; k < n; ++k) sums[k + 1] = sums[k] + (in[at(k)] ? 1 : 0);
        for (int k = 0; k < n; ++k) {
            const int a = std::max(0, k - radius), b = std::min(n, k + radius + 1);
            const int set = sums[b] - sums[a];
            out[at(k)] = (op == Window::Dilate ? set > 0 : set == b - a) ? 1 : 0;
        }
    }
    return out;
}

PlanBits squareWindow(const PlanGrid& g, const PlanBits& mask, int radius, Window op) {
    if (radius <= 0) return mask;
    return windowPass(g, windowPass(g, mask, radius, true, op), radius, false, op);
}

}  // namespace

CellRange centresIn(const PlanGrid& g, glm::dvec2 lo, glm::dvec2 hi) {
    if (!(std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(hi.x) && std::isfinite(hi.y))) return {};
    CellRange r;
    r.i0 = std::max(0, centreIndex(lo.x, g.origin.x, g.cellSize, g.nx, true));
    r.i1 = std::min(g.nx - 1, centreIndex(hi.x, g.origin.x, g.cellSize, g.nx, false));
    r.k0 = std::max(0, centreIndex(lo.y, g.origin.y, g.cellSize, g.nz, true));
    r.k1 = std::min(g.nz - 1, centreIndex(hi.y, g.origin.y, g.cellSize, g.nz, false));
    return r;
}

void markTriangle(const PlanGrid& g, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, PlanBits& mask,
                  const TriangleOptions& options) {
    const double area = edgeFunction(a, b, c);
    if (area == 0.0) return;
    const CellRange r = centresIn(g, glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
    const double sign = area > 0.0 ? 1.0 : -1.0, tolerance = -options.edgeTolerance * std::abs(area);
    for (int k = r.k0; k <= r.k1; ++k)
        for (int i = r.i0; i <= r.i1; ++i) {
            const glm::dvec2 p = g.centre(i, k);
            if (sign * edgeFunction(a, b, p) >= tolerance && sign * edgeFunction(b, c, p) >= tolerance &&
                sign * edgeFunction(c, a, p) >= tolerance)
                mask[static_cast<std::size_t>(g.index(i, k))] = 1;
        }
}

PlanBits dilated(const PlanGrid& g, const PlanBits& mask, int radius) {
    return squareWindow(g, mask, radius, Window::Dilate);
}

PlanBits eroded(const PlanGrid& g, const PlanBits& mask, int radius) {
    return squareWindow(g, mask, radius, Window::Erode);
}

PlanBits closed(const PlanGrid& g, PlanBits mask, int radius) {
    if (radius <= 0) return mask;
    return eroded(g, dilated(g, mask, radius), radius);
}

}  // namespace cavewall::scenes
