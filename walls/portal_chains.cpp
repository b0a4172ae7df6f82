#include "walls/portal_chains.h"

#include <algorithm>
#include <map>

namespace cavewall::walls {

namespace {

void addChain(std::vector<std::vector<int>>& chains, std::vector<int> chain) {
    if (std::find(chains.begin(), chains.end(), chain) == chains.end()) chains.push_back(std::move(chain));
}

}  // namespace

PortalChains::PortalChains(const Plan& plan, const VisibilityTable& table) : _cellCount(table.cellCount) {
    const int n = _cellCount;
    _chains.resize(static_cast<std::size_t>(n) * n);
    for (const PlannedWall& w : plan.walls) _quads.push_back(w.quad);
    auto at = [&](int eye, int cell) -> std::vector<std::vector<int>>& {
        return _chains[static_cast<std::size_t>(eye) * n + cell];
    };
    auto valid = [&](int c) { return c >= 0 && c < n; };
    for (int w = 0; w < static_cast<int>(plan.walls.size()); ++w) {
        const auto& cells = plan.walls[w].cells;
        for (int s = 0; s < 2; ++s)
            if (valid(cells[s]) && valid(cells[1 - s]) && cells[s] != cells[1 - s])
                addChain(at(cells[s], cells[1 - s]), {w});
    }
    // Beyond sides: parents precede their children (Plan::beyond).
    std::vector<std::vector<int>> beyondChain(plan.beyond.size());
    for (std::size_t i = 0; i < plan.beyond.size(); ++i) {
        const BeyondSide& b = plan.beyond[i];
        std::vector<int>& chain = beyondChain[i];
        if (b.parent >= 0 && static_cast<std::size_t>(b.parent) < i)
            chain = beyondChain[static_cast<std::size_t>(b.parent)];
        else if (b.viaWall >= 0)
            chain = {b.viaWall};
        chain.push_back(b.side.wall);
        const int behind = plan.walls[b.side.wall].cells[1 - b.side.side];
        if (valid(b.eyeCell) && valid(behind) && behind != b.eyeCell) addChain(at(b.eyeCell, behind), chain);
    }
    // Seen without test: the eye's own cell and cells seen through open boundaries.
    for (int e = 0; e < n; ++e)
        for (int c = 0; c < n; ++c)
            if (c == e || table.at(e, c) == CellVisibility::Geometry) at(e, c).clear();
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
    // One set per combination of drawn cells seen through chains (most objects have one cell).
    std::map<std::vector<int>, int> setOf;
    std::vector<int> cells;
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
        if (free || cells.empty()) continue;
        std::sort(cells.begin(), cells.end());
        auto [it, added] = setOf.try_emplace(cells, static_cast<int>(out.sets.size()));
        if (added) {
            std::vector<int> set;
            for (int c : cells)
                for (const std::vector<int>& chain : chains(eyeCell, c)) {
                    set.push_back(static_cast<int>(out.chains.size()));
                    out.chains.push_back(chain);
                }
            out.sets.push_back(std::move(set));
        }
        out.objectSet[i] = it->second;
    }
}

}  // namespace cavewall::walls
