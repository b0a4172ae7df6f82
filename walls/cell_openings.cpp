#include "walls/cell_openings.h"

#include "walls/visibility.h"

#include <limits>

namespace cavewall::walls {

namespace {

// How far an open boundary part reaches below and above its cell's floor, metres: far enough
// that the pyramid through it is the wedge through its floor segment.
constexpr double kOpeningReach = 1000.0;

// How far past a cell's floor box its own walls reach, metres: a wall's thickness and what is
// mounted on it. A window pane in the wall or a switch on its face lies within this band.
constexpr double kWallBand = 0.5;

// How far a portal may lie from the doorway it stands for, metres (render::PortalSets::slack):
// cell boundaries are snapped and run through the middle of walls, doorways are the doors'
// boxes, so the opening a line of sight passes may lie half a wall's thickness off.
constexpr double kPortalSlack = 0.3;

using Box2 = std::array<glm::dvec2, 2>;  // (x, z) from, to

// The vertical rectangle over the floor segment [a, b] (x, z) from height y0 to y1, its normal
// (-dz, dx) facing `inside` (x, z).
display::ScreenQuad verticalQuad(glm::dvec2 a, glm::dvec2 b, double y0, double y1, glm::dvec2 inside) {
    const glm::dvec2 along = b - a, into = inside - a;
    if (along.x * into.y - along.y * into.x < 0.0) std::swap(a, b);
    return {{a.x, y0, a.y}, {b.x, y0, b.y}, {a.x, y1, a.y}};
}

// The mean of `cell`'s region corners (x, z): inside it for the convex regions cells have.
glm::dvec2 regionCentre(const scenes::Cell& cell) {
    glm::dvec2 centre(0.0);
    for (const glm::dvec2& p : cell.region) centre += p / static_cast<double>(cell.region.size());
    return centre;
}

// The floor box (x, z) of `cell`, grown by `margin` (negative: shrunk).
Box2 floorBox(const scenes::Cell& cell, double margin) {
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const glm::dvec2& p : cell.region) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {lo - margin, hi + margin};
}

// Whether `b` overlaps the column over the box `column` (x, z), at any height.
bool overlaps(const scenes::Bounds& b, const Box2& column) {
    return b.min.x < column[1].x && b.max.x > column[0].x && b.min.z < column[1].y && b.max.z > column[0].y;
}

// Whether `b` lies within the box `inner` (x, z), at any height.
bool within(const scenes::Bounds& b, const Box2& inner) {
    return b.min.x >= inner[0].x && b.max.x <= inner[1].x && b.min.z >= inner[0].y && b.max.z <= inner[1].y;
}

// Whether `o` is a pane of glass: its material blends, its box is thin across (at most 10 cm)
// and at least 20 cm wide and high.
bool isPane(const scenes::Scene& scene, const scenes::Object& o) {
    const scenes::Bounds& b = o.worldBounds;
    if (b.empty()) return false;
    const glm::dvec3 size = b.max - b.min;
    if (std::min(size.x, size.z) > 0.1 || std::max(size.x, size.z) < 0.2 || size.y < 0.2) return false;
    return scenes::blends(scene, o);
}

// Whether a pane with the box `b` is in the walls of the cell whose floor box grown by
// kWallBand is `band` and shrunk by it `inner`: it reaches into the band and not only into the
// inner box (not a pane standing in the room).
bool inWalls(const scenes::Bounds& b, const Box2& inner, const Box2& band) {
    return overlaps(b, band) && !within(b, inner);
}

// A pane of glass in a cell's walls as an opening: the vertical rectangle through the middle of
// its box across its thinner horizontal side, grown by that side's thickness and 2 cm all
// round, facing `inside` (x, z). A line of sight through the pane crosses it there.
display::ScreenQuad paneQuad(const scenes::Bounds& b, glm::dvec2 inside) {
    const glm::dvec3 size = b.max - b.min, mid = b.centre();
    const double grow = std::min(size.x, size.z) + 0.02;
    const bool thinX = size.x < size.z;
    const glm::dvec2 from = thinX ? glm::dvec2(mid.x, b.min.z - grow) : glm::dvec2(b.min.x - grow, mid.z);
    const glm::dvec2 to = thinX ? glm::dvec2(mid.x, b.max.z + grow) : glm::dvec2(b.max.x + grow, mid.z);
    return verticalQuad(from, to, b.min.y - grow, b.max.y + grow, inside);
}

}  // namespace

CellOpenings::CellOpenings(const Plan& plan, const scenes::SceneDescription& description, const scenes::Scene& scene)
    : _cellCount(static_cast<int>(description.cells.size())), _openings(description.cells.size()) {
    for (int w = 0; w < static_cast<int>(plan.walls.size()); ++w)
        for (int s = 0; s < 2; ++s) {
            _quads.push_back(quadSeenFrom(plan.walls[w].quad, s));
            const int cell = plan.walls[w].cells[s];
            if (cell >= 0 && cell < _cellCount) _openings[cell].push_back(2 * w + s);
        }
    auto add = [&](int cell, const display::ScreenQuad& q) {
        _openings[cell].push_back(static_cast<int>(_quads.size()));
        _quads.push_back(q);
    };
    std::vector<const scenes::Object*> panes;  // windows of some cell, in object order
    for (const scenes::Object& o : scene.objects)
        if (isPane(scene, o)) panes.push_back(&o);
    for (int e = 0; e < _cellCount; ++e) {
        const scenes::Cell& cell = description.cells[e];
        const glm::dvec2 centre = regionCentre(cell);
        _columns.push_back(floorBox(cell, kWallBand));
        for (const auto& [a, b] : openBoundary(description, e))
            add(e, verticalQuad(a, b, cell.floorY - kOpeningReach, cell.floorY + kOpeningReach, centre));
        const Box2 inner = floorBox(cell, -kWallBand);
        for (const scenes::Object* o : panes)
            if (inWalls(o->worldBounds, inner, _columns.back())) add(e, paneQuad(o->worldBounds, centre));
    }
}

const std::vector<int>& CellOpenings::openings(int cell) const {
    static const std::vector<int> none;
    return cell >= 0 && cell < _cellCount ? _openings[cell] : none;
}

void CellOpenings::frameSets(int eyeCell, const std::vector<bool>& drawn, const scenes::Scene& scene,
                             render::PortalSets& out) const {
    out.portals.clear();
    out.chains.clear();
    out.sets.clear();
    out.objectSet.assign(scene.objects.size(), -1);
    const std::vector<int>& openings = this->openings(eyeCell);
    if (openings.empty()) return;
    out.slack = kPortalSlack;
    out.sets.emplace_back();
    for (int o : openings) {
        out.sets[0].push_back(static_cast<int>(out.chains.size()));
        out.chains.push_back({static_cast<int>(out.portals.size())});
        out.portals.push_back(_quads[static_cast<std::size_t>(o)]);
    }
    const Box2& column = _columns[static_cast<std::size_t>(eyeCell)];
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const scenes::Object& o = scene.objects[i];
        if (o.role == scenes::Role::Structure || overlaps(o.worldBounds, column)) continue;
        bool tested = false, free = false;
        scenes::anyCellOf(o, [&](int c) {
            if (c < 0 || c >= _cellCount || c >= static_cast<int>(drawn.size()) || !drawn[c]) return false;
            free = c == eyeCell;
            tested = true;
            return free;
        });
        if (tested && !free) out.objectSet[i] = 0;
    }
}

}  // namespace cavewall::walls
