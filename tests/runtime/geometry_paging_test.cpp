// Geometry paging by cell on the GPU (walls/gl/walkthrough.h, display/gl/scene_gpu.h): a cell's
// meshes live in buffers of their own, uploaded when the pager makes the cell resident and
// deleted when it evicts it, so the resident bytes reported are GPU bytes and go down on
// eviction; where every cell a frame needs is resident, the frame equals the unpaged one. The
// pager's policy is tested without GL in tests/walls/geometry_pager_test.cpp.
#include "tests/gl/gl_test_support.h"
#include "tests/runtime/runtime_fixture.h"

#include "config/error.h"
#include "display/gl/frame_images.h"
#include "display/gl/scene_renderer.h"
#include "scenes/image_compare.h"
#include "walls/geometry_pager.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <iostream>
#include <algorithm>
#include <numeric>

namespace cavewall::testing {
namespace {

constexpr double kMB = 1024.0 * 1024.0;

class GeometryPagingTest : public GlTest {};

// twoCells(): the red box is cell B's only paged object, the green box cell A's; the floors are
// structure (always resident, in the shared buffers). The GPU side alone: uploading and freeing
// cells moves the resident bytes by exactly the pager's sizes of those cells.
TEST_F(GeometryPagingTest, UploadingAndFreeingACellMovesTheGpuBytesByItsSize) {
    const SmallPlant& scene = twoCells();
    const std::vector<std::size_t> cellBytes = walls::cellGeometryBytes(scene.scene, 2);
    gl::RenderSettings settings;
    settings.pagedCells = 2;
    gl::SceneRenderer renderer(scene.scene, settings);
    gl::GpuScene& gpu = renderer.gpu();
    EXPECT_EQ(gpu.residentCellBytes(), 0u);
    const std::vector<std::vector<int>> meshes = gl::meshesByCell(scene.scene, 2);
    for (int c : {0, 1}) gpu.uploadCell(c, gl::packMeshes(scene.scene, nullptr, meshes[c]));
    EXPECT_TRUE(gpu.cellResident(0) && gpu.cellResident(1));
    EXPECT_EQ(gpu.residentCellBytes(), cellBytes[0] + cellBytes[1]);
    gpu.freeCell(0);
    EXPECT_FALSE(gpu.cellResident(0));
    EXPECT_EQ(gpu.residentCellBytes(), cellBytes[1]);
    // A cell's objects are not in the shared buffers: drawing them needs the cell.
    int redBox = -1;
    for (int i = 0; i < static_cast<int>(scene.scene.objects.size()); ++i)
        if (scene.scene.objects[i].name == "red box") redBox = i;
    ASSERT_GE(redBox, 0);
    EXPECT_EQ(gpu.setOf(redBox), 2);
    EXPECT_EQ(gpu.mesh(scene.scene.objects[redBox].mesh).indexCount, 0u);  // set 0: empty
    EXPECT_NE(gpu.mesh(2, scene.scene.objects[redBox].mesh, 0), nullptr);
    gpu.freeCell(1);
    EXPECT_EQ(gpu.mesh(2, scene.scene.objects[redBox].mesh, 0), nullptr);
    EXPECT_EQ(gpu.residentCellBytes(), 0u);
}

// Along the small plant's north aisle under a budget of about two cells: the walkthrough frees
// evicted cells on the GPU, so its resident bytes (FrameResult::geometry, frames.csv) are the
// GPU's and drop when the pager evicts more than it pages in.
TEST_F(GeometryPagingTest, TheWalkthroughFreesEvictedCellsOnTheGpu) {
    const SmallPlant& plant = smallPlant();
    std::vector<std::size_t> cellBytes =
        walls::cellGeometryBytes(plant.scene, static_cast<int>(plant.description.cells.size()));
    std::sort(cellBytes.rbegin(), cellBytes.rend());
    const display::Display display = testDisplay(32);
    gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    options.geometryBudgetMB = static_cast<double>(cellBytes[0] + cellBytes[1]) / kMB;
    gl::Walkthrough walkthrough(plant.scene, plant.description, display, *context, plant.walls, options);
    double previousMB = 0.0, peakMB = 0.0;
    long previousEvictions = 0, previousPageIns = 0;
    int drops = 0;
    for (double x = -36.0; x <= 36.0; x += 3.0) {
        walls::FrameInput in;
        in.worldFromCave = cavePlacedAt({x, 1.7, -10.0});
        const walls::FrameResult r = walkthrough.renderFrame(in);
        const long evicted = r.geometry.evictions - previousEvictions, paged = r.geometry.pageIns - previousPageIns;
        std::cout << "x = " << x << ": " << r.geometry.resident << " cells, " << r.geometry.residentMB * kMB
                  << " GPU bytes, +" << paged << " -" << evicted << "\n";
        EXPECT_EQ(r.geometryForced, 0);
        if (evicted > 0 && paged == 0) {
            EXPECT_LT(r.geometry.residentMB, previousMB);
        }
        drops += r.geometry.residentMB < previousMB;
        peakMB = std::max(peakMB, r.geometry.residentMB);
        previousMB = r.geometry.residentMB;
        previousEvictions = r.geometry.evictions;
        previousPageIns = r.geometry.pageIns;
    }
    EXPECT_GT(previousEvictions, 0);
    EXPECT_GT(drops, 0);
    std::cout << "peak " << peakMB << " MB of " << walls::modelGeometryBytes(plant.scene) / kMB << " MB\n";
}

// With every needed cell resident (synchronous paging, a budget for all of them) the paged
// renderer draws the same pixels as the one holding the whole model, in all three zones of the
// plant's wall N2|N3; only the opaque draw order within a batch may differ (grouped by cell),
// hence the golden tolerance rather than exact equality.
TEST_F(GeometryPagingTest, FramesEqualTheUnpagedOnesWhenTheNeededCellsAreResident) {
    const SmallPlant& plant = smallPlant();
    const display::Display display = testDisplay(64);
    gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    gl::Walkthrough whole(plant.scene, plant.description, display, *context, plant.walls, options);
    options.geometryBudgetMB = 64.0;
    gl::Walkthrough paged(plant.scene, plant.description, display, *context, plant.walls, options);
    int frames = 0;
    for (double x = -29.5; x < -20.0; x += 1.5, ++frames) {
        SCOPED_TRACE(x);
        walls::FrameInput in;
        in.worldFromCave = cavePlacedAt({x, 1.7, -10.0});
        in.readImages = true;
        const walls::FrameResult a = whole.renderFrame(in), b = paged.renderFrame(in);
        EXPECT_EQ(b.geometryMisses, 0);
        EXPECT_GT(b.geometry.resident, 0);
        EXPECT_EQ(a.geometryTriangles, b.geometryTriangles);
        const scenes::ImageComparison c =
            scenes::compareImages(gl::foldoutOf(display, b.images), gl::foldoutOf(display, a.images));
        EXPECT_TRUE(c.passes()) << c.describe();
    }
    EXPECT_GE(frames, 6);
}

// The warp pass draws cell objects from the shared buffers, which paging empties: refused.
TEST_F(GeometryPagingTest, WarpTransitionWithPagingIsRefusedWithAMessage) {
    const SmallPlant& scene = twoCells();
    const display::Display display = testDisplay(16);
    gl::WalkthroughOptions options;
    options.geometryBudgetMB = 1.0;
    options.transition = walls::Transition::Warp;
    EXPECT_THAT([&] { gl::Walkthrough w(scene.scene, scene.description, display, *context, scene.walls, options); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("expected transition blend, got warp")));
}

}  // namespace
}  // namespace cavewall::testing
