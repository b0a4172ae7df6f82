#include "walls/visibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>

namespace cavewall::walls {
namespace {

constexpr double kOnLine = 1e-6;      // metres: an edge lies on another's line
constexpr double kMinOpening = 1e-3;  // metres of open boundary that count as a connection
// Cells whose floors differ by more than this are on different storeys: they share no open
// boundary, and a wall covers a cell's edge only when it reaches into [floorY, floorY + this].
constexpr double kStoreyStep = 1.0;

struct Segment {
    glm::dvec2 a, b;
    double bottom = 0.0, top = 0.0;  // the wall's y range
};

Segment footprint(glm::dvec3 lowerLeft, glm::dvec3 lowerRight, glm::dvec3 upperLeft) {
    return {{lowerLeft.x, lowerLeft.z},
            {lowerRight.x, lowerRight.z},
            std::min(lowerLeft.y, upperLeft.y),
            std::max(lowerLeft.y, upperLeft.y)};
}

double cross2(glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; }

// The interval of `s` along `e` (parameters in metres from e.a) when s lies on e's line.
bool onLine(const Segment& e, const Segment& s, glm::dvec2& interval) {
    const glm::dvec2 dir = e.b - e.a;
    const double len = glm::length(dir);
    if (len == 0) return false;
    const glm::dvec2 u = dir / len;
    if (std::abs(cross2(u, s.a - e.a)) > kOnLine || std::abs(cross2(u, s.b - e.a)) > kOnLine) return false;
    const double t0 = glm::dot(s.a - e.a, u), t1 = glm::dot(s.b - e.a, u);
    interval = {std::max(0.0, std::min(t0, t1)), std::min(len, std::max(t0, t1))};
    return interval.y > interval.x;
}

std::vector<Segment> allFootprints(const scenes::SceneDescription& d) {
    std::vector<Segment> out;
    for (const auto& w : d.walls) out.push_back(footprint(w.lowerLeft, w.lowerRight, w.upperLeft));
    for (const auto& w : d.realWalls) out.push_back(footprint(w.lowerLeft, w.lowerRight, w.upperLeft));
    return out;
}

// The parts of `shared` outside the union of `covers` (intervals on one line), in order.
std::vector<glm::dvec2> uncoveredParts(glm::dvec2 shared, std::vector<glm::dvec2> covers) {
    std::sort(covers.begin(), covers.end(), [](glm::dvec2 x, glm::dvec2 y) { return x.x < y.x; });
    std::vector<glm::dvec2> out;
    double at = shared.x;
    for (const glm::dvec2& c : covers) {
        if (c.x > at) out.push_back({at, std::min(c.x, shared.y)});
        at = std::max(at, c.y);
        if (at >= shared.y) break;
    }
    if (shared.y > at) out.push_back({at, shared.y});
    return out;
}

// The intervals along `e` of the walls that cover it for a cell whose floor is at floorY.
std::vector<glm::dvec2> coversOf(const Segment& e, const std::vector<Segment>& walls, double floorY) {
    std::vector<glm::dvec2> covers;
    for (const Segment& w : walls) {
        glm::dvec2 c;
        if (w.top > floorY && w.bottom < floorY + kStoreyStep && onLine(e, w, c)) covers.push_back(c);
    }
    return covers;
}

// Length of `shared` minus the union of `covers`.
double uncovered(glm::dvec2 shared, std::vector<glm::dvec2> covers) {
    double open = 0.0;
    for (const glm::dvec2& part : uncoveredParts(shared, std::move(covers))) open += part.y - part.x;
    return open;
}

double signedDistance(glm::dvec3 p, const display::ScreenQuad& wall, const display::ScreenBasis& b, int side) {
    return glm::dot(p - wall.lowerLeft, b.normal) * (side == 0 ? 1.0 : -1.0);
}

bool partlyBehind(const scenes::Cell& cell, const scenes::VirtualWall& w, int side) {
    const display::ScreenQuad q{w.lowerLeft, w.lowerRight, w.upperLeft};
    const display::ScreenBasis b = display::screenBasis(q);
    for (const glm::dvec2& p : cell.region)
        if (signedDistance({p.x, w.lowerLeft.y, p.y}, q, b, side) < -1e-9) return true;
    return false;
}

// Convex hull (Andrew's monotone chain) of a few points.
Polygon2 hull(std::vector<glm::dvec2> pts) {
    std::sort(pts.begin(), pts.end(),
              [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (pts.size() < 3) return pts;
    Polygon2 h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross2(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross2(h[k - 1] - h[k - 2], pts[i - 1] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i - 1];
    }
    h.resize(k - 1);
    return h;
}

// Per cell: does the table show it from `viewer` through `wall`? (All false for a viewer
// outside the table.)
std::vector<bool> cellsShownThrough(const VisibilityTable& table, int viewer, int wall) {
    std::vector<bool> shown(std::size_t(table.cellCount), false);
    if (viewer < 0 || viewer >= table.cellCount) return shown;
    for (int c = 0; c < table.cellCount; ++c) {
        const auto& through = table.throughWalls(viewer, c);
        shown[c] = std::find(through.begin(), through.end(), wall) != through.end();
    }
    return shown;
}

// The axis-aligned box of a wall rectangle, grown by a micrometre (plus rounding at the
// rectangle's size) so that a box classify() finds crossing the rectangle always overlaps it.
scenes::Bounds rectangleBox(const display::ScreenQuad& q) {
    scenes::Bounds b;
    for (const glm::dvec3& p : {q.lowerLeft, q.lowerRight, q.upperLeft, q.lowerRight + (q.upperLeft - q.lowerLeft)})
        b.add(p);
    const double margin =
        1e-6 + 1e-9 * glm::length(b.size()) + 1e-12 * glm::length(glm::max(glm::abs(b.min), glm::abs(b.max)));
    b.min -= glm::dvec3(margin);
    b.max += glm::dvec3(margin);
    return b;
}

bool overlaps(const scenes::Bounds& a, const scenes::Bounds& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
           b.min.z <= a.max.z;
}

}  // namespace

const char* toString(CellVisibility v) {
    switch (v) {
        case CellVisibility::Hidden: return "hidden";
        case CellVisibility::Geometry: return "geometry";
        case CellVisibility::Texture: return "texture";
    }
    return "?";
}

const char* toString(Placement p) {
    switch (p) {
        case Placement::Behind: return "behind";
        case Placement::Intersecting: return "intersecting";
        case Placement::InFront: return "in front";
        case Placement::Beside: return "beside";
    }
    return "?";
}

namespace {

double openLength(const scenes::SceneDescription& d, const std::vector<Segment>& walls, int a, int b) {
    const auto& ra = d.cells[a].region;
    const auto& rb = d.cells[b].region;
    const double floorY = d.cells[a].floorY;
    if (std::abs(d.cells[b].floorY - floorY) > kStoreyStep) return 0.0;
    double open = 0;
    for (std::size_t i = 0; i < ra.size(); ++i) {
        const Segment e{ra[i], ra[(i + 1) % ra.size()]};
        for (std::size_t j = 0; j < rb.size(); ++j) {
            glm::dvec2 shared;
            if (!onLine(e, {rb[j], rb[(j + 1) % rb.size()]}, shared)) continue;
            open += uncovered(shared, coversOf(e, walls, floorY));
        }
    }
    return open;
}

// The floor box (x, z) of every cell, grown by kNearby.
constexpr double kNearby = 1e-3;  // metres; edges on one line (onLine) are within kOnLine
std::vector<std::array<glm::dvec2, 2>> cellBoxes(const scenes::SceneDescription& d) {
    std::vector<std::array<glm::dvec2, 2>> boxes;
    for (const scenes::Cell& c : d.cells) {
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
        for (const glm::dvec2& p : c.region) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        boxes.push_back({lo - kNearby, hi + kNearby});
    }
    return boxes;
}

}  // namespace

DirectGroups directGroups(const VisibilityTable& t) {
    DirectGroups g;
    for (int a = 0; a < t.cellCount; ++a) {
        int seen = 0;
        for (int b = 0; b < t.cellCount; ++b) seen += b != a && t.at(a, b) == CellVisibility::Geometry ? 1 : 0;
        g.pairs += seen;
        if (seen > 0 && seen + 1 > g.largest) g.largest = seen + 1, g.largestCell = a;
    }
    g.pairs /= 2;
    return g;
}

std::string describeDirectGroups(const VisibilityTable& table, const scenes::SceneDescription& d) {
    const DirectGroups g = directGroups(table);
    if (g.pairs == 0) return "";
    return "pairs of cells that see each other directly (joined by edges no wall, portal or virtual wall covers): " +
           std::to_string(g.pairs) + "; the largest group, " + std::to_string(g.largest) + " cells with " +
           d.cells[static_cast<std::size_t>(g.largestCell)].name + ", is drawn whole from any of them";
}

double openBoundaryLength(const scenes::SceneDescription& d, int a, int b) {
    return openLength(d, allFootprints(d), a, b);
}

std::vector<std::array<glm::dvec2, 2>> openBoundary(const scenes::SceneDescription& d, int a) {
    const std::vector<Segment> walls = allFootprints(d);
    const auto& region = d.cells[a].region;
    std::vector<std::array<glm::dvec2, 2>> out;
    for (std::size_t i = 0; i < region.size(); ++i) {
        const Segment e{region[i], region[(i + 1) % region.size()]};
        const double length = glm::length(e.b - e.a);
        if (!(length > kMinOpening)) continue;
        const glm::dvec2 u = (e.b - e.a) / length;
        for (const glm::dvec2& part : uncoveredParts({0.0, length}, coversOf(e, walls, d.cells[a].floorY)))
            if (part.y - part.x > kMinOpening) out.push_back({e.a + part.x * u, e.a + part.y * u});
    }
    return out;
}

VisibilityTable computeVisibility(const scenes::SceneDescription& d) {
    const int n = int(d.cells.size());
    VisibilityTable t;
    t.cellCount = n;
    t.entries.assign(std::size_t(n) * n, CellVisibility::Hidden);
    t.walls.assign(std::size_t(n) * n, {});
    std::vector<std::vector<int>> open(n), passable(n);
    // Measuring a pair scans every wall's footprint and the pairs grow with the square of the
    // cells; cells whose floor boxes are apart share no edge, so only nearby pairs are measured.
    const std::vector<Segment> footprints = allFootprints(d);
    const auto boxes = cellBoxes(d);
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) {
            const auto &ba = boxes[a], &bb = boxes[b];
            if (ba[0].x > bb[1].x || bb[0].x > ba[1].x || ba[0].y > bb[1].y || bb[0].y > ba[1].y) continue;
            if (openLength(d, footprints, a, b) > kMinOpening) open[a].push_back(b), open[b].push_back(a);
        }
    for (int a = 0; a < n; ++a) passable[a] = open[a];
    for (const auto& w : d.walls)
        if (w.cells[0] >= 0 && w.cells[1] >= 0)
            passable[w.cells[0]].push_back(w.cells[1]), passable[w.cells[1]].push_back(w.cells[0]);
    auto flood = [&](int start, const std::vector<std::vector<int>>& links, const std::vector<bool>& blocked) {
        std::vector<bool> seen(n, false);
        std::deque<int> queue{start};
        seen[start] = true;
        while (!queue.empty()) {
            const int c = queue.front();
            queue.pop_front();
            for (int next : links[c])
                if (!seen[next] && !blocked[next]) seen[next] = true, queue.push_back(next);
        }
        return seen;
    };
    for (int a = 0; a < n; ++a) {
        const std::vector<bool> group = flood(a, open, std::vector<bool>(n, false));
        for (int b = 0; b < n; ++b)
            if (group[b]) t.entries[std::size_t(a) * n + b] = CellVisibility::Geometry;
        for (int w = 0; w < int(d.walls.size()); ++w)
            for (int side = 0; side < 2; ++side) {
                const int here = d.walls[w].cells[side], there = d.walls[w].cells[1 - side];
                if (here < 0 || there < 0 || !group[here] || group[there]) continue;
                const std::vector<bool> behind = flood(there, passable, group);
                for (int b = 0; b < n; ++b) {
                    if (!behind[b] || !partlyBehind(d.cells[b], d.walls[w], side)) continue;
                    t.entries[std::size_t(a) * n + b] = CellVisibility::Texture;
                    t.walls[std::size_t(a) * n + b].push_back(w);
                }
            }
    }
    return t;
}

Placement classify(const scenes::Bounds& box, const display::ScreenQuad& wall, int side) {
    const display::ScreenBasis b = display::screenBasis(wall);
    glm::dvec3 corners[8];
    double dist[8], lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 8; ++i) {
        corners[i] = {i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z};
        dist[i] = signedDistance(corners[i], wall, b, side);
        lo = std::min(lo, dist[i]);
        hi = std::max(hi, dist[i]);
    }
    if (hi <= 0) return Placement::Behind;
    if (lo >= 0) return Placement::InFront;
    // The box's cross-section with the plane, in wall coordinates, against the rectangle.
    std::vector<glm::dvec2> section;
    auto toWall = [&](glm::dvec3 p) {
        return glm::dvec2(glm::dot(p - wall.lowerLeft, b.right), glm::dot(p - wall.lowerLeft, b.up));
    };
    for (int i = 0; i < 8; ++i) {
        if (dist[i] == 0) section.push_back(toWall(corners[i]));
        for (int axis = 1; axis <= 4; axis <<= 1) {
            const int j = i | axis;
            if (j == i || (dist[i] < 0) == (dist[j] < 0) || dist[i] == 0 || dist[j] == 0) continue;
            section.push_back(toWall(corners[i] + (corners[j] - corners[i]) * (dist[i] / (dist[i] - dist[j]))));
        }
    }
    const Polygon2 h = hull(section);
    const Polygon2 inside = clipBox(h, {0, 0}, {b.width, b.height});
    bool touches = !inside.empty();
    for (const glm::dvec2& p : h) touches = touches || (p.x >= 0 && p.x <= b.width && p.y >= 0 && p.y <= b.height);
    return touches ? Placement::Intersecting : Placement::Beside;
}

WallContents wallContents(const scenes::Scene& scene, const scenes::SceneDescription& d, const VisibilityTable& table,
                          int wall, int side) {
    WallContents out;
    const scenes::VirtualWall& w = d.walls[wall];
    const display::ScreenQuad q{w.lowerLeft, w.lowerRight, w.upperLeft};
    const display::ScreenBasis b = display::screenBasis(q);
    const int viewer = w.cells[side];
    const std::vector<bool> shownCells = cellsShownThrough(table, viewer, wall);
    const scenes::Bounds rect = rectangleBox(q);
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        const scenes::Object& o = scene.objects[i];
        if (o.role == scenes::Role::Structure || o.worldBounds.empty()) continue;
        // Classifying is the cost here (objects x wall sides); an object neither possibly shown
        // through this wall nor touching the rectangle's box is neither baked nor intersecting.
        const bool anyCell = o.cell < 0 || viewer < 0 || o.cell >= table.cellCount;
        const bool mayBake =
            anyCell || scenes::anyCellOf(o, [&](int c) { return c < table.cellCount && shownCells[c]; });
        if (!mayBake && !overlaps(o.worldBounds, rect)) continue;
        const Placement p = classify(o.worldBounds, q, side);
        if (p == Placement::Intersecting) out.intersecting.push_back(i);
        if (p != Placement::Behind) continue;
        const bool shown = o.cell < 0 || viewer < 0 || scenes::anyCellOf(o, [&](int c) {
                               if (c >= table.cellCount) return false;
                               const auto& through = table.throughWalls(viewer, c);
                               return std::find(through.begin(), through.end(), wall) != through.end();
                           });
        if (!shown) continue;
        out.baked.push_back(i);
        double nearest = std::numeric_limits<double>::infinity();
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner{c & 1 ? o.worldBounds.max.x : o.worldBounds.min.x,
                                    c & 2 ? o.worldBounds.max.y : o.worldBounds.min.y,
                                    c & 4 ? o.worldBounds.max.z : o.worldBounds.min.z};
            out.depthBehind = std::max(out.depthBehind, -signedDistance(corner, q, b, side));
            nearest = std::min(nearest, std::max(0.0, -signedDistance(corner, q, b, side)));
        }
        out.depthNear = out.baked.size() == 1 ? nearest : std::min(out.depthNear, nearest);
    }
    return out;
}

