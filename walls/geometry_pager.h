#pragma once
// Paging of the model's geometry by cell under a GPU memory budget, GL-free: the counterpart of
// walls/texture_pager.h for the cells the walkthrough draws as geometry.
//
// With virtual walls a frame draws as geometry only the viewer's cell and the cells it blends
// into (walkthrough/frame_planner.h); every other cell is a texture. Per frame the runtime says which
// cells it draws as geometry now and which it may draw soon (the neighbours of those: one wall
// away). A background thread loads the cells' mesh groups (below; the `Loader` reads or
// prepares a group's meshes; the GL side uploads what is ready); residency is counted in bytes
// against the budget, and when a new group would exceed it the least recently wanted groups
// that no wanted-now cell uses are evicted. A cell wanted now that is not resident is a miss
// for that frame: the planner keeps its wall textures (never a stall, never a hole), and the
// miss is counted. Structure and objects without a cell are always resident and not counted
// in the budget.
//
// Units: what is loaded, counted and freed is a mesh group (scenes/paged_meshes.h: the meshes
// used by exactly the same cells), not a cell: a mesh shared by several cells is resident once,
// while any cell using it is wanted or until evicted, so the resident geometry is the union of
// the resident cells' meshes and never more than the whole model's. A cell is resident when all
// its groups are. A pager built from cell sizes alone treats each cell as its own group.
//
// Sizes: a group's bytes are those of its meshes (each once; compact vertices and 32-bit
// indices, kVertexBytes/kIndexBytes, the indices of every level of detail when the levels are
// given): exactly the GPU buffers render/gl/scene_gpu.h allocates for it. cellGeometryBytes
// gives a cell's own meshes (each once per cell), the yardstick "the largest three cells".
// Per-object transforms are per view (the scene renderer's draw records), not per cell.

#include "scenes/mesh_lod.h"
#include "scenes/paged_meshes.h"
#include "scenes/scene.h"
#include "walls/residency.h"

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace cavewall::walls {

inline constexpr std::size_t kVertexBytes = 24;  // display/gl's compact vertex
inline constexpr std::size_t kIndexBytes = 4;

// Bytes of each cell's geometry (index = cell, `cellCount` cells); structure and objects
// without a cell are not counted. `lods`: one per mesh (render::RenderScene::lods()), or null.
std::vector<std::size_t> cellGeometryBytes(const scenes::Scene& scene, int cellCount,
                                           const std::vector<scenes::MeshLod>* lods = nullptr);
// Bytes of the whole model's geometry: every mesh once (with its levels when given).
std::size_t modelGeometryBytes(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods = nullptr);
// Bytes of each mesh group of `groups` (its meshes once, with their levels when given).
std::vector<std::size_t> groupGeometryBytes(const scenes::Scene& scene, const scenes::PagedMeshGroups& groups,
                                            const std::vector<scenes::MeshLod>* lods = nullptr);
// The sum of the `n` largest of `bytes` (the largest three cells' worth: n = 3).
std::size_t largestBytes(std::vector<std::size_t> bytes, std::size_t n);

struct GeometryPagerStats {
    int resident = 0;         // groups resident (cells, with one group per cell)
    double residentMB = 0.0;  // bytes of the resident groups (each once)
    long pageIns = 0;         // groups made resident so far
    long misses = 0;          // wanted-now cells that were not resident, summed over frames
    long evictions = 0;       // groups evicted so far
};

class GeometryPager {
public:
    // Loads group `group`'s geometry on the pager's thread (may throw: the group then stays
    // missing, its cells misses, and is retried when wanted again). Empty: nothing to load (the
    // sizes alone are paged).
    using Loader = std::function<void(int group)>;

    // `groupBytes` from groupGeometryBytes, `cellGroups` the groups of each cell
    // (PagedMeshGroups::cellGroups); `budgetMB` > 0.
    GeometryPager(std::vector<std::size_t> groupBytes, std::vector<std::vector<int>> cellGroups, double budgetMB,
                  Loader loader = {});
    // One group per cell: `cellBytes` from cellGeometryBytes (a model whose cells share nothing).
    GeometryPager(std::vector<std::size_t> cellBytes, double budgetMB, Loader loader = {});
    ~GeometryPager();
    GeometryPager(const GeometryPager&) = delete;
    GeometryPager& operator=(const GeometryPager&) = delete;

    // Declares this frame's wishes (cells) and counts misses among `now` (a cell with a group
    // not resident). Cheap; never blocks on I/O.
    void request(const std::vector<int>& now, const std::vector<int>& soon);
    // Groups loaded and ready for upload, those of wanted-now cells first. The caller uploads
    // them and then calls markResident for each.
    std::vector<int> takeReady();
    void markResident(int group);
    // Groups to delete on the GPU now to stay within the budget (never one a wanted-now cell uses).
    std::vector<int> takeEvictions();

    // Cell `cell`'s groups are all resident (true for a cell without paged geometry).
    bool isResident(int cell) const;
    bool groupResident(int group) const;
    // The groups of cell `cell` (empty for an unknown cell).
    const std::vector<int>& groupsOf(int cell) const;
    GeometryPagerStats stats() const;
    double budgetMB() const;
    // Blocks until the loader is idle (tests, benches' warm-up, synchronous paging).
    void waitIdle();

private:
    void worker();

    bool cellResident(int cell) const;  // under the lock

    std::vector<std::size_t> _bytes;            // per group
    std::vector<std::vector<int>> _cellGroups;  // per cell
    Loader _loader;

    mutable std::mutex _mutex;
    std::condition_variable _wake, _idle;
    std::deque<int> _queue;
    std::set<int> _loading;
    std::vector<int> _ready;
    ResidencyCore _residency;   // resident groups, budget and eviction (walls/residency.h)
    GeometryPagerStats _stats;  // misses (the rest from _residency)
    bool _stop = false;
    std::thread _thread;
};

}  // namespace cavewall::walls
