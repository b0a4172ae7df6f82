// Geometry paging by cell on the GPU (walkthrough/gl/walkthrough.h, render/gl/scene_gpu.h): a cell's
// meshes live in buffers of their own, uploaded when the pager makes the cell resident and
// deleted when it evicts it, so the resident bytes reported are GPU bytes and go down on
// eviction; where every cell a frame needs is resident, the frame equals the unpaged one. The
// pager's policy is tested without GL in tests/walls/geometry_pager_test.cpp.
#include "tests/support/gl/gl_test_support.h"
#include "tests/walkthrough/gl/runtime_fixture.h"

#include "config/error.h"
#include "display/gl/frame_images.h"
#include "render/gl/scene_renderer.h"
#include "metrics/image_compare.h"
#include "walls/geometry_pager.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <iostream>
#include <algorithm>
#include <map>
#include <set>
#include <numeric>

namespace cavewall::testing {
namespace {

constexpr double kMB = 1024.0 * 1024.0;

class GeometryPagingTest : public GlTest {};

// twoCells(): the red box is cell B's only paged object, the green box cell A's (each its own
// mesh, so each cell has one group of its own); the floors are structure (always resident, in
// the shared buffers). The GPU side alone: uploading and freeing groups moves the resident
// bytes by exactly the pager's sizes of those groups, here the cells' sizes.
TEST_F(GeometryPagingTest, UploadingAndFreeingAGroupMovesTheGpuBytesByItsSize) {
    const SmallPlant& scene = twoCells();
    const std::vector<std::size_t> cellBytes = walls::cellGeometryBytes(scene.scene, 2);
    render::gl::RenderSettings settings;
    settings.pagedCells = 2;
    render::gl::SceneRenderer renderer(scene.scene, settings);
    render::gl::GpuScene& gpu = renderer.gpu();
    EXPECT_EQ(gpu.residentPagedBytes(), 0u);
    const scenes::PagedMeshGroups& groups = gpu.meshGroups();
    ASSERT_EQ(groups.groupCount(), 2);
    const std::vector<std::size_t> groupBytes = walls::groupGeometryBytes(scene.scene, groups);
    for (int g : {0, 1}) gpu.uploadGroup(g, render::gl::packMeshes(scene.scene, nullptr, groups.groupMeshes[g]));
    EXPECT_TRUE(gpu.cellResident(0) && gpu.cellResident(1));
    EXPECT_EQ(gpu.residentPagedBytes(), cellBytes[0] + cellBytes[1]);
    int redBox = -1;
    for (int i = 0; i < static_cast<int>(scene.scene.objects.size()); ++i)
        if (scene.scene.objects[i].name == "red box") redBox = i;
    ASSERT_GE(redBox, 0);
    const int redMesh = scene.scene.objects[redBox].mesh, redGroup = groups.groupOfMesh[redMesh];
    ASSERT_GE(redGroup, 0);
    EXPECT_EQ(groups.cellGroups[1], std::vector<int>{redGroup});  // cell B
    gpu.freeGroup(1 - redGroup);
    EXPECT_FALSE(gpu.cellResident(0));
    EXPECT_EQ(gpu.residentPagedBytes(), groupBytes[redGroup]);
    EXPECT_EQ(gpu.residentPagedBytes(), cellBytes[1]);
    // A cell's objects are not in the shared buffers: drawing them needs their group.
    EXPECT_EQ(gpu.setOf(redBox), 1 + redGroup);
    EXPECT_EQ(gpu.mesh(redMesh).indexCount, 0u);  // set 0: empty
    EXPECT_NE(gpu.mesh(1 + redGroup, redMesh, 0), nullptr);
    gpu.freeGroup(redGroup);
    EXPECT_EQ(gpu.mesh(1 + redGroup, redMesh, 0), nullptr);
    EXPECT_EQ(gpu.residentPagedBytes(), 0u);
}

// The small plant with a mesh of its own for every (mesh, cell set) pair its paged objects use:
// the same pixels and walls, but no mesh shared by two cell sets, so every cell set (a cell, or
// the cells of an object standing in several, scenes/paged_meshes.h) is a mesh group of its own
// (a model exported without instancing).
scenes::Scene unshared(const scenes::Scene& scene, int cells) {
    scenes::Scene out = scene;
    std::map<std::pair<int, std::vector<int>>, int> copies;
    for (scenes::Object& o : out.objects) {
        if (!scenes::pagedWithCell(o, cells)) continue;
        auto [it, added] = copies.emplace(std::pair{o.mesh, scenes::cellsOf(o)}, static_cast<int>(out.meshes.size()));
        if (added) out.meshes.push_back(scene.meshes[o.mesh]);
        o.mesh = it->second;
    }
    return out;
}

// Walks the small plant's north aisle and returns the frames' resident GPU bytes (MB).
struct AisleWalk {
    double minMB = 1e30, peakMB = 0.0;
    long evictions = 0, drops = 0;
};
AisleWalk walkNorthAisle(const scenes::Scene& scene, const SmallPlant& plant, display::gl::Context& context,
                         double budgetMB) {
    const display::Display display = testDisplay(32);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    options.geometryBudgetMB = budgetMB;
    walkthrough::gl::Walkthrough walkthrough(scene, plant.description, display, context, plant.walls, options);
    AisleWalk w;
    double previousMB = 0.0;
    long previousEvictions = 0, previousPageIns = 0;
    for (double x = -36.0; x <= 36.0; x += 3.0) {
        walkthrough::FrameInput in;
        in.worldFromCave = cavePlacedAt({x, 1.7, -10.0});
        const walkthrough::FrameResult r = walkthrough.renderFrame(in);
        const long evicted = r.geometry.evictions - previousEvictions, paged = r.geometry.pageIns - previousPageIns;
        std::cout << "x = " << x << ": " << r.geometry.resident << " groups, " << r.geometry.residentMB * kMB
                  << " GPU bytes, +" << paged << " -" << evicted << "\n";
        EXPECT_EQ(r.geometryForced, 0);
        if (evicted > 0 && paged == 0) {
            EXPECT_LT(r.geometry.residentMB, previousMB);
        }
        w.drops += r.geometry.residentMB < previousMB;
        w.minMB = std::min(w.minMB, r.geometry.residentMB);
        w.peakMB = std::max(w.peakMB, r.geometry.residentMB);
        previousMB = r.geometry.residentMB;
        previousEvictions = r.geometry.evictions;
        previousPageIns = r.geometry.pageIns;
    }
    w.evictions = previousEvictions;
    return w;
}

// The distinct cell sets of the paged objects of `scene`.
int cellSetCount(const scenes::Scene& scene, int cells) {
    std::set<std::vector<int>> sets;
    for (const scenes::Object& o : scene.objects)
        if (scenes::pagedWithCell(o, cells)) {
            std::vector<int> set = scenes::cellsOf(o);
            std::sort(set.begin(), set.end());
            sets.insert(set);
        }
    return static_cast<int>(sets.size());
}

// Without shared meshes each cell set is one group: under a budget of about two cells the
// walkthrough frees evicted groups on the GPU, so its resident bytes (FrameResult::geometry,
// frames.csv) are the GPU's and drop when the pager evicts more than it pages in.
TEST_F(GeometryPagingTest, TheWalkthroughFreesEvictedGroupsOnTheGpu) {
    const SmallPlant& plant = smallPlant();
    const int cells = static_cast<int>(plant.description.cells.size());
    const scenes::Scene scene = unshared(plant.scene, cells);
    ASSERT_EQ(render::gl::SceneRenderer(scene,
                                        [&] {
                                            render::gl::RenderSettings s;
                                            s.pagedCells = cells;
                                            return s;
                                        }())
                  .gpu()
                  .meshGroups()
                  .groupCount(),
              cellSetCount(scene, cells));
    std::vector<std::size_t> cellBytes = walls::cellGeometryBytes(scene, cells);
    std::sort(cellBytes.rbegin(), cellBytes.rend());
    const AisleWalk w = walkNorthAisle(scene, plant, *context, static_cast<double>(cellBytes[0] + cellBytes[1]) / kMB);
    EXPECT_GT(w.evictions, 0);
    EXPECT_GT(w.drops, 0);
}

// The plant as generated: its cells share their part kinds' meshes (six mesh groups), so the
// walk holds each mesh once, below the whole model and the largest three cells' worth, where a
// copy per cell (the unshared scene above) holds more.
TEST_F(GeometryPagingTest, AMeshSharedByCellsIsStoredOnce) {
    const SmallPlant& plant = smallPlant();
    const int cells = static_cast<int>(plant.description.cells.size());
    const AisleWalk shared = walkNorthAisle(plant.scene, plant, *context, 64.0);
    const AisleWalk copies = walkNorthAisle(unshared(plant.scene, cells), plant, *context, 64.0);
    const std::size_t model = walls::modelGeometryBytes(plant.scene);
    const std::size_t largestThree = walls::largestBytes(walls::cellGeometryBytes(plant.scene, cells), 3);
    std::cout << "peak " << shared.peakMB * kMB << " bytes shared, " << copies.peakMB * kMB << " with a copy per cell; "
              << "whole model " << model << ", largest three cells " << largestThree << "\n";
    EXPECT_EQ(shared.evictions, 0);
    EXPECT_LT(shared.peakMB * kMB, static_cast<double>(model));
    EXPECT_LT(shared.peakMB * kMB, static_cast<double>(largestThree));
    EXPECT_LT(shared.peakMB, copies.peakMB);
}

// With every needed cell resident (synchronous paging, a budget for all of them) the paged
// renderer draws the same pixels as the one holding the whole model, in all three zones of the
// plant's wall N2|N3; only the opaque draw order within a batch may differ (grouped by cell),
// hence the golden tolerance rather than exact equality.
TEST_F(GeometryPagingTest, FramesEqualTheUnpagedOnesWhenTheNeededCellsAreResident) {
    const SmallPlant& plant = smallPlant();
    const display::Display display = testDisplay(64);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    walkthrough::gl::Walkthrough whole(plant.scene, plant.description, display, *context, plant.walls, options);
    options.geometryBudgetMB = 64.0;
    walkthrough::gl::Walkthrough paged(plant.scene, plant.description, display, *context, plant.walls, options);
    int frames = 0;
    for (double x = -29.5; x < -20.0; x += 1.5, ++frames) {
        SCOPED_TRACE(x);
        walkthrough::FrameInput in;
        in.worldFromCave = cavePlacedAt({x, 1.7, -10.0});
        in.readImages = true;
        const walkthrough::FrameResult a = whole.renderFrame(in), b = paged.renderFrame(in);
        EXPECT_EQ(b.geometryMisses, 0);
        EXPECT_GT(b.geometry.resident, 0);
        EXPECT_EQ(a.geometryTriangles, b.geometryTriangles);
        const metrics::ImageComparison c = metrics::compareImages(display::gl::foldoutOf(display, b.images),
                                                                  display::gl::foldoutOf(display, a.images));
        EXPECT_TRUE(c.passes()) << c.describe();
    }
    EXPECT_GE(frames, 6);
}

// The warp pass draws cell objects from the shared buffers, which paging empties: refused.
TEST_F(GeometryPagingTest, WarpTransitionWithPagingIsRefusedWithAMessage) {
    const SmallPlant& scene = twoCells();
    const display::Display display = testDisplay(16);
    walkthrough::gl::WalkthroughOptions options;
    options.geometryBudgetMB = 1.0;
    options.transition = walkthrough::Transition::Warp;
    EXPECT_THAT(
        [&] {
            walkthrough::gl::Walkthrough w(scene.scene, scene.description, display, *context, scene.walls, options);
        },
        ::testing::ThrowsMessage<Error>(::testing::HasSubstr("expected transition blend, got warp")));
}

}  // namespace
}  // namespace cavewall::testing
