#include "walls/geometry_pager.h"

#include <gtest/gtest.h>

#include <atomic>
#include <latch>

namespace cavewall::walls {
namespace {

constexpr std::size_t kMB = 1024 * 1024;

void uploadAll(GeometryPager& pager) {
    pager.waitIdle();
    for (int c : pager.takeReady()) pager.markResident(c);
}

// Two meshes (a 3-vertex triangle, a 4-vertex quad) placed in three cells; the quad twice in
// cell 1, once in cell 2; structure and cell-less objects are not paged. The bytes are those of
// the GPU buffers a cell gets (display/gl/scene_gpu.h): vertices and indices, no per-object data.
TEST(GeometryPager, CellBytesCountEachMeshOncePerCell) {
    scenes::Scene s;
    s.meshes.resize(2);
    s.meshes[0].positions.resize(3);
    s.meshes[0].indices.resize(3);
    s.meshes[1].positions.resize(4);
    s.meshes[1].indices.resize(6);
    auto add = [&](int mesh, int cell, scenes::Role role = scenes::Role::Content) {
        scenes::Object o;
        o.mesh = mesh, o.cell = cell, o.role = role;
        s.objects.push_back(o);
    };
    add(0, 0);
    add(1, 1);
    add(1, 1);
    add(1, 2);
    add(0, 2);
    add(0, -1);
    add(1, 0, scenes::Role::Structure);
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
    EXPECT_EQ(pager.stats().misses, 1);   // cell 0 was wanted now and is not resident
    EXPECT_FALSE(pager.isResident(0));    // request never waits for the loader
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

TEST(GeometryPager, UnknownCellsAreIgnored) {
    GeometryPager pager({kMB}, 8.0);
    pager.request({-1, 5}, {7});
    uploadAll(pager);
    EXPECT_EQ(pager.stats().misses, 0);
    EXPECT_EQ(pager.stats().resident, 0);
}

}  // namespace
}  // namespace cavewall::walls