glm::dvec2 depthSpanOf(const WallContents* front, const WallContents* back) {
    glm::dvec2 span(std::numeric_limits<double>::infinity(), 0.0);
    for (const WallContents* c : {front, back})
        if (c && !c->baked.empty()) span = {std::min(span.x, c->depthNear), std::max(span.y, c->depthBehind)};
    return span.x > span.y ? glm::dvec2(0.0) : span;
}

std::vector<glm::dvec2> wallDepthSpans(const scenes::Scene& scene, const scenes::SceneDescription& d,
                                       const VisibilityTable& table) {
    std::vector<glm::dvec2> spans;
    for (int w = 0; w < int(d.walls.size()); ++w) {
        WallContents sides[2];
        for (int side = 0; side < 2; ++side)
            if (d.walls[w].cells[side] >= 0) sides[side] = wallContents(scene, d, table, w, side);
        spans.push_back(depthSpanOf(&sides[0], &sides[1]));
    }
    return spans;
}

void assignDepthBehind(Plan& plan, const scenes::Scene& scene, const scenes::SceneDescription& d,
                       const VisibilityTable& table) {
    const std::vector<glm::dvec2> spans = wallDepthSpans(scene, d, table);
    for (PlannedWall& w : plan.walls) {
        w.depthNear = spans[w.id].x;
        w.depthBehind = spans[w.id].y;
    }
}

}  // namespace cavewall::walls
