#include "walls/portal_chains.h"

#include "walls/visibility.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

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

void addChain(std::vector<std::vector<int>>& chains, std::vector<int> chain) {
    if (std::find(chains.begin(), chains.end(), chain) == chains.end()) chains.push_back(std::move(chain));
}

}  // namespace

PortalChains::PortalChains(const Plan& plan, const VisibilityTable& table, const scenes::SceneDescription& description)
    : _cellCount(table.cellCount) {
    _chains.resize(static_cast<std::size_t>(_cellCount) * _cellCount);
    for (const PlannedWall& w : plan.walls) {
        _quads.push_back(quadSeenFrom(w.quad, 0));
        _quads.push_back(quadSeenFrom(w.quad, 1));
    }
    for (int e = 0; e < _cellCount; ++e)
        _columns.push_back(e < static_cast<int>(description.cells.size()) ? floorBox(description.cells[e])
                                                                          : std::array<glm::dvec2, 2>{});
    std::vector<std::vector<int>> openings(_cellCount);  // per cell: its walls and open boundary parts
    addWallChains(plan, table, openings);
    addBeyondChains(plan);
    for (int e = 0; e < _cellCount && e < static_cast<int>(description.cells.size()); ++e)
        for (const auto& [a, b] : openBoundary(description, e)) {
            openings[e].push_back(static_cast<int>(_quads.size()));
            _quads.push_back(openingQuad(description.cells[e], a, b));
        }
    // The eye's own cell without test; cells seen directly through any one opening of it.
    for (int e = 0; e < _cellCount; ++e)
        for (int c = 0; c < _cellCount; ++c) {
            std::vector<std::vector<int>>& chains = at(e, c);
            if (c == e || table.at(e, c) == CellVisibility::Geometry) chains.clear();
            if (c != e && table.at(e, c) == CellVisibility::Geometry)
                for (int o : openings[e]) chains.push_back({o});
        }
}

std::vector<std::vector<int>>& PortalChains::at(int eyeCell, int cell) {
    return _chains[static_cast<std::size_t>(eyeCell) * _cellCount + cell];
}

bool PortalChains::valid(int cell) const { return cell >= 0 && cell < _cellCount; }

// Wall w seen from its side s is an opening of cells[s], the chain to the cell behind it and
// to every cell its textures show from there.
void PortalChains::addWallChains(const Plan& plan, const VisibilityTable& table,
                                 std::vector<std::vector<int>>& openings) {
    for (int w = 0; w < static_cast<int>(plan.walls.size()); ++w) {
        const auto& cells = plan.walls[w].cells;
        for (int s = 0; s < 2; ++s) {
            const int e = cells[s];
            if (!valid(e)) continue;
            openings[e].push_back(2 * w + s);
            if (valid(cells[1 - s]) && cells[1 - s] != e) addChain(at(e, cells[1 - s]), {2 * w + s});
            for (int c = 0; c < _cellCount; ++c) {
                const std::vector<int>& through = table.throughWalls(e, c);
                if (c != e && std::find(through.begin(), through.end(), w) != through.end())
                    addChain(at(e, c), {2 * w + s});
            }
        }
    }
}

// A beyond side's chain: its parent's (or the eye cell's wall it is seen through), then the far
// wall seen from the neighbour's side. Parents precede their children in Plan::beyond.
void PortalChains::addBeyondChains(const Plan& plan) {
    std::vector<std::vector<int>> beyondChain(plan.beyond.size());
    for (std::size_t i = 0; i < plan.beyond.size(); ++i) {
        const BeyondSide& b = plan.beyond[i];
        std::vector<int>& chain = beyondChain[i];
        if (b.parent >= 0 && static_cast<std::size_t>(b.parent) < i) {
            chain = beyondChain[static_cast<std::size_t>(b.parent)];
        } else if (b.viaWall >= 0 && valid(b.eyeCell)) {
            const auto& cells = plan.walls[b.viaWall].cells;
            chain = {2 * b.viaWall + (cells[0] == b.eyeCell ? 0 : 1)};
        }
        chain.push_back(2 * b.side.wall + b.side.side);
        const int behind = plan.walls[b.side.wall].cells[1 - b.side.side];
        if (valid(b.eyeCell) && valid(behind) && behind != b.eyeCell) addChain(at(b.eyeCell, behind), chain);
    }
}

const std::vector<std::vector<int>>& PortalChains::chains(int eyeCell, int cell) const {
    static const std::vector<std::vector<int>> none;
    if (eyeCell < 0 || eyeCell >= _cellCount || cell < 0 || cell >= _cellCount) return none;
    return _chains[static_cast<std::size_t>(eyeCell) * _cellCount + cell];
}

void PortalChains::frameSets(int eyeCell, const std::vector<bool>& drawn, const scenes::Scene& scene,
                             render::PortalSets& out) const {
    out.portals.clear();
    out.chains.clear();
    out.sets.clear();
    out.objectSet.assign(scene.objects.size(), -1);
    if (eyeCell < 0 || eyeCell >= _cellCount) return;
    out.portals = _quads;
    const std::array<glm::dvec2, 2> column = _columns[static_cast<std::size_t>(eyeCell)];
    // One set per combination of drawn cells seen through chains: most objects have one cell,
    // whose set is found by index; combinations by a map.
    std::vector<int> setOfCell(static_cast<std::size_t>(_cellCount), -1);
    std::map<std::vector<int>, int> setOf;
    std::vector<int> cells;
    auto newSet = [&](const std::vector<int>& of) {
        std::vector<int> set;
        for (int c : of)
            for (const std::vector<int>& chain : chains(eyeCell, c)) {
                set.push_back(static_cast<int>(out.chains.size()));
                out.chains.push_back(chain);
            }
        out.sets.push_back(std::move(set));
        return static_cast<int>(out.sets.size()) - 1;
    };
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const scenes::Object& o = scene.objects[i];
        if (o.role == scenes::Role::Structure) continue;
        cells.clear();
        bool free = false;
        scenes::anyCellOf(o, [&](int c) {
            if (c < 0 || c >= _cellCount || c >= static_cast<int>(drawn.size()) || !drawn[c]) return false;
            if (chains(eyeCell, c).empty()) free = true;
            cells.push_back(c);
            return free;
        });
        if (free || cells.empty() || overlaps(o.worldBounds, column)) continue;
        if (cells.size() == 1) {
            int& set = setOfCell[static_cast<std::size_t>(cells[0])];
            if (set < 0) set = newSet(cells);
            out.objectSet[i] = set;
            continue;
        }
        std::sort(cells.begin(), cells.end());
        const auto found = setOf.find(cells);
        out.objectSet[i] = found != setOf.end() ? found->second : setOf.emplace(cells, newSet(cells)).first->second;
    }
}

}  // namespace cavewall::walls
