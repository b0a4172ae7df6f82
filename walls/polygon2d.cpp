#include "walls/polygon2d.h"

#include <algorithm>

#include <cmath>

namespace cavewall::walls {

Polygon2 clipHalfPlane(const Polygon2& polygon, glm::dvec2 normal, double offset) {
    Polygon2 out;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % n];
        const double da = glm::dot(normal, a) - offset, db = glm::dot(normal, b) - offset;
        if (da <= 0) out.push_back(a);
        // The edge crosses the line: keep the crossing point (exact at the endpoints).
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out.size() >= 3 ? out : Polygon2{};
}

Polygon2 clipBox(const Polygon2& polygon, glm::dvec2 lo, glm::dvec2 hi) {
    Polygon2 p = polygon;
    if (std::isfinite(lo.x)) p = clipHalfPlane(p, {-1, 0}, -lo.x);
    if (std::isfinite(hi.x)) p = clipHalfPlane(p, {1, 0}, hi.x);
    if (std::isfinite(lo.y)) p = clipHalfPlane(p, {0, -1}, -lo.y);
    if (std::isfinite(hi.y)) p = clipHalfPlane(p, {0, 1}, hi.y);
    return p;
}

double signedArea(const Polygon2& polygon) {
    double twice = 0;
    for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % n];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

glm::dvec2 centroid(const Polygon2& polygon) {
    if (polygon.empty()) return glm::dvec2(0.0);
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& p : polygon) mean += p;
    mean /= double(polygon.size());
    const double area = signedArea(polygon);
    if (std::abs(area) < 1e-12) return mean;
    // Relative to the mean for precision far from the origin.
    glm::dvec2 c(0.0);
    for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
        const glm::dvec2 a = polygon[i] - mean, b = polygon[(i + 1) % n] - mean;
        const double cross = a.x * b.y - b.x * a.y;
        c += (a + b) * cross;
    }
    return mean + c / (6.0 * area);
}

bool containsConvex(const Polygon2& polygon, glm::dvec2 p, double tolerance) {
    if (polygon.size() < 3) return false;
    const double orientation = signedArea(polygon) >= 0 ? 1.0 : -1.0;
    for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % n];
        const glm::dvec2 e = b - a;
        const double len = glm::length(e);
        if (len == 0) continue;
        const double side = orientation * (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / len;
        if (side < -tolerance) return false;
    }
    return true;
}

glm::dvec2 closestPointConvex(const Polygon2& polygon, glm::dvec2 p) {
    if (polygon.empty() || containsConvex(polygon, p, 0.0)) return p;
    glm::dvec2 best = polygon[0];
    double bestDistance = glm::length(p - best);
    for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
        const glm::dvec2 a = polygon[i], e = polygon[(i + 1) % n] - a;
        const double ee = glm::dot(e, e);
        const glm::dvec2 q = ee > 0.0 ? a + std::clamp(glm::dot(p - a, e) / ee, 0.0, 1.0) * e : a;
        if (const double d = glm::length(p - q); d < bestDistance) best = q, bestDistance = d;
    }
    return best;
}

bool isConvex(const Polygon2& polygon) {
    const std::size_t n = polygon.size();
    if (n < 3 || std::abs(signedArea(polygon)) < 1e-12) return false;
    int sign = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % n], c = polygon[(i + 2) % n];
        const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
        if (std::abs(cross) < 1e-12) continue;
        const int s = cross > 0 ? 1 : -1;
        if (sign != 0 && s != sign) return false;
        sign = s;
    }
    return true;
}

}  // namespace cavewall::walls
