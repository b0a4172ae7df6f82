#include "walls/frame_select.h"

#include "scenes/region.h"
#include "walls/polygon2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::walls {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Distance from x to the interval [lo, hi] (0 inside).
double distanceTo(double x, glm::dvec2 range) { return std::max({range.x - x, x - range.y, 0.0}); }

double tent(double distance, double width) {
    if (width <= 0.0) return distance <= 0.0 ? 1.0 : 0.0;
    return std::clamp(1.0 - distance / width, 0.0, 1.0);
}

}  // namespace

FrameSelector::FrameSelector(const Plan& plan, const VisibilityTable& table,
                             const scenes::SceneDescription& description)
    : _plan(plan), _table(table), _description(description), _zones(plan) {
    for (const WallSide& side : plan.sides) _sides.push_back(buildSide(side));
    for (const BeyondSide& b : plan.beyond) _beyond.push_back(buildSide(b.side));
}

FrameSelector::SideCores FrameSelector::buildSide(const WallSide& side) const {
    // Cores stop half a blend width before every interior border (the strips are centred on the
    // borders); the first row after a geometry zone starts its core a whole blend width after
    // dG (the strip [dG, dG + b] blends to geometry); outer edges are open.
    SideCores sc{side.origin, side.along, side.inward, {}};
    const double half = 0.5 * _plan.options.blendWidth;
    if (side.hasGeometry) sc.cores.push_back({-1, {-kInf, kInf}, {-kInf, side.geometryDistance}});
    for (std::size_t r = 0; r < side.rows.size(); ++r) {
        const PlannedRow& row = side.rows[r];
        const double dLo = r > 0 ? row.near + half : side.hasGeometry ? row.near + 2 * half : -kInf;
        const double dHi = r + 1 < side.rows.size() ? row.far - half : kInf;
        for (std::size_t k = 0; k < row.textures.size(); ++k) {
            const double sLo = k > 0 ? row.cuts[k - 1] + half : -kInf;
            const double sHi = k < row.cuts.size() ? row.cuts[k] - half : kInf;
            sc.cores.push_back({row.textures[k], {sLo, sHi}, {dLo, dHi}});
        }
    }
    return sc;
}

WallBlend FrameSelector::blendAt(int sideIndex, glm::dvec2 floorPoint) const {
    const WallSide& side = _plan.sides[sideIndex];
    WallBlend out = blend(side, _sides[sideIndex], floorPoint);
    out.zone = _zones.find(side.cell, side.wall, floorPoint);
    return out;
}

WallBlend FrameSelector::blend(const WallSide& side, const SideCores& sc, glm::dvec2 floorPoint) const {
    const glm::dvec2 p(glm::dot(floorPoint - sc.origin, sc.along), glm::dot(floorPoint - sc.origin, sc.inward));
    const double b = _plan.options.blendWidth;
    WallBlend out{side.wall, side.side, -1, {}, 0.0};
    double total = 0.0;
    for (const Core& c : sc.cores) {
        const double w = tent(distanceTo(p.y, c.d), b) * (c.texture < 0 ? 1.0 : tent(distanceTo(p.x, c.s), b));
        if (w <= 0.0) continue;
        total += w;
        if (c.texture < 0)
            out.geometryWeight += w;
        else
            out.textures.emplace_back(c.texture, w);
    }
    if (total <= 0.0) {  // outside every core's reach (the eye left the cell): geometry
        out.textures.clear();
        out.geometryWeight = 1.0;
        return out;
    }
    for (auto& [id, w] : out.textures) w /= total;
    out.geometryWeight /= total;
    std::sort(out.textures.begin(), out.textures.end());
    return out;
}

FrameSelection FrameSelector::select(glm::dvec3 eye) const {
    FrameSelection f;
    f.cell = scenes::findCell(_description.cells, eye);
    if (f.cell < 0) {
        for (int c = 0; c < int(_description.cells.size()); ++c) f.geometryCells.push_back(c);
        return f;
    }
    f.geometryCells.push_back(f.cell);
    for (int c = 0; c < _table.cellCount; ++c)
        if (c != f.cell && _table.at(f.cell, c) == CellVisibility::Geometry) f.geometryCells.push_back(c);
    for (int i = 0; i < int(_plan.sides.size()); ++i) {
        if (_plan.sides[i].cell != f.cell) continue;
        WallBlend w = blendAt(i, {eye.x, eye.z});
        if (w.geometryWeight > 0.0) {
            const auto& cells = _plan.walls[w.wall].cells;
            f.geometryCells.push_back(cells[0] == f.cell ? cells[1] : cells[0]);
        }
        f.walls.push_back(std::move(w));
    }
    addBeyond(eye, f);
    std::sort(f.geometryCells.begin(), f.geometryCells.end());
    f.geometryCells.erase(std::unique(f.geometryCells.begin(), f.geometryCells.end()), f.geometryCells.end());
    return f;
}

void FrameSelector::addBeyond(glm::dvec3 eye, FrameSelection& f) const {
    const glm::dvec2 p(eye.x, eye.z);
    // The walls through which a neighbour is drawn as geometry (geometry weight > 0), and the
    // beyond sides that draw their cell behind as geometry (the second level's parents; they
    // precede their children in Plan::beyond).
    std::vector<int> vias, parents, done, added;
    for (const WallBlend& w : f.walls)
        if (w.geometryWeight > 0.0) vias.push_back(w.wall);
    auto has = [](const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); };
    for (int i = 0; i < int(_plan.beyond.size()); ++i) {
        const BeyondSide& b = _plan.beyond[i];
        if (b.eyeCell != f.cell) continue;
        const bool active = b.parent >= 0   ? has(parents, b.parent)
                            : b.viaWall < 0 ? _table.at(f.cell, b.side.cell) == CellVisibility::Geometry
                                            : has(vias, b.viaWall);
        const int behind = _plan.walls[b.side.wall].cells[1 - b.side.side];
        if (!active || has(f.geometryCells, behind) || has(added, behind) || has(done, b.side.wall)) continue;
        // Facing: the eye is on the neighbour's side of the wall's plane.
        if (glm::dot(p - b.side.origin, b.side.inward) <= 0.0) continue;
        // Outside the eye region nothing is proven: geometry (the planner's regions cover every
        // eye that draws the neighbour, so this is a guard, not a path).
        WallBlend w = containsConvex(b.eyeRegion, p) ? blend(b.side, _beyond[i], p)
                                                     : WallBlend{b.side.wall, b.side.side, -1, {}, 1.0};
        if (w.geometryWeight > 0.0) {
            parents.push_back(i);
            if (behind >= 0) added.push_back(behind);
        }
        done.push_back(b.side.wall);
        f.beyond.push_back(std::move(w));
    }
    f.geometryCells.insert(f.geometryCells.end(), added.begin(), added.end());
}

}  // namespace cavewall::walls
