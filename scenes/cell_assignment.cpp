#include "scenes/cell_assignment.h"

#include "scenes/region.h"
#include "scenes/storey_voids.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::scenes {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The (x, z) rectangle [lo, hi] as a counter-clockwise region (seen from +Y).
std::vector<glm::dvec2> rectangle(glm::dvec2 lo, glm::dvec2 hi) {
    return {{lo.x, hi.y}, {hi.x, hi.y}, {hi.x, lo.y}, {lo.x, lo.y}};
}

struct CellSpan {
    glm::dvec2 lo{kInfinity}, hi{-kInfinity};  // the region's (x, z) bounds
    double bottom = 0.0, top = kInfinity;      // heights an object must meet
    double aboveTop = kInfinity;               // the storey above's top: objects seen over a void start below it
};

// The lowest floor of the cells over `region` in plan at least kMinStoreyHeight above `floorY`.
double topOver(const std::vector<Cell>& cells, const std::vector<glm::dvec2>& region, double floorY) {
    double top = kInfinity;
    for (const Cell& d : cells)
        if (d.floorY >= floorY + kMinStoreyHeight && d.floorY < top && overlapArea(region, d.region) > 0.0)
            top = d.floorY;
    return top;
}

std::vector<CellSpan> cellSpans(const std::vector<Cell>& cells) {
    std::vector<CellSpan> spans(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const PlanRect bounds = regionBounds(cells[c].region);
        spans[c].lo = bounds.lo;
        spans[c].hi = bounds.hi;
        spans[c].bottom = cells[c].floorY - kBelowFloor;
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
        spans[c].top = topOver(cells, cells[c].region, cells[c].floorY);
        if (std::isfinite(spans[c].top)) spans[c].aboveTop = topOver(cells, cells[c].region, spans[c].top);
    }
    return spans;
}

// Whether `box`, above cell `s`'s top and below the storey above's top, is seen from the cell
// over its void: its plan rectangle grown by `reach` and by its height over the top (a 45°
// sight line through the void's edge), at most kVoidSightMetres, meets the void.
bool seenOverVoid(const CellSpan& s, const PlanMask& hole, const Bounds& box, double reach) {
    if (hole.empty() || box.min.y < s.top - kAboveTop || box.min.y >= s.aboveTop - kAboveTop) return false;
    const double grow = reach + std::clamp(box.max.y - s.top, 0.0, kVoidSightMetres);
    return hole.count(glm::dvec2(box.min.x, box.min.z) - grow, glm::dvec2(box.max.x, box.max.z) + grow) > 0;
}

bool meetsHeight(const CellSpan& s, const Bounds& box) {
    return box.max.y >= s.bottom && box.min.y < s.top - kAboveTop;
}

// Whether `box`, in lower cell `s`'s storey, is seen from the storey above through the cell's
// void: its plan rectangle grown by `reach` and by its depth under the cell's top (a 45° sight
// line down through the void's edge reaches that far under the slab), at most kVoidSightMetres,
// meets the void within the (x, z) rectangle [near.lo, near.hi] (where the sight line crosses
// the upper floor's level: near the viewer's cell).
bool seenThroughVoid(const CellSpan& s, const PlanMask& hole, const Bounds& box, double reach, const CellSpan& near) {
    if (hole.empty() || !meetsHeight(s, box)) return false;
    const double grow = reach + std::clamp(s.top - box.min.y, 0.0, kVoidSightMetres);
    const glm::dvec2 lo = glm::max(glm::dvec2(box.min.x, box.min.z) - grow, near.lo - kDownReachMetres);
    const glm::dvec2 hi = glm::min(glm::dvec2(box.max.x, box.max.z) + grow, near.hi + kDownReachMetres);
    return hole.count(lo, hi) > 0;
}

// Per cell, the lower cells whose void opens to the cell's storey (the lower cell's top lies
// within the slab's span of the cell's floor) and lies within kDownReachMetres of the cell's
// region's plan bounds.
std::vector<std::vector<int>> voidsBelow(const std::vector<Cell>& cells, const std::vector<CellSpan>& spans,
                                         const std::vector<PlanMask>& voids) {
    std::vector<std::vector<int>> out(cells.size());
    for (std::size_t u = 0; u < cells.size(); ++u)
        for (std::size_t l = 0; l < voids.size() && l < spans.size(); ++l) {
            const double top = spans[l].top, floorY = cells[u].floorY;
            if (l == u || voids[l].empty() || !(floorY >= top - kSlabBelow && floorY <= top + kSlabAbove)) continue;
            if (voids[l].count(spans[u].lo - kDownReachMetres, spans[u].hi + kDownReachMetres) > 0)
                out[u].push_back(static_cast<int>(l));
        }
    return out;
}

