#include "scenes/region.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::scenes {
namespace {

// z grows towards the viewer, so seen from +Y the plane is (x, -z): a left turn there is a
// negative cross product in (x, z).
double turn(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const glm::dvec2 u = b - a, v = c - b;
    return -(u.x * v.y - u.y * v.x);
}

}  // namespace

PlanRect regionBounds(const std::vector<glm::dvec2>& region) {
    PlanRect r;
    for (const glm::dvec2& p : region) {
        r.lo = glm::min(r.lo, p);
        r.hi = glm::max(r.hi, p);
    }
    return r;
}

double regionArea(const std::vector<glm::dvec2>& r) {
    double s = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const glm::dvec2 a = r[i], b = r[(i + 1) % r.size()];
        s += a.x * b.y - b.x * a.y;
    }
    return -0.5 * s;
}

int firstNonConvexCorner(const std::vector<glm::dvec2>& r) {
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = r[(i + n - 1) % n], b = r[i], c = r[(i + 1) % n];
        const double scale = glm::length(b - a) * glm::length(c - b);
        const double t = turn(a, b, c);
        if (t < -1e-9 * scale) return static_cast<int>(i);
        // Straight on is fine; going straight back (a spike) is not.
        if (std::abs(t) <= 1e-9 * scale && glm::dot(b - a, c - b) < 0.0) return static_cast<int>(i);
    }
    return -1;
}

bool regionContains(const std::vector<glm::dvec2>& r, glm::dvec2 p, double tolerance) {
    if (r.size() < 3) return false;
    // Inside is left of every edge seen from above for a counter-clockwise region, right for a
    // clockwise one.
    const double inward = regionArea(r) >= 0.0 ? 1.0 : -1.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const glm::dvec2 a = r[i], b = r[(i + 1) % r.size()];
        const double len = glm::length(b - a);
        if (len == 0.0) continue;
        // Signed distance of p to the inner side of edge a->b.
        if (inward * turn(a, b, p) / len < -tolerance) return false;
    }
    return true;
}

double overlapArea(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b) {
    // Sutherland-Hodgman: clip a by every edge of b (both convex, counter-clockwise).
    std::vector<glm::dvec2> poly = a;
    for (std::size_t i = 0; i < b.size() && !poly.empty(); ++i) {
        const glm::dvec2 e0 = b[i], e1 = b[(i + 1) % b.size()];
        std::vector<glm::dvec2> out;
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const glm::dvec2 p = poly[k], q = poly[(k + 1) % poly.size()];
            const double dp = turn(e0, e1, p), dq = turn(e0, e1, q);
            if (dp >= 0.0) out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        poly = std::move(out);
    }
    return poly.size() < 3 ? 0.0 : std::max(regionArea(poly), 0.0);
}

int findCell(const std::vector<Cell>& cells, glm::dvec3 p) {
    int best = -1, lowest = -1;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (!regionContains(cells[i].region, {p.x, p.z}, 1e-6)) continue;
        const int c = static_cast<int>(i);
        if (lowest < 0 || cells[i].floorY < cells[lowest].floorY) lowest = c;
        if (cells[i].floorY <= p.y + 0.5 && (best < 0 || cells[i].floorY > cells[best].floorY)) best = c;
    }
    return best >= 0 ? best : lowest;
}

glm::dvec2 cellHeadHeights(const SceneDescription& d, int cell) {
    if (cell < 0 || cell >= static_cast<int>(d.cells.size())) return d.headHeightRange;
    double lowest = d.cells[cell].floorY;
    for (const Cell& c : d.cells) lowest = std::min(lowest, c.floorY);
    return d.headHeightRange + (d.cells[cell].floorY - lowest);
}

namespace {

double pointSegmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

}  // namespace

double segmentRegionDistance(glm::dvec2 a, glm::dvec2 b, const std::vector<glm::dvec2>& region) {
    if (regionContains(region, a) || regionContains(region, b)) return 0.0;
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < region.size(); ++i) {
        const glm::dvec2 p = region[i], q = region[(i + 1) % region.size()];
        // Proper crossing of the two segments: opposite sides both ways.
        auto side = [](glm::dvec2 o, glm::dvec2 u, glm::dvec2 v) {
            return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
        };
        if (side(a, b, p) * side(a, b, q) < 0 && side(p, q, a) * side(p, q, b) < 0) return 0.0;
        d = std::min({d, pointSegmentDistance(p, a, b), pointSegmentDistance(a, p, q), pointSegmentDistance(b, p, q)});
    }
    return d;
}

}  // namespace cavewall::scenes
