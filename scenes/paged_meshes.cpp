#include "scenes/paged_meshes.h"

#include <algorithm>
#include <map>

namespace cavewall::scenes {

PagedMeshGroups pagedMeshGroups(const Scene& scene, int cellCount) {
    const std::size_t meshCount = scene.meshes.size();
    std::vector<bool> alwaysResident(meshCount, false);
    std::vector<std::vector<int>> cellsOfMesh(meshCount);
    for (const Object& o : scene.objects) {
        if (o.mesh < 0 || static_cast<std::size_t>(o.mesh) >= meshCount) continue;
        if (!pagedWithCell(o, cellCount))
            alwaysResident[o.mesh] = true;
        else
            for (int c : cellsOf(o)) cellsOfMesh[o.mesh].push_back(c);
    }
    PagedMeshGroups g;
    g.groupOfMesh.assign(meshCount, -1);
    g.cellGroups.resize(static_cast<std::size_t>(std::max(cellCount, 0)));
    std::map<std::vector<int>, int> bySignature;  // cells using a mesh -> group
    for (std::size_t m = 0; m < meshCount; ++m) {
        std::vector<int>& cells = cellsOfMesh[m];
        if (alwaysResident[m] || cells.empty()) continue;
        std::sort(cells.begin(), cells.end());
        cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
        auto [it, added] = bySignature.emplace(cells, g.groupCount());
        if (added) {
            g.groupMeshes.emplace_back();
            g.groupCells.push_back(cells);
            for (int c : cells) g.cellGroups[static_cast<std::size_t>(c)].push_back(it->second);
        }
        g.groupOfMesh[m] = it->second;
        g.groupMeshes[static_cast<std::size_t>(it->second)].push_back(static_cast<int>(m));
    }
    return g;
}

}  // namespace cavewall::scenes
