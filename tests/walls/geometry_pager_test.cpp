#include "walls/geometry_pager.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <latch>

namespace cavewall::walls {
namespace {

constexpr std::size_t kMB = 1024 * 1024;

// Places mesh `mesh` of `s` in `cell` (-1: none) as a `role` object.
void placeObject(scenes::Scene& s, int mesh, int cell, scenes::Role role = scenes::Role::Content) {
    scenes::Object o;
    o.mesh = mesh;
    o.cell = cell;
    o.role = role;
    s.objects.push_back(o);
}

void uploadAll(GeometryPager& pager) {
    pager.waitIdle();
    for (int c : pager.takeReady()) pager.markResident(c);
}

// Two meshes (a 3-vertex triangle, a 4-vertex quad) placed in three cells; the quad twice in
// cell 1, once in cell 2; structure and cell-less objects are not paged. The bytes are those of
// the GPU buffers a cell gets (render/gl/scene_gpu.h): vertices and indices, no per-object data.
TEST(GeometryPager, CellBytesCountEachMeshOncePerCell) {
    scenes::Scene s;
    s.meshes.resize(2);
    s.meshes[0].positions.resize(3);
    s.meshes[0].indices.resize(3);
    s.meshes[1].positions.resize(4);
    s.meshes[1].indices.resize(6);
    placeObject(s, 0, 0);
    placeObject(s, 1, 1);
    placeObject(s, 1, 1);
    placeObject(s, 1, 2);
    placeObject(s, 0, 2);
    placeObject(s, 0, -1);
    placeObject(s, 1, 0, scenes::Role::Structure);
    const std::size_t tri = 3 * kVertexBytes + 3 * kIndexBytes, quad = 4 * kVertexBytes + 6 * kIndexBytes;
    const std::vector<std::size_t> bytes = cellGeometryBytes(s, 3);
    ASSERT_EQ(bytes.size(), 3u);
    EXPECT_EQ(bytes[0], tri);
    EXPECT_EQ(bytes[1], quad);  // the quad is stored once for its two instances
    EXPECT_EQ(bytes[2], quad + tri);
    EXPECT_EQ(modelGeometryBytes(s), tri + quad);
    // With levels of detail a mesh's index buffer holds every level: the quad's two levels
    // (6 + 3 indices) replace its 6 indices; the triangle has no levels and keeps its own.
    std::vector<scenes::MeshLod> lods(2);
    lods[1].indices.resize(9);
    lods[1].levels.resize(2);
    const std::size_t quadLevels = 4 * kVertexBytes + 9 * kIndexBytes;
    EXPECT_EQ(cellGeometryBytes(s, 3, &lods)[2], quadLevels + tri);
    EXPECT_EQ(modelGeometryBytes(s, &lods), tri + quadLevels);
}

TEST(GeometryPager, LoadsWhatIsWantedAndCountsMisses) {
    std::atomic<int> loads{0};
    GeometryPager pager({kMB, kMB, kMB, kMB}, 8.0, [&](int) { ++loads; });
    pager.request({0}, {1, 2});
    EXPECT_EQ(pager.stats().misses, 1);  // cell 0 was wanted now and is not resident
    EXPECT_FALSE(pager.isResident(0));   // request never waits for the loader
    uploadAll(pager);
    EXPECT_EQ(loads.load(), 3);
    EXPECT_TRUE(pager.isResident(0) && pager.isResident(1) && pager.isResident(2));
    EXPECT_FALSE(pager.isResident(3));
    pager.request({1}, {0});
    const GeometryPagerStats s = pager.stats();
    EXPECT_EQ(s.misses, 1);  // resident: no new miss
    EXPECT_EQ(s.resident, 3);
    EXPECT_EQ(s.pageIns, 3);
    EXPECT_NEAR(s.residentMB, 3.0, 1e-12);
    EXPECT_EQ(loads.load(), 3);  // nothing loaded twice
}

TEST(GeometryPager, EvictsTheLeastRecentlyWantedButNeverACellWantedNow) {
    GeometryPager pager({kMB, kMB, kMB, kMB}, 2.5);  // room for two cells
    for (int c : {0, 1}) {
        pager.request({c}, {});
        uploadAll(pager);
    }
    EXPECT_TRUE(pager.takeEvictions().empty());
    pager.request({2, 1}, {});
    uploadAll(pager);
    EXPECT_EQ(pager.takeEvictions(), std::vector<int>{0});  // the oldest wish, not wanted now
    EXPECT_LE(pager.stats().residentMB, 2.5);
    // Three cells wanted at once do not fit: the pager goes over budget rather than evict one.
    pager.request({0, 1, 2}, {});
    uploadAll(pager);
    EXPECT_TRUE(pager.takeEvictions().empty());
    EXPECT_EQ(pager.stats().resident, 3);
}

// A slow disk: a frame's request returns at once while the cell loads; the cell is a miss on
// every frame until it is resident (the planner keeps its wall textures meanwhile).
TEST(GeometryPager, FramesNeverWaitForTheLoader) {
    std::latch release(1);
    GeometryPager pager({kMB, kMB}, 8.0, [&](int) { release.wait(); });
    for (int frame = 0; frame < 3; ++frame) {
        pager.request({1}, {});
        EXPECT_TRUE(pager.takeReady().empty());
    }
    EXPECT_EQ(pager.stats().misses, 3);
    release.count_down();
    uploadAll(pager);
    pager.request({1}, {});
    EXPECT_EQ(pager.stats().misses, 3);
    EXPECT_TRUE(pager.isResident(1));
}

TEST(GeometryPager, AFailedLoadStaysAMissAndIsRetried) {
    std::atomic<int> attempts{0};
    GeometryPager pager({kMB}, 8.0, [&](int) {
        if (attempts++ == 0) throw std::runtime_error("cell 0: read error");
    });
    pager.request({0}, {});
    uploadAll(pager);
    EXPECT_FALSE(pager.isResident(0));
    pager.request({0}, {});
    uploadAll(pager);
    EXPECT_TRUE(pager.isResident(0));
    EXPECT_EQ(attempts.load(), 2);
    EXPECT_EQ(pager.stats().misses, 2);
}

// Three meshes in three cells as a CAD export places parts: mesh 0 (a part kind) in every cell,
// mesh 1 in cell 0 only, mesh 2 in cells 1 and 2; mesh 3 is used by structure and by cell 1
// (always resident), mesh 4 by nothing.
scenes::Scene sharedMeshes() {
    scenes::Scene s;
    s.meshes.resize(5);
    for (int m = 0; m < 5; ++m) {
        s.meshes[m].positions.resize(static_cast<std::size_t>(10 * (m + 1)));  // distinct sizes
        s.meshes[m].indices.resize(3);
    }
    for (int c : {0, 1, 2}) placeObject(s, 0, c);
    placeObject(s, 1, 0);
    placeObject(s, 2, 2);
    placeObject(s, 2, 1);
    placeObject(s, 0, 2);
    placeObject(s, 3, 1);
    placeObject(s, 3, -1, scenes::Role::Structure);
    return s;
}

TEST(PagedMeshGroups, GroupsMeshesByTheCellsThatUseThem) {
    const scenes::PagedMeshGroups g = scenes::pagedMeshGroups(sharedMeshes(), 3);
    // Numbered by first mesh: mesh 0 -> group 0 (cells 0, 1, 2), 1 -> 1 (cell 0), 2 -> 2 (1, 2).
    EXPECT_EQ(g.groupOfMesh, (std::vector<int>{0, 1, 2, -1, -1}));
    EXPECT_EQ(g.groupMeshes, (std::vector<std::vector<int>>{{0}, {1}, {2}}));
    EXPECT_EQ(g.groupCells, (std::vector<std::vector<int>>{{0, 1, 2}, {0}, {1, 2}}));
    EXPECT_EQ(g.cellGroups, (std::vector<std::vector<int>>{{0, 1}, {0, 2}, {0, 2}}));
    // Meshes used by the same cells share a group.
    scenes::Scene s = sharedMeshes();
    s.objects.push_back({});
    s.objects.back().mesh = 4;
    s.objects.back().cell = 0;
    const scenes::PagedMeshGroups h = scenes::pagedMeshGroups(s, 3);
    EXPECT_EQ(h.groupOfMesh[4], 1);
    EXPECT_EQ(h.groupMeshes[1], (std::vector<int>{1, 4}));
    // An object whose cell is outside the description is always resident, and so is its mesh.
    s.objects.back().cell = 7;
    EXPECT_EQ(scenes::pagedMeshGroups(s, 3).groupOfMesh[4], -1);
}

// An object of two cells (a wall between two rooms) pages with both: its mesh is in the group
// of exactly those cells, loaded when either is wanted; one of its cells beyond the description
// makes it always resident.
TEST(PagedMeshGroups, AnObjectOfTwoCellsPagesWithItsCells) {
    scenes::Scene s = sharedMeshes();
    placeObject(s, 4, 0);
    s.objects.back().moreCells = {2};
    const scenes::PagedMeshGroups g = scenes::pagedMeshGroups(s, 3);
    ASSERT_GE(g.groupOfMesh[4], 0);
    EXPECT_EQ(g.groupCells[static_cast<std::size_t>(g.groupOfMesh[4])], (std::vector<int>{0, 2}));
    for (int c : {0, 2}) {
        const std::vector<int>& groups = g.cellGroups[static_cast<std::size_t>(c)];
        EXPECT_NE(std::find(groups.begin(), groups.end(), g.groupOfMesh[4]), groups.end()) << "cell " << c;
    }
    const std::vector<int>& groups1 = g.cellGroups[1];
    EXPECT_EQ(std::find(groups1.begin(), groups1.end(), g.groupOfMesh[4]), groups1.end());
    const std::size_t mesh4 = s.meshes[4].positions.size() * kVertexBytes + 3 * kIndexBytes;
    const std::vector<std::size_t> withWall = cellGeometryBytes(s, 3), without = cellGeometryBytes(sharedMeshes(), 3);
    EXPECT_EQ(withWall[0], without[0] + mesh4);
    EXPECT_EQ(withWall[1], without[1]);
    EXPECT_EQ(withWall[2], without[2] + mesh4);
    s.objects.back().moreCells = {5};
    EXPECT_EQ(scenes::pagedMeshGroups(s, 3).groupOfMesh[4], -1);
}

// The point of groups: walking through every cell keeps each mesh once, so the resident bytes
// are the union of the cells' meshes (here the whole model less the always-resident mesh 3),
// where a copy per cell would hold mesh 0 three times and mesh 2 twice.
TEST(GeometryPager, AMeshSharedByCellsIsResidentOnce) {
    const scenes::Scene s = sharedMeshes();
    const scenes::PagedMeshGroups g = scenes::pagedMeshGroups(s, 3);
    const std::vector<std::size_t> groupBytes = groupGeometryBytes(s, g);
    std::atomic<int> loads{0};
    GeometryPager pager(groupBytes, g.cellGroups, 64.0, [&](int) { ++loads; });
    for (int c : {0, 1, 2}) {
        pager.request({c}, {});
        uploadAll(pager);
        EXPECT_TRUE(pager.isResident(c));
    }
    EXPECT_EQ(loads.load(), 3);  // three groups, each loaded once
    auto bytes = [&](int mesh) { return s.meshes[mesh].positions.size() * kVertexBytes + 3 * kIndexBytes; };
    const std::size_t resident = bytes(0) + bytes(1) + bytes(2);
    EXPECT_NEAR(pager.stats().residentMB * kMB, static_cast<double>(resident), 1e-6);
    EXPECT_EQ(modelGeometryBytes(s), resident + bytes(3) + bytes(4));
    // The yardstick counts each cell's own meshes (cell 1's include the always-resident mesh 3).
    const std::vector<std::size_t> cellBytes = cellGeometryBytes(s, 3);
    EXPECT_EQ(cellBytes,
              (std::vector<std::size_t>{bytes(0) + bytes(1), bytes(0) + bytes(2) + bytes(3), bytes(0) + bytes(2)}));
    EXPECT_EQ(largestBytes(cellBytes, 3), 3 * bytes(0) + bytes(1) + 2 * bytes(2) + bytes(3));
    EXPECT_LT(resident, largestBytes(cellBytes, 3));
    // Cells 1 and 2 are the largest two: cell 2 (mesh 2, 732 B) outweighs cell 0 (mesh 1, 492 B).
    EXPECT_EQ(largestBytes(cellBytes, 2), 2 * bytes(0) + 2 * bytes(2) + bytes(3));
}

// A cell is resident when all its groups are; evicting a group another wanted-now cell uses is
// never allowed, and a group only a cell left behind uses goes first.
TEST(GeometryPager, EvictsGroupsNoWantedCellUses) {
    // Cells 0: {0, 1}, 1: {0, 2}, 2: {0, 3}; 1 MB each; room for three groups.
    GeometryPager pager({kMB, kMB, kMB, kMB}, {{0, 1}, {0, 2}, {0, 3}}, 3.5);
    pager.request({0}, {});
    uploadAll(pager);
    pager.request({1}, {});
    uploadAll(pager);
    EXPECT_TRUE(pager.takeEvictions().empty());
    EXPECT_TRUE(pager.isResident(0) && pager.isResident(1));
    pager.request({2}, {});
    uploadAll(pager);
    EXPECT_EQ(pager.takeEvictions(), std::vector<int>{1});  // cell 0's own group; group 0 stays
    EXPECT_FALSE(pager.isResident(0));
    EXPECT_TRUE(pager.isResident(1) && pager.isResident(2));
    EXPECT_TRUE(pager.groupResident(0));
    EXPECT_EQ(pager.stats().resident, 3);
    EXPECT_EQ(pager.stats().pageIns, 4);  // groups 0, 1, 2, 3: group 0 once for all three cells
    EXPECT_EQ(pager.groupsOf(2), (std::vector<int>{0, 3}));
    EXPECT_TRUE(pager.groupsOf(9).empty());
}

// A miss is per cell: a cell counts once per frame however many of its groups are missing.
TEST(GeometryPager, MissesCountCellsNotGroups) {
    GeometryPager pager({kMB, kMB, kMB}, {{0, 1, 2}, {}}, 8.0);
    pager.request({0, 1}, {});
    EXPECT_EQ(pager.stats().misses, 1);
    EXPECT_TRUE(pager.isResident(1));  // no paged geometry: always resident
}

TEST(GeometryPager, UnknownCellsAreIgnored) {
    GeometryPager pager({kMB}, 8.0);
    pager.request({-1, 5}, {7});
    uploadAll(pager);
    EXPECT_EQ(pager.stats().misses, 0);
    EXPECT_EQ(pager.stats().resident, 0);
}

}  // namespace
}  // namespace cavewall::walls
