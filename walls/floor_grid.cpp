#include "walls/floor_grid.h"

#include "config/error.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace cavewall::walls {

namespace {

constexpr double kMaxCells = 16e6;  // a storey's grid, at most (coarser cells beyond)

void markRect(FloorGrid& g, std::vector<std::uint8_t>& layer, glm::dvec2 lo, glm::dvec2 hi) {
    const scenes::CellRange r = scenes::centresIn(g, lo, hi);
    for (int k = r.k0; k <= r.k1; ++k)
        for (int i = r.i0; i <= r.i1; ++i) layer[g.index(i, k)] = 1;
}

// An object's world triangles, one call per triangle.
template <typename F>
void forEachTriangle(const scenes::Scene& scene, const scenes::Object& o, F&& f) {
    const scenes::Mesh& m = scene.meshes[o.mesh];
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        glm::dvec3 p[3];
        for (int v = 0; v < 3; ++v)
            p[v] = glm::dvec3(o.worldFromModel * glm::dvec4(glm::dvec3(m.positions[m.indices[t + v]]), 1.0));
        f(p[0], p[1], p[2]);
    }
}

// The extent of an object's vertices along the minor principal axis of their (x, z) spread.
double footprintThickness(const scenes::Scene& scene, const scenes::Object& o) {
    const scenes::Mesh& m = scene.meshes[o.mesh];
    if (m.positions.empty()) return 0.0;
    std::vector<glm::dvec2> xz;
    xz.reserve(m.positions.size());
    glm::dvec2 mean(0.0);
    for (const glm::vec3& p : m.positions) {
        const glm::dvec3 w(o.worldFromModel * glm::dvec4(glm::dvec3(p), 1.0));
        xz.push_back({w.x, w.z});
        mean += xz.back();
    }
    mean /= static_cast<double>(xz.size());
    double sxx = 0.0, sxz = 0.0, szz = 0.0;
    for (const glm::dvec2& p : xz) {
        const glm::dvec2 d = p - mean;
        sxx += d.x * d.x;
        sxz += d.x * d.y;
        szz += d.y * d.y;
    }
    // The major axis's angle of the 2x2 covariance; the minor axis is perpendicular to it.
    const double angle = 0.5 * std::atan2(2.0 * sxz, sxx - szz);
    const glm::dvec2 minor(-std::sin(angle), std::cos(angle));
    double lo = 1e300, hi = -1e300;
    for (const glm::dvec2& p : xz) {
        const double t = glm::dot(p - mean, minor);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    return hi - lo;
}

double verticalShare(const scenes::Scene& scene, const scenes::Object& o) {
    const double maxUp = std::sin(glm::radians(15.0));
    double vertical = 0.0, all = 0.0;
    forEachTriangle(scene, o, [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double area = glm::length(n);
        all += area;
        if (area > 0.0 && std::abs(n.y) <= maxUp * area) vertical += area;
    });
    return all > 0.0 ? vertical / all : 0.0;
}

bool isWallElement(const scenes::Scene& scene, const scenes::Object& o, double floorY, double ceilingY,
                   const FloorGridOptions& options) {
    const scenes::Bounds& b = o.worldBounds;
    if (b.empty() || o.mesh < 0 || o.mesh >= static_cast<int>(scene.meshes.size())) return false;
    const double minTop = std::min(options.minTop, ceilingY - floorY - 0.1);
    if (b.min.y > floorY + options.maxBottom || b.max.y < floorY + minTop) return false;
    if (std::min(b.size().x, b.size().z) > options.maxThickness && footprintThickness(scene, o) > options.maxThickness)
        return false;
    return verticalShare(scene, o) >= options.minVerticalShare;
}

// The segment where the triangle meets the plane y = h, when it crosses it.
bool sliceTriangle(const glm::dvec3 p[3], double h, glm::dvec2& a, glm::dvec2& b) {
    glm::dvec2 hits[2];
    int n = 0;
    for (int e = 0; e < 3 && n < 2; ++e) {
        const glm::dvec3& u = p[e];
        const glm::dvec3& v = p[(e + 1) % 3];
        if ((u.y < h) == (v.y < h)) continue;
        const double t = (h - u.y) / (v.y - u.y);
        hits[n++] = {u.x + t * (v.x - u.x), u.z + t * (v.z - u.z)};
    }
    if (n < 2) return false;
    a = hits[0];
    b = hits[1];
    return true;
}

bool meetsRect(const scenes::Object& o, const scenes::Scene& scene, const FloorGrid& g) {
    const scenes::Bounds& b = o.worldBounds;
    return !b.empty() && b.max.x >= g.origin.x && b.max.z >= g.origin.y && b.min.x <= g.origin.x + g.nx * g.cellSize &&
           b.min.z <= g.origin.y + g.nz * g.cellSize && o.mesh >= 0 && o.mesh < static_cast<int>(scene.meshes.size());
}

// The walking floor near floorY (see the header): the bin with the most upward area.
double walkingFloor(const scenes::Scene& scene, const FloorGrid& g, double floorY, const FloorGridOptions& options) {
    constexpr double kBin = 0.05;
    const double lo = floorY - options.floorSearchBelow, minUp = std::cos(glm::radians(10.0));
    const int bins = static_cast<int>(std::ceil((options.floorSearchBelow + options.floorSearchAbove) / kBin));
    std::vector<double> area(bins, 0.0);
    for (const scenes::Object& o : scene.objects) {
        if (!meetsRect(o, scene, g) || o.worldBounds.min.y > lo + bins * kBin || o.worldBounds.max.y < lo) continue;
        forEachTriangle(scene, o, [&](glm::dvec3 p, glm::dvec3 q, glm::dvec3 r) {
            const glm::dvec3 n = glm::cross(q - p, r - p);
            const double length = glm::length(n);
            const int bin = static_cast<int>(std::floor(((p.y + q.y + r.y) / 3.0 - lo) / kBin));
            if (length > 0.0 && n.y >= minUp * length && bin >= 0 && bin < bins) area[bin] += 0.5 * n.y;
        });
    }
    const auto most = std::max_element(area.begin(), area.end());
    if (*most <= 0.0) return floorY;
    return lo + (static_cast<double>(most - area.begin()) + 0.5) * kBin;
}

}  // namespace