// Whether `box` is seen from cell `c` down through a void of the storey below.
bool seenFromAbove(const std::vector<CellSpan>& spans, const std::vector<PlanMask>& voids, std::size_t c,
                   const std::vector<int>& below, const Bounds& box, double reach) {
    for (int l : below)
        if (seenThroughVoid(spans[l], voids[l], box, reach, spans[c])) return true;
    return false;
}

// The storeys' voids: per cell, its void toward the storey above, and the lower cells whose
// voids it looks down through.
struct Voids {
    std::vector<PlanMask> up;
    std::vector<std::vector<int>> below;
};

CellsOfBox boxCells(const std::vector<Cell>& cells, const std::vector<CellSpan>& spans, const Voids& voids,
                    const Bounds& box, double reach) {
    CellsOfBox out;
    if (box.empty()) return out;
    const glm::dvec2 lo = glm::dvec2(box.min.x, box.min.z) - reach, hi = glm::dvec2(box.max.x, box.max.z) + reach;
    const std::vector<glm::dvec2> footprint = rectangle(lo, hi);
    const glm::dvec2 centre(box.centre().x, box.centre().z);
    std::vector<int> overlapped, overVoid, underVoid;
    int holding = -1, largest = -1;
    double largestArea = 0.0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const CellSpan& s = spans[c];
        if (c < voids.up.size() && seenOverVoid(s, voids.up[c], box, reach)) {
            overVoid.push_back(static_cast<int>(c));
            continue;
        }
        const bool inPlan = !(hi.x <= s.lo.x || lo.x >= s.hi.x || hi.y <= s.lo.y || lo.y >= s.hi.y);
        const double area = meetsHeight(s, box) && inPlan ? overlapArea(footprint, cells[c].region) : 0.0;
        if (area <= 0.0) {
            if (c < voids.below.size() && seenFromAbove(spans, voids.up, c, voids.below[c], box, reach))
                underVoid.push_back(static_cast<int>(c));
            continue;
        }
        const int cell = static_cast<int>(c);
        overlapped.push_back(cell);
        if (holding < 0 && regionContains(cells[c].region, centre, 1e-6)) holding = cell;
        if (area > largestArea) {
            largestArea = area;
            largest = cell;
        }
    }
    if (overlapped.empty()) {
        const int c = findCell(cells, box.centre());
        if (c >= 0 && meetsHeight(spans[c], box)) out.cell = c;
    } else {
        out.cell = holding >= 0 ? holding : largest;
    }
    for (int c : overlapped)
        if (c != out.cell) out.moreCells.push_back(c);
    for (int c : overVoid)
        if (out.cell < 0)
            out.cell = c;
        else if (c != out.cell)
            out.moreCells.push_back(c);
    // A lower object in no cell stays drawn with every cell (-1): it is given no upper cell.
    for (int c : underVoid)
        if (out.cell >= 0 && c != out.cell) out.moreCells.push_back(c);
    std::sort(out.moreCells.begin(), out.moreCells.end());
    out.moreCells.erase(std::unique(out.moreCells.begin(), out.moreCells.end()), out.moreCells.end());
    return out;
}

}  // namespace

CellsOfBox cellsOfBox(const std::vector<Cell>& cells, const Bounds& box, double reach) {
    return boxCells(cells, cellSpans(cells), {}, box, reach);
}

void assignCells(Scene& scene, const std::vector<Cell>& cells, double reach) {
    const std::vector<CellSpan> spans = cellSpans(cells);
    std::vector<double> tops;
    std::vector<PlanRect> bounds;
    for (const CellSpan& s : spans) {
        tops.push_back(s.top);
        bounds.push_back({s.lo, s.hi});
    }
    Voids voids;
    voids.up = cellVoids(scene, cells, tops, bounds);
    voids.below = voidsBelow(cells, spans, voids.up);
    for (Object& o : scene.objects) {
        CellsOfBox c = boxCells(cells, spans, voids, o.worldBounds, reach);
        o.cell = c.cell;
        o.moreCells = std::move(c.moreCells);
    }
}

}  // namespace cavewall::scenes
