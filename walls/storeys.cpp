#include "walls/storeys.h"

#include "scenes/region.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace cavewall::walls {

namespace {

// A run of adjacent non-empty histogram bins: its area-weighted height and its area.
struct Level {
    double y = 0.0, area = 0.0;
};

// Levels of the facets facing `up` (true) or down: runs of adjacent non-empty bins.
std::vector<Level> levelsOf(const std::vector<Facet>& facets, bool up, double bin) {
    std::map<long long, std::pair<double, double>> bins;  // bin -> (area, area x y)
    for (const Facet& f : facets) {
        if (f.up != up || !(f.area > 0.0)) continue;
        auto& [area, moment] = bins[static_cast<long long>(std::floor(f.y / bin))];
        area += f.area;
        moment += f.area * f.y;
    }
    std::vector<Level> levels;
    long long previous = 0;
    double moment = 0.0;
    for (const auto& [index, sums] : bins) {
        if (levels.empty() || index > previous + 1) {
            if (!levels.empty()) levels.back().y = moment / levels.back().area;
            levels.push_back({});
            moment = 0.0;
        }
        levels.back().area += sums.first;
        moment += sums.second;
        previous = index;
    }
    if (!levels.empty()) levels.back().y = moment / levels.back().area;
    return levels;
}

// Levels closer than `merge` join the one with the most area (which keeps its height).
std::vector<Level> mergeLevels(std::vector<Level> levels, double merge) {
    std::sort(levels.begin(), levels.end(),
              [](const Level& a, const Level& b) { return a.area > b.area || (a.area == b.area && a.y < b.y); });
    std::vector<Level> kept;
    for (const Level& l : levels) {
        auto near = std::min_element(kept.begin(), kept.end(), [&](const Level& a, const Level& b) {
            return std::abs(a.y - l.y) < std::abs(b.y - l.y);
        });
        if (near != kept.end() && std::abs(near->y - l.y) < merge)
            near->area += l.area;
        else
            kept.push_back(l);
    }
    std::sort(kept.begin(), kept.end(), [](const Level& a, const Level& b) { return a.y < b.y; });
    return kept;
}

double areaAbove(const std::vector<Level>& ceilings, double y) {
    double area = 0.0;
    for (const Level& c : ceilings)
        if (c.y > y) area += c.area;
    return area;
}

// The highest ceiling level in (lo, hi) with at least `minArea`; `fallback` when none.
double ceilingIn(const std::vector<Level>& ceilings, double lo, double hi, double minArea, double fallback) {
    double y = fallback;
    bool found = false;
    for (const Level& c : ceilings)
        if (c.y > lo && c.y < hi && c.area >= minArea && (!found || c.y > y)) {
            y = c.y;
            found = true;
        }
    return y;
}

// 1 m columns of (x, z).
using Column = std::pair<long long, long long>;

// True when `heights` (sorted) climb from `low` to `high` in steps no larger than `maxStep`.
bool climbs(const std::vector<double>& heights, double low, double high, double maxStep) {
    double at = low;
    for (double y : heights) {
        if (y - at > maxStep) return false;
        at = std::max(at, y);
    }
    return high - at <= maxStep;
}

// Stairs between floors `from` and `from + 1` (the header's rule).
void addStairs(Storeys& out, const std::vector<Facet>& facets, int from, const StoreyOptions& options) {
    const double low = out.storeys[from].floorY + options.minHeadroom / 4.0;
    const double high = out.storeys[from + 1].floorY - options.minHeadroom / 4.0;
    std::map<Column, std::vector<double>> heights;  // sorted once gathered
    std::map<Column, double> columnArea;
    for (const Facet& f : facets) {
        if (!f.up || f.y <= low || f.y >= high) continue;
        const Column c{static_cast<long long>(std::floor(f.centre.x)), static_cast<long long>(std::floor(f.centre.y))};
        heights[c].push_back(f.y);
        columnArea[c] += f.area;
    }
    std::set<Column> open;
    for (const auto& [c, area] : columnArea)
        if (area >= 0.05) open.insert(c);
    for (auto& [c, ys] : heights) std::sort(ys.begin(), ys.end());
    while (!open.empty()) {
        std::vector<Column> stack{*open.begin()}, component;
        open.erase(open.begin());
        while (!stack.empty()) {
            const Column c = stack.back();
            stack.pop_back();
            component.push_back(c);
            for (long long dx = -1; dx <= 1; ++dx)
                for (long long dz = -1; dz <= 1; ++dz)
                    if (auto n = open.find({c.first + dx, c.second + dz}); n != open.end()) {
                        stack.push_back(*n);
                        open.erase(n);
                    }
        }
        if (static_cast<double>(component.size()) > options.maxStairArea) continue;
        std::vector<double> ys;
        Stair s{from, glm::dvec2(1e300), glm::dvec2(-1e300)};
        double lowest = high, highest = low;
        for (const Column& c : component) {
            const std::vector<double>& here = heights[c];
            ys.insert(ys.end(), here.begin(), here.end());
            const glm::dvec2 corner(c.first, c.second);
            s.lo = glm::min(s.lo, corner);
            s.hi = glm::max(s.hi, corner + 1.0);
            if (here.front() < lowest) {
                lowest = here.front();
                s.bottom = corner + 0.5;
            }
            if (here.back() > highest) {
                highest = here.back();
                s.top = corner + 0.5;
            }
        }
        std::sort(ys.begin(), ys.end());
        if (climbs(ys, low, high, options.maxRise)) out.stairs.push_back(s);
    }
}

}  // namespace

