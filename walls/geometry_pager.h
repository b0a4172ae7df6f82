#pragma once
// Paging of the model's geometry by cell under a GPU memory budget, GL-free: the counterpart of
// walls/texture_pager.h for the cells the walkthrough draws as geometry (cavewall issue 15).
//
// With virtual walls a frame draws as geometry only the viewer's cell and the cells it blends
// into (walls/frame_planner.h); every other cell is a texture. Per frame the runtime says which
// cells it draws as geometry now and which it may draw soon (the neighbours of those: one wall
// away). A background thread loads cells (the `Loader`: reads or prepares a cell's meshes;
// the GL side uploads what is ready); residency is counted in bytes (cellGeometryBytes) against
// the budget, and when a new cell would exceed it the least recently wanted cells not wanted
// now are evicted. A cell wanted now that is not resident is a miss for that frame: the planner
// keeps its wall textures (never a stall, never a hole), and the miss is counted. Structure
// and objects without a cell are always resident and not counted in the budget.
//
// Sizes: a cell's bytes are those of the meshes its paged objects use (scenes::pagedWithCell;
// each mesh once per cell, compact vertices and 32-bit indices, kVertexBytes/kIndexBytes, the
// indices of every level of detail when the levels are given): exactly the GPU buffers
// display/gl/scene_gpu.h allocates for the cell. A mesh shared by two cells counts in both, as
// the GPU stores it in both (each cell is loadable on its own, as from a cell-ordered cache).
// Per-object transforms are per view (the scene renderer's draw records), not per cell.

#include "scenes/mesh_lod.h"
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

inline constexpr std::size_t kVertexBytes = 24;     // display/gl's compact vertex
inline constexpr std::size_t kIndexBytes = 4;

// Bytes of each cell's geometry (index = cell, `cellCount` cells); structure and objects
// without a cell are not counted. `lods`: one per mesh (render::RenderScene::lods()), or null.
std::vector<std::size_t> cellGeometryBytes(const scenes::Scene& scene, int cellCount,
                                           const std::vector<scenes::MeshLod>* lods = nullptr);
// Bytes of the whole model's geometry: every mesh once (with its levels when given).
std::size_t modelGeometryBytes(const scenes::Scene& scene, const std::vector<scenes::MeshLod>* lods = nullptr);

struct GeometryPagerStats {
    int resident = 0;                        // cells resident
    double residentMB = 0.0;
    long pageIns = 0;                        // cells made resident so far
    long misses = 0;                         // wanted-now cells that were not resident, summed over frames
    long evictions = 0;
};

class GeometryPager {
public:
    // Loads cell `cell`'s geometry on the pager's thread (may throw: the cell then stays a miss
    // and is retried when wanted again). Empty: nothing to load (the sizes alone are paged).
    using Loader = std::function<void(int cell)>;

    // `cellBytes` from cellGeometryBytes; `budgetMB` > 0.
    GeometryPager(std::vector<std::size_t> cellBytes, double budgetMB, Loader loader = {});
    ~GeometryPager();
    GeometryPager(const GeometryPager&) = delete;
    GeometryPager& operator=(const GeometryPager&) = delete;

    // Declares this frame's wishes and counts misses among `now`. Cheap; never blocks on I/O.
    void request(const std::vector<int>& now, const std::vector<int>& soon);
    // Cells loaded and ready for upload, wanted-now first. The caller uploads them and then
    // calls markResident for each.
    std::vector<int> takeReady();
    void markResident(int cell);
    // Cells to delete on the GPU now to stay within the budget (never one wanted now).
    std::vector<int> takeEvictions();

    bool isResident(int cell) const;
    GeometryPagerStats stats() const;
    double budgetMB() const;
    // Blocks until the loader is idle (tests, benches' warm-up, synchronous paging).
    void waitIdle();

private:
    void worker();

    std::vector<std::size_t> _bytes;
    Loader _loader;

    mutable std::mutex _mutex;
    std::condition_variable _wake, _idle;
    std::deque<int> _queue;
    std::set<int> _loading;
    std::vector<int> _ready;
    ResidencyCore _residency;        // resident cells, budget and eviction (walls/residency.h)
    GeometryPagerStats _stats;   // misses (the rest from _residency)
    bool _stop = false;
    std::thread _thread;
};

}  // namespace cavewall::walls
