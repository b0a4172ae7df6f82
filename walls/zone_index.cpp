#include "walls/zone_index.h"

#include <algorithm>
#include <cmath>

namespace cavewall::walls {
namespace {

void bounds(const Polygon2& p, glm::dvec2& lo, glm::dvec2& hi) {
    lo = glm::dvec2(INFINITY);
    hi = glm::dvec2(-INFINITY);
    for (const glm::dvec2& v : p) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
}

}  // namespace

ZoneIndex::ZoneIndex(const Plan& plan) {
    for (const Zone& z : plan.zones) _polygons.push_back(z.floorPolygon);
    for (const WallSide& s : plan.sides) {
        SideGrid g;
        g.cell = s.cell;
        g.wall = s.wall;
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (int z = s.firstZone; z < s.firstZone + s.zoneCount; ++z) {
            glm::dvec2 zl, zh;
            bounds(_polygons[z], zl, zh);
            lo = glm::min(lo, zl);
            hi = glm::max(hi, zh);
        }
        if (s.zoneCount > 0) {
            // About one zone per square on average keeps the lists short.
            const glm::dvec2 size = glm::max(hi - lo, glm::dvec2(1e-6));
            g.square = std::max(std::sqrt(size.x * size.y / s.zoneCount), 1e-3);
            g.origin = lo;
            g.count = glm::max(glm::ivec2(glm::ceil(size / g.square)), glm::ivec2(1));
            g.squares.resize(std::size_t(g.count.x) * g.count.y);
            for (int z = s.firstZone; z < s.firstZone + s.zoneCount; ++z) {
                glm::dvec2 zl, zh;
                bounds(_polygons[z], zl, zh);
                const glm::ivec2 a =
                    glm::clamp(glm::ivec2(glm::floor((zl - lo) / g.square)), glm::ivec2(0), g.count - 1);
                const glm::ivec2 b =
                    glm::clamp(glm::ivec2(glm::floor((zh - lo) / g.square)), glm::ivec2(0), g.count - 1);
                for (int y = a.y; y <= b.y; ++y)
                    for (int x = a.x; x <= b.x; ++x) g.squares[std::size_t(y) * g.count.x + x].push_back(z);
            }
        }
        _sides.push_back(std::move(g));
    }
}

int ZoneIndex::find(int cell, int wall, glm::dvec2 p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return -1;
    for (const SideGrid& g : _sides) {
        if (g.cell != cell || g.wall != wall || g.squares.empty()) continue;
        const glm::dvec2 f = glm::floor((p - g.origin) / g.square);
        // Points on the far border belong to the last square; anything further is outside.
        const glm::ivec2 i = glm::clamp(glm::ivec2(f), glm::ivec2(0), g.count - 1);
        if (!(std::abs(f.x - i.x) <= 1 && std::abs(f.y - i.y) <= 1)) return -1;
        for (int z : g.squares[std::size_t(i.y) * g.count.x + i.x])
            if (containsConvex(_polygons[z], p)) return z;
        return -1;
    }
    return -1;
}

}  // namespace cavewall::walls
