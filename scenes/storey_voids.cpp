#include "scenes/storey_voids.h"

#include "scenes/plan_raster.h"
#include "scenes/region.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace cavewall::scenes {

PlanMask::PlanMask(glm::dvec2 origin, double step, int nx, int nz, const std::vector<bool>& open)
    : _origin(origin), _step(step), _nx(nx), _nz(nz) {
    const std::size_t w = static_cast<std::size_t>(nx) + 1;
    _sums.assign(w * (static_cast<std::size_t>(nz) + 1), 0);
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i)
            _sums[(j + 1) * w + i + 1] = _sums[j * w + i + 1] + _sums[(j + 1) * w + i] - _sums[j * w + i] +
                                         (open[static_cast<std::size_t>(j) * nx + i] ? 1 : 0);
}

long PlanMask::count(glm::dvec2 lo, glm::dvec2 hi) const {
    if (_sums.empty() || !(lo.x <= hi.x && lo.y <= hi.y)) return 0;  // also NaN
    // Samples i with origin + step * (i + 0.5) in [lo, hi]: i in [ceil(a - 0.5), floor(b - 0.5)].
    auto first = [&](double v, double o, int n) {
        return static_cast<int>(std::clamp(std::ceil((v - o) / _step - 0.5), 0.0, static_cast<double>(n)));
    };
    auto last = [&](double v, double o, int n) {
        return static_cast<int>(std::clamp(std::floor((v - o) / _step - 0.5) + 1.0, 0.0, static_cast<double>(n)));
    };
    const int i0 = first(lo.x, _origin.x, _nx), i1 = last(hi.x, _origin.x, _nx);
    const int j0 = first(lo.y, _origin.y, _nz), j1 = last(hi.y, _origin.y, _nz);
    if (i0 >= i1 || j0 >= j1) return 0;
    const std::size_t w = static_cast<std::size_t>(_nx) + 1;
    return _sums[j1 * w + i1] - _sums[j0 * w + i1] - _sums[j1 * w + i0] + _sums[j0 * w + i0];
}

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// Centres an edge misses by rounding still count: a slab of abutting boards has no cracks.
constexpr TriangleOptions kSlabEdges{1e-9};

// A grid over the cells' regions' bounds.
PlanGrid planGrid(const std::vector<PlanRect>& bounds, const VoidOptions& options) {
    glm::dvec2 lo(kUnbounded), hi(-kUnbounded);
    for (const PlanRect& b : bounds) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    PlanGrid g;
    if (!(lo.x <= hi.x && lo.y <= hi.y)) return g;
    const glm::dvec2 extent = hi - lo;
    g.cellSize = std::max(options.sampleMetres, std::max(extent.x, extent.y) / 2048.0);
    g.origin = lo - g.cellSize;
    g.nx = static_cast<int>(std::ceil(extent.x / g.cellSize)) + 2;
    g.nz = static_cast<int>(std::ceil(extent.y / g.cellSize)) + 2;
    return g;
}

// The slab of every floor level and the covering over every top level.
struct Coverage {
    std::map<double, PlanBits> slab, roof;
};

// Triangle `t` of `m` placed by `o` in the world; false when an index is out of range.
bool worldTriangle(const Object& o, const Mesh& m, std::size_t t, std::array<glm::dvec3, 3>& p) {
    for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t v = m.indices[t + k];
        if (v >= m.positions.size()) return false;
        p[k] = glm::dvec3(o.worldFromModel * glm::dvec4(glm::dvec3(m.positions[v]), 1.0));
    }
    return true;
}

// Marks one world triangle into the slabs it lies in and the coverings it lies over.
void markCoverage(const PlanGrid& g, const std::array<glm::dvec3, 3>& p, Coverage& out) {
    static const double slabCos = std::cos(kSlabTiltDeg * kPi / 180.0);
    static const double roofCos = std::cos(kRoofTiltDeg * kPi / 180.0);
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double len = glm::length(n);
    if (!(len > 0.0)) return;
    const double up = std::abs(n.y) / len;
    if (up < roofCos) return;
    const double lowY = std::min({p[0].y, p[1].y, p[2].y}), highY = std::max({p[0].y, p[1].y, p[2].y});
    const glm::dvec2 a(p[0].x, p[0].z), b(p[1].x, p[1].z), c(p[2].x, p[2].z);
    for (auto& [y, mask] : out.slab)
        if (up >= slabCos && lowY >= y - kSlabBelow && highY <= y + kSlabAbove)
            markTriangle(g, a, b, c, mask, kSlabEdges);
    for (auto& [y, mask] : out.roof)
        if (lowY > y + kCoverAbove) markTriangle(g, a, b, c, mask, kSlabEdges);
}