std::vector<Facet> horizontalFacets(const scenes::Scene& scene, const StoreyOptions& options) {
    const double cosTilt = std::cos(options.maxTiltDeg * M_PI / 180.0);
    std::vector<Facet> facets;
    for (const scenes::Object& o : scene.objects) {
        if (o.mesh < 0 || o.mesh >= static_cast<int>(scene.meshes.size())) continue;
        const scenes::Mesh& m = scene.meshes[o.mesh];
        for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
            glm::dvec3 p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = glm::dvec3(o.worldFromModel * glm::dvec4(glm::dvec3(m.positions[m.indices[i + k]]), 1.0));
            glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
            if (o.flipWinding) n = -n;
            const double length = glm::length(n);
            if (!(length > 0.0) || std::abs(n.y) < cosTilt * length) continue;
            const glm::dvec3 c = (p[0] + p[1] + p[2]) / 3.0;
            const glm::dvec3 lo = glm::min(p[0], glm::min(p[1], p[2])), hi = glm::max(p[0], glm::max(p[1], p[2]));
            facets.push_back({c.y, 0.5 * std::abs(n.y), {c.x, c.z}, n.y > 0.0, {lo.x, lo.z}, {hi.x, hi.z}});
        }
    }
    return facets;
}

Storeys findStoreys(const std::vector<Facet>& facets, double bottomY, double topY, const StoreyOptions& options) {
    assert(options.binMetres > 0.0);
    const std::vector<Level> floors = mergeLevels(levelsOf(facets, true, options.binMetres), options.mergeMetres);
    const std::vector<Level> ceilings = levelsOf(facets, false, options.binMetres);
    double largest = 0.0;
    for (const Level& l : floors) largest = std::max(largest, l.area);
    Storeys out;
    for (const Level& l : floors)
        // Large enough, and covered: the roof is not a floor.
        if (l.area >= options.minFloorShare * largest &&
            areaAbove(ceilings, l.y + 0.5 * options.minHeadroom) >= options.minFloorShare * l.area)
            out.storeys.push_back({l.y, topY, l.area});
    if (out.storeys.empty()) return {{{bottomY, topY, 0.0}}, {}};
    for (Storey& s : out.storeys)
        for (const Facet& f : facets)
            if (f.up && std::abs(f.y - s.floorY) <= 0.25) {
                const bool first = s.floorMin.x > s.floorMax.x;
                s.floorMin = first ? f.lo : glm::min(s.floorMin, f.lo);
                s.floorMax = first ? f.hi : glm::max(s.floorMax, f.hi);
            }
    for (std::size_t i = 0; i < out.storeys.size(); ++i) {
        Storey& s = out.storeys[i];
        const bool top = i + 1 == out.storeys.size();
        const double next = top ? topY : out.storeys[i + 1].floorY;
        s.ceilingY = ceilingIn(ceilings, s.floorY + options.minHeadroom, top ? topY + 1.0 : next,
                               options.minFloorShare * s.floorArea, next);
    }
    for (std::size_t i = 0; i + 1 < out.storeys.size(); ++i) addStairs(out, facets, static_cast<int>(i), options);
    std::sort(out.stairs.begin(), out.stairs.end(), [](const Stair& a, const Stair& b) {
        return std::make_tuple(a.from, a.lo.x, a.lo.y) < std::make_tuple(b.from, b.lo.x, b.lo.y);
    });
    return out;
}

