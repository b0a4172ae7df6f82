#include "walls/storeys.h"

#include "scenes/region.h"
#include "walls/walk_grid.h"

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

// Levels of the facets facing `up` (true) or down: runs of adjacent non-empty bins, each at the
// area-weighted height of its bin with the most area.
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
    double peak = 0.0;  // the area of the run's heaviest bin so far
    for (const auto& [index, sums] : bins) {
        if (levels.empty() || index > previous + 1) {
            levels.push_back({});
            peak = 0.0;
        }
        levels.back().area += sums.first;
        if (sums.first > peak) {
            peak = sums.first;
            levels.back().y = sums.second / sums.first;
        }
        previous = index;
    }
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

// The stair between floors `from` and `from + 1` (the header's rule), if the walk finds one.
void addStair(Storeys& out, int from) {
    Stair s;
    s.from = from;
    s.path = out.walk->climb(out.storeys[from].floorY, out.storeys[from + 1].floorY);
    if (s.path.empty()) return;
    s.lo = s.hi = {s.path.front().x, s.path.front().z};
    for (const glm::dvec3& p : s.path) {
        s.lo = glm::min(s.lo, glm::dvec2(p.x, p.z));
        s.hi = glm::max(s.hi, glm::dvec2(p.x, p.z));
    }
    s.bottom = {s.path.front().x, s.path.front().z};
    s.top = {s.path.back().x, s.path.back().z};
    out.stairs.push_back(std::move(s));
}

// Adds `p` unless it repeats the last point (no zero-length step).
void append(std::vector<glm::dvec3>& path, glm::dvec3 p) {
    if (path.empty() || path.back() != p) path.push_back(p);
}

// Walks from the path's end to the floor point `to` on storey `storey`: by `route` where it finds
// a walk, else over the walkable levels (a straight line where they find none), at eye height.
void walkTo(std::vector<glm::dvec3>& path, const Storeys& found, glm::dvec3 to, double eyeHeight,
            const FloorRoute& route, int storey) {
    const glm::dvec3 eye(0.0, eyeHeight, 0.0);
    std::vector<glm::dvec3> walk;
    if (route) walk = route(storey, path.back() - eye, to);
    if (walk.empty() && found.walk) walk = found.walk->route(path.back() - eye, to);
    for (const glm::dvec3& p : walk) append(path, p + eye);
    append(path, to + eye);
}

// The stair from storey `from` to the next whose every point (and every metre between) puts
// the eye in a cell; null when none does.
const Stair* stairBetween(const Storeys& found, int from, const std::vector<scenes::Cell>& cells, double eyeHeight) {
    for (const Stair& s : found.stairs) {
        if (s.from != from) continue;
        bool held = true;
        for (std::size_t k = 0; held && k + 1 < s.path.size(); ++k) {
            const int steps = std::max(1, static_cast<int>(std::ceil(glm::length(s.path[k + 1] - s.path[k]))));
            for (int t = 0; held && t <= steps; ++t) {
                const glm::dvec3 p = glm::mix(s.path[k], s.path[k + 1], double(t) / steps);
                held = scenes::findCell(cells, p + glm::dvec3(0.0, eyeHeight, 0.0)) >= 0;
            }
        }
        if (held && !s.path.empty()) return &s;
    }
    return nullptr;
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
            Facet f{c.y, 0.5 * std::abs(n.y), {c.x, c.z}, n.y > 0.0, {lo.x, lo.z}, {hi.x, hi.z}};
            for (int k = 0; k < 3; ++k) f.corners[k] = {p[k].x, p[k].z};
            f.slope = {-n.x / n.y, -n.z / n.y};  // the plane n . (q - c) = 0 solved for y
            facets.push_back(f);
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
    if (out.storeys.empty()) return {{{bottomY, topY, 0.0}}, {}, nullptr};
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
    if (out.storeys.size() < 2) return out;
    out.walk = std::make_shared<WalkGrid>(facets, out.storeys.front().floorY - 0.5, topY);
    for (std::size_t i = 0; i + 1 < out.storeys.size(); ++i) addStair(out, static_cast<int>(i));
    return out;
}

Storeys findStoreys(const scenes::Scene& scene, const StoreyOptions& options) {
    const scenes::Bounds b = scene.bounds();
    if (b.empty()) return {{{0.0, 0.0, 0.0}}, {}, nullptr};
    return findStoreys(horizontalFacets(scene, options), b.min.y, b.max.y, options);
}

scenes::SceneDescription stackStoreys(const std::vector<scenes::SceneDescription>& perStorey, const Storeys& found,
                                      double eyeHeight, const FloorRoute& route) {
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
            const Stair* stair = stairBetween(found, static_cast<int>(i) - 1, out.cells, eyeHeight);
            if (stair) {
                const int below = static_cast<int>(i) - 1;
                walkTo(out.walkPath, found, stair->path.front(), eyeHeight, route, below);
                for (const glm::dvec3& p : stair->path) append(out.walkPath, p + glm::dvec3(0.0, eyeHeight, 0.0));
                walkTo(out.walkPath, found, path.front() - glm::dvec3(0.0, eyeHeight, 0.0), eyeHeight, route,
                       below + 1);
            } else {
                out.walkBreaks.push_back(static_cast<int>(out.walkPath.size()));  // no frame between the storeys
            }
        }
        for (const glm::dvec3& p : path) append(out.walkPath, p);
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