Coverage coverage(const Scene& scene, const PlanGrid& g, const std::vector<double>& floors,
                  const std::vector<double>& tops) {
    Coverage out;
    for (double y : floors) out.slab[y] = g.blank();
    for (double y : tops) out.roof[y] = g.blank();
    std::array<glm::dvec3, 3> p{};
    for (const Object& o : scene.objects) {
        if (o.mesh < 0 || static_cast<std::size_t>(o.mesh) >= scene.meshes.size() || o.worldBounds.empty()) continue;
        const Mesh& m = scene.meshes[static_cast<std::size_t>(o.mesh)];
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
            if (worldTriangle(o, m, t, p)) markCoverage(g, p, out);
    }
    return out;
}

// The samples of `cell` (its region's bounds: `bounds`) open from `floor` to `upper` under `roof`.
PlanMask cellVoid(const PlanGrid& g, const Cell& cell, const PlanRect& bounds, const PlanBits& floor,
                  const PlanBits& upper, const PlanBits& roof) {
    const glm::dvec2 lo = bounds.lo, hi = bounds.hi;
    // The grid covers every cell's region, so these stay within [0, n].
    auto index = [&](double v, double o, int n, bool up) {
        const double k = (v - o) / g.cellSize;
        return static_cast<int>(std::clamp(up ? std::ceil(k) : std::floor(k), 0.0, static_cast<double>(n)));
    };
    const int i0 = index(lo.x, g.origin.x, g.nx, false), i1 = index(hi.x, g.origin.x, g.nx, true);
    const int j0 = index(lo.y, g.origin.y, g.nz, false), j1 = index(hi.y, g.origin.y, g.nz, true);
    if (i0 >= i1 || j0 >= j1) return {};
    std::vector<bool> open(static_cast<std::size_t>(i1 - i0) * (j1 - j0), false);
    for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i) {
            const std::size_t s = static_cast<std::size_t>(j) * g.nx + i;
            if (floor[s] && !upper[s] && roof[s] && regionContains(cell.region, g.centre(i, j), 1e-9))
                open[static_cast<std::size_t>(j - j0) * (i1 - i0) + (i - i0)] = true;
        }
    return PlanMask(g.origin + g.cellSize * glm::dvec2(i0, j0), g.cellSize, i1 - i0, j1 - j0, open);
}

}  // namespace

std::vector<PlanMask> cellVoids(const Scene& scene, const std::vector<Cell>& cells, const std::vector<double>& tops,
                                const std::vector<PlanRect>& bounds, const VoidOptions& options) {
    std::vector<PlanMask> out(cells.size());
    const std::size_t n = std::min({cells.size(), tops.size(), bounds.size()});
    std::vector<double> floors, roofs;
    for (std::size_t c = 0; c < n; ++c)
        if (std::isfinite(tops[c]) && std::isfinite(cells[c].floorY)) {
            floors.push_back(cells[c].floorY);
            floors.push_back(tops[c]);
            roofs.push_back(tops[c]);
        }
    if (roofs.empty()) return out;
    const PlanGrid g = planGrid(bounds, options);
    if (g.nx <= 0 || g.nz <= 0) return out;
    Coverage cover = coverage(scene, g, floors, roofs);
    const int r = static_cast<int>(std::lround(options.closeMetres / g.cellSize));
    for (auto& [y, mask] : cover.slab) mask = closed(g, std::move(mask), r);
    for (std::size_t c = 0; c < n; ++c)
        if (std::isfinite(tops[c]) && std::isfinite(cells[c].floorY))
            out[c] = cellVoid(g, cells[c], bounds[c], cover.slab.at(cells[c].floorY), cover.slab.at(tops[c]),
                              cover.roof.at(tops[c]));
    return out;
}

}  // namespace cavewall::scenes
