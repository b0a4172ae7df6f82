#include "display/pixel_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace cavewall::display {

namespace {

// r² / (h p) at the screen point (x, y).
double pixelsPerRadianAt(const ViewScreen& s, double x, double y) {
    return (x * x + y * y + s.distance * s.distance) / (s.distance * s.pixelSize);
}

// The corner of [x0, x1] x [y0, y1] farthest from the screen's foot point (0, 0).
double farthestCorner(const ViewScreen& s, double x0, double x1, double y0, double y1) {
    return pixelsPerRadianAt(s, std::max(std::abs(x0), std::abs(x1)), std::max(std::abs(y0), std::abs(y1)));
}

}  // namespace

ViewScreen viewScreen(const OffAxisFrustum& frustum, glm::ivec2 viewportSize) {
    ViewScreen s;
    s.distance = frustum.eyeDistance;
    const glm::dmat4 viewFromClip = glm::inverse(frustum.clipFromView);
    // The rays through the NDC corners, scaled onto the screen plane z = -h.
    auto onScreen = [&](double x, double y) {
        const glm::dvec4 p = viewFromClip * glm::dvec4(x, y, 0.5, 1.0);
        const glm::dvec3 v = glm::dvec3(p) / p.w;
        return v * (s.distance / -v.z);
    };
    const glm::dvec3 lowerLeft = onScreen(-1.0, -1.0), upperRight = onScreen(1.0, 1.0);
    s.left = lowerLeft.x;
    s.bottom = lowerLeft.y;
    s.right = upperRight.x;
    s.top = upperRight.y;
    const double px = (s.right - s.left) / std::max(viewportSize.x, 1);
    const double py = (s.top - s.bottom) / std::max(viewportSize.y, 1);
    s.pixelSize = std::min(px, py);
    return s;
}

ViewScreen viewScreen(const ScreenQuad& screen, glm::dvec3 eye, glm::ivec2 pixels) {
    const ScreenBasis b = screenBasis(screen);
    const glm::dvec3 toCorner = screen.lowerLeft - eye;
    ViewScreen s;
    s.distance = std::max(std::abs(glm::dot(toCorner, b.normal)), 1e-3);
    s.left = glm::dot(toCorner, b.right);
    s.right = s.left + b.width;
    s.bottom = glm::dot(toCorner, b.up);
    s.top = s.bottom + b.height;
    s.pixelSize = std::min(b.width / std::max(pixels.x, 1), b.height / std::max(pixels.y, 1));
    return s;
}

double maxPixelsPerRadian(const ViewScreen& screen) {
    return farthestCorner(screen, screen.left, screen.right, screen.bottom, screen.top);
}

double minPixelsPerDegree(const ViewScreen& screen) {
    // The screen point nearest the eye (the origin) is the foot point (0, 0, -h) clamped to the
    // rectangle. At distance r a ray turning across its plane with the normal moves r metres per
    // radian, within that plane r² / h >= r: the fewest pixels per radian there are r / p.
    const double x = std::clamp(0.0, screen.left, screen.right), y = std::clamp(0.0, screen.bottom, screen.top);
    const double r = std::sqrt(x * x + y * y + screen.distance * screen.distance);
    return r / screen.pixelSize * std::numbers::pi / 180.0;
}

double maxPixelsPerRadian(const ViewScreen& screen, std::span<const glm::dvec3> viewPoints) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const glm::dvec3& p : viewPoints) {
        // On or behind the eye plane a point projects anywhere: the whole screen.
        if (!(p.z < 0.0)) return maxPixelsPerRadian(screen);
        const double k = screen.distance / -p.z;
        x0 = std::min(x0, p.x * k);
        x1 = std::max(x1, p.x * k);
        y0 = std::min(y0, p.y * k);
        y1 = std::max(y1, p.y * k);
    }
    x0 = std::max(x0, screen.left);
    x1 = std::min(x1, screen.right);
    y0 = std::max(y0, screen.bottom);
    y1 = std::min(y1, screen.top);
    if (!(x0 <= x1 && y0 <= y1)) return 0.0;
    return farthestCorner(screen, x0, x1, y0, y1);
}

double maxPixelsPerRadianInFront(const ViewScreen& screen, std::span<const glm::dvec3> viewPoints) {
    // The hull cut by the plane z = -e is the hull of the points in front and of the plane's
    // crossings of every segment from a point in front to one behind.
    constexpr double e = 1e-9;
    std::vector<glm::dvec3> front;
    for (const glm::dvec3& a : viewPoints) {
        if (!(a.z <= -e)) continue;
        front.push_back(a);
        for (const glm::dvec3& b : viewPoints)
            if (b.z > -e) front.push_back(a + (b - a) * ((-e - a.z) / (b.z - a.z)));
    }
    return front.empty() ? 0.0 : maxPixelsPerRadian(screen, front);
}

double nearestDistance(std::span<const glm::dvec3> points) {
    if (points.empty()) return std::numeric_limits<double>::infinity();
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 outside = glm::max(glm::max(lo, -hi), glm::dvec3(0.0));
    return glm::length(outside);
}

double maxStretch(const glm::dmat3& m) {
    // The square root of the largest eigenvalue of the symmetric a = mᵀm, in closed form
    // (trigonometric solution of its characteristic cubic).
    const glm::dmat3 a = glm::transpose(m) * m;
    const double off = a[1][0] * a[1][0] + a[2][0] * a[2][0] + a[2][1] * a[2][1];
    double largest = std::max({a[0][0], a[1][1], a[2][2]});
    if (off > 0.0) {
        const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
        const double p2 =
            (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) + (a[2][2] - q) * (a[2][2] - q) + 2.0 * off;
        const double p = std::sqrt(p2 / 6.0);
        const glm::dmat3 b = (a - q * glm::dmat3(1.0)) / p;
        const double phi = std::acos(std::clamp(0.5 * glm::determinant(b), -1.0, 1.0)) / 3.0;
        largest = std::max(largest, q + 2.0 * p * std::cos(phi));
    }
    // A few ulps up, so rounding never makes the bound too small.
    return std::sqrt(std::max(largest, 0.0)) * (1.0 + 1e-12);
}

}  // namespace cavewall::display