FloorGrid makeFloorGrid(glm::dvec2 lo, glm::dvec2 hi, double cellSize) {
    assert(cellSize > 0.0);
    FloorGrid g;
    g.origin = lo;
    g.cellSize = cellSize;
    g.nx = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / cellSize)));
    g.nz = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / cellSize)));
    g.wall.assign(static_cast<std::size_t>(g.nx) * g.nz, 0);
    g.floor.assign(g.wall.size(), 0);
    return g;
}

void markWallSegment(FloorGrid& g, glm::dvec2 a, glm::dvec2 b) {
    // Steps of a quarter cell meet every cell the segment crosses but for corners it only grazes.
    const int steps = std::max(1, static_cast<int>(std::ceil(glm::length(b - a) / (0.25 * g.cellSize))));
    for (int s = 0; s <= steps; ++s) {
        if (const int c = g.cellAt(glm::mix(a, b, static_cast<double>(s) / steps)); c >= 0) g.wall[c] = 1;
    }
}

void markWallRect(FloorGrid& g, glm::dvec2 lo, glm::dvec2 hi) { markRect(g, g.wall, lo, hi); }
void markFloorRect(FloorGrid& g, glm::dvec2 lo, glm::dvec2 hi) { markRect(g, g.floor, lo, hi); }

void markFloorTriangle(FloorGrid& g, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    scenes::markTriangle(g, a, b, c, g.floor);
}

StoreyGrid rasteriseStorey(const scenes::Scene& scene, double floorY, double ceilingY, glm::dvec2 lo, glm::dvec2 hi,
                           const FloorGridOptions& options) {
    if (!(options.cellSize > 0.0) || !std::isfinite(options.cellSize))
        throw Error("floor grid: cell size out of range (expected > 0 m, got " + std::to_string(options.cellSize) +
                    ")");
    StoreyGrid out;
    const glm::dvec2 size = glm::max(hi - lo + 2.0 * options.margin, glm::dvec2(0.0));
    const double cellSize = std::max(options.cellSize, std::sqrt(size.x * size.y / kMaxCells));
    out.grid = makeFloorGrid(lo - options.margin, hi + options.margin, cellSize);
    FloorGrid& g = out.grid;
    const double minUp = std::cos(glm::radians(10.0));
    floorY = walkingFloor(scene, g, floorY, options);
    out.floorY = floorY;
    for (const scenes::Object& o : scene.objects) {
        if (!meetsRect(o, scene, g)) continue;
        const scenes::Bounds& b = o.worldBounds;
        if (b.min.y <= floorY + options.floorTolerance && b.max.y >= floorY - options.floorTolerance)
            forEachTriangle(scene, o, [&](glm::dvec3 p, glm::dvec3 q, glm::dvec3 r) {
                const glm::dvec3 n = glm::cross(q - p, r - p);
                const double length = glm::length(n);
                if (!(length > 0.0) || n.y < minUp * length) return;
                if (std::abs((p.y + q.y + r.y) / 3.0 - floorY) > options.floorTolerance) return;
                markFloorTriangle(g, {p.x, p.z}, {q.x, q.z}, {r.x, r.z});
            });
        if (!isWallElement(scene, o, floorY, ceilingY, options)) continue;
        ++out.wallElements;
        forEachTriangle(scene, o, [&](glm::dvec3 p, glm::dvec3 q, glm::dvec3 r) {
            const glm::dvec3 tri[3] = {p, q, r};
            for (double h : options.sliceHeights) {
                glm::dvec2 a, c;
                if (sliceTriangle(tri, floorY + h, a, c)) markWallSegment(g, a, c);
            }
        });
    }
    return out;
}

std::vector<float> chamferDistance(const FloorGrid& g, const std::vector<std::uint8_t>& source) {
    constexpr float kFar = 1e9f;
    std::vector<float> d(source.size(), kFar);
    for (std::size_t c = 0; c < source.size(); ++c)
        if (source[c]) d[c] = 0.0f;
    auto relax = [&](int i, int k, int di, int dk, float w) {
        if (g.inside(i + di, k + dk)) d[g.index(i, k)] = std::min(d[g.index(i, k)], d[g.index(i + di, k + dk)] + w);
    };
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i) {
            relax(i, k, -1, 0, 3.0f);
            relax(i, k, 0, -1, 3.0f);
            relax(i, k, -1, -1, 4.0f);
            relax(i, k, 1, -1, 4.0f);
        }
    for (int k = g.nz - 1; k >= 0; --k)
        for (int i = g.nx - 1; i >= 0; --i) {
            relax(i, k, 1, 0, 3.0f);
            relax(i, k, 0, 1, 3.0f);
            relax(i, k, 1, 1, 4.0f);
            relax(i, k, -1, 1, 4.0f);
        }
    for (float& v : d) v /= 3.0f;
    return d;
}

}  // namespace cavewall::walls