Storeys findStoreys(const scenes::Scene& scene, const StoreyOptions& options) {
    const scenes::Bounds b = scene.bounds();
    if (b.empty()) return {{{0.0, 0.0, 0.0}}, {}};
    return findStoreys(horizontalFacets(scene, options), b.min.y, b.max.y, options);
}

scenes::SceneDescription stackStoreys(const std::vector<scenes::SceneDescription>& perStorey, const Storeys& found,
                                      double eyeHeight) {
    assert(!perStorey.empty() && perStorey.size() == found.storeys.size());
    scenes::SceneDescription out = perStorey.front();
    out.cells.clear();
    out.walls.clear();
    out.realWalls.clear();
    out.walkPath.clear();
    out.wallPath.clear();
    for (std::size_t i = 0; i < perStorey.size(); ++i) {
        const scenes::SceneDescription& d = perStorey[i];
        const std::string prefix = std::to_string(i) + "/";
        const int first = static_cast<int>(out.cells.size());
        for (scenes::Cell c : d.cells) {
            c.name = prefix + c.name;
            out.cells.push_back(std::move(c));
        }
        for (scenes::VirtualWall w : d.walls) {
            w.name = prefix + w.name;
            for (int& c : w.cells) c += c >= 0 ? first : 0;
            out.walls.push_back(std::move(w));
        }
        for (scenes::RealWall w : d.realWalls) {
            w.name = prefix + w.name;
            out.realWalls.push_back(std::move(w));
        }
    }
    for (std::size_t i = 0; i < perStorey.size(); ++i) {
        const std::vector<glm::dvec3>& path = perStorey[i].walkPath;
        if (path.empty()) continue;
        if (i > 0 && !out.walkPath.empty()) {
            const double below = found.storeys[i - 1].floorY + eyeHeight, above = found.storeys[i].floorY + eyeHeight;
            const auto stair = std::find_if(found.stairs.begin(), found.stairs.end(), [&](const Stair& s) {
                return s.from == static_cast<int>(i) - 1 &&
                       scenes::findCell(out.cells, {s.bottom.x, below, s.bottom.y}) >= 0 &&
                       scenes::findCell(out.cells, {s.top.x, above, s.top.y}) >= 0;
            });
            if (stair != found.stairs.end()) {
                out.walkPath.push_back({stair->bottom.x, below, stair->bottom.y});
                out.walkPath.push_back({stair->top.x, above, stair->top.y});
            } else if (const glm::dvec3 foot{path.front().x, below, path.front().z}; out.walkPath.back() != foot) {
                out.walkPath.push_back(foot);  // no zero-length step where the loops line up
            }
        }
        out.walkPath.insert(out.walkPath.end(), path.begin(), path.end());
    }
    return out;
}

int storeyAt(const std::vector<Storey>& storeys, double y) {
    int best = -1;
    for (std::size_t i = 0; i < storeys.size(); ++i)
        if (storeys[i].floorY <= y + 0.5 && (best < 0 || storeys[i].floorY > storeys[best].floorY))
            best = static_cast<int>(i);
    if (best >= 0) return best;
    return storeys.empty() ? -1 : 0;
}

}  // namespace cavewall::walls
