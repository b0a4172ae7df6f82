#include "walls/cell_openings.h"

#include "walls/visibility.h"

#include <limits>

namespace cavewall::walls {

namespace {

// How far an open boundary part reaches below and above its cell's floor, metres: far enough
// that the pyramid through it is the wedge through its floor segment.
constexpr double kOpeningReach = 1000.0;

// The opening over the floor segment [a, b] of `cell`'s boundary, reaching kOpeningReach below
// and above its floor, its normal into the cell.
display::ScreenQuad openingQuad(const scenes::Cell& cell, glm::dvec2 a, glm::dvec2 b) {
    glm::dvec2 inside(0.0);
    for (const glm::dvec2& p : cell.region) inside += p / static_cast<double>(cell.region.size());
    const glm::dvec2 along = b - a, into = inside - a;
    if (along.x * into.y - along.y * into.x < 0.0) std::swap(a, b);  // the normal (-dz, dx) into the cell
    const double y = cell.floorY;
    return {{a.x, y - kOpeningReach, a.y}, {b.x, y - kOpeningReach, b.y}, {a.x, y + kOpeningReach, a.y}};
}

// The floor box (x, z) of `cell`, shrunk by a centimetre so that a box only touching the
// cell's edge does not overlap it.
std::array<glm::dvec2, 2> floorBox(const scenes::Cell& cell) {
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const glm::dvec2& p : cell.region) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return {lo + 0.01, hi - 0.01};
}

// Whether `b` overlaps the column over the floor box `column` (x, z), at any height.
bool overlaps(const scenes::Bounds& b, const std::array<glm::dvec2, 2>& column) {
    return b.min.x < column[1].x && b.max.x > column[0].x && b.min.z < column[1].y && b.max.z > column[0].y;
}

}  // namespace

CellOpenings::CellOpenings(const Plan& plan, const scenes::SceneDescription& description)
    : _cellCount(static_cast<int>(description.cells.size())), _openings(description.cells.size()) {
    for (int w = 0; w < static_cast<int>(plan.walls.size()); ++w)
        for (int s = 0; s < 2; ++s) {
            _quads.push_back(quadSeenFrom(plan.walls[w].quad, s));
            const int cell = plan.walls[w].cells[s];
            if (cell >= 0 && cell < _cellCount) _openings[cell].push_back(2 * w + s);
        }
    for (int e = 0; e < _cellCount; ++e) {
        _columns.push_back(floorBox(description.cells[e]));
        for (const auto& [a, b] : openBoundary(description, e)) {
            _openings[e].push_back(static_cast<int>(_quads.size()));
            _quads.push_back(openingQuad(description.cells[e], a, b));
        }
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
    if (openings(eyeCell).empty()) return;
    out.portals = _quads;
    out.sets.emplace_back();
    for (int o : openings(eyeCell)) {
        out.sets[0].push_back(static_cast<int>(out.chains.size()));
        out.chains.push_back({o});
    }
    const std::array<glm::dvec2, 2>& column = _columns[static_cast<std::size_t>(eyeCell)];
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
