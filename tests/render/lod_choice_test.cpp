// Levels of detail for a frame (render/lod_choice.h): pixels per unit of error, the level
// chosen per object over all views, and what the views' render lists then submit.
//
// Scene: a finely tessellated cylinder (radius 0.5 m, height 1 m, 720 segments, welded as the
// loader welds) in front of the one-screen display (2 m screen 1 m from the eye, 256 x 256
// pixels, so 128 px per metre on the screen).
#include "display/display.h"
#include "render/lod_choice.h"
#include "render/render_list.h"
#include "scenes/mesh_optimize.h"
#include "scenes/primitives.h"
#include "tests/render/render_test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::render {
namespace {

constexpr int kPixels = 256;

scenes::Scene cylinderScene(glm::dvec3 centre) {
    scenes::Scene scene;
    scenes::Mesh m = scenes::makeCylinder(0.5f, 1.0f, 720, glm::vec4(1.0f));
    scenes::weldVertices(m);
    scenes::optimizeVertexOrder(m);
    scene.meshes.push_back(std::move(m));
    scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), centre), "cylinder");
    return scene;
}

std::vector<display::ScreenView> viewsFrom(glm::dvec3 eye) {
    static const display::Display d(testing::oneScreen(kPixels));
    return d.views({eye, glm::dquat(1, 0, 0, 0)});
}

// Triangles the views' render lists submit at `lod`'s levels.
std::size_t submitted(const RenderScene& scene, const std::vector<display::ScreenView>& views, const FrameLod& lod) {
    ListBuilder builder(scene);
    DrawFilter filter;
    filter.lodLevels = &lod.levels;
    std::size_t triangles = 0;
    for (const display::ScreenView& v : views) triangles += builder.build(v.frustum, glm::dmat4(1.0), filter).triangles;
    return triangles;
}

TEST(LodChoice, PixelsPerUnitIsTheScreensPixelsPerRadianOverTheDistance) {
    const display::ScreenView view = viewsFrom({0, 0, 0}).at(0);
    const display::ViewScreen screen = display::viewScreen(view.frustum, {kPixels, kPixels});
    // A 1 cm box on the axis 4 m away: at the screen centre (1 m away) 128 px per metre is 128 px
    // per radian; its nearest point is 3.995 m away, so one unit of error covers 128 / 3.995 px
    // (its corners lie 0.1° off the axis, where pixels per radian are 1 / cos² = 1 + 3e-6 times
    // more: within 1e-5 relative).
    scenes::Bounds box;
    box.add({-0.005, -0.005, -4.005});
    box.add({0.005, 0.005, -3.995});
    const glm::dmat4 viewFromWorld = view.frustum.viewFromFrame;
    const double p = pixelsPerUnit(box, 1.0, screen, viewFromWorld, 1.0);
    EXPECT_NEAR(p, 128.0 / 3.995, 1e-5 * 128.0 / 3.995);
    // Model and view scales multiply it.
    EXPECT_DOUBLE_EQ(pixelsPerUnit(box, 2.0, screen, viewFromWorld, 1.5), 3.0 * p);
    // An eye inside the bounds: no level but the full one will do.
    scenes::Bounds around;
    around.add({-1, -1, -1});
    around.add({1, 1, 1});
    EXPECT_EQ(pixelsPerUnit(around, 1.0, screen, viewFromWorld, 1.0), INFINITY);
}

TEST(LodChoice, WithoutLevelChainsEverythingIsLevelZero) {
    const scenes::Scene scene = cylinderScene({0.1, -0.6, -4});
    const RenderScene rs(scene, false);
    const FrameLod lod = chooseLods(rs, viewsFrom({0, 0, 0}), glm::dmat4(1.0), {}, 1.0);
    EXPECT_EQ(lod.levels, std::vector<int>(1, 0));
    EXPECT_EQ(lod.maxErrorPx, 0.0);
    EXPECT_EQ(submitted(rs, viewsFrom({0, 0, 0}), lod), scene.meshes[0].triangleCount());
}

TEST(LodChoice, TheListsSubmitThePredictedTrianglesWithinTheTolerance) {
    const scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    const RenderScene rs(scene, true);
    ASSERT_GT(rs.levelCount(0), 2);
    const std::vector<display::ScreenView> one = viewsFrom({0, 0, 0});
    for (double tolerance : {0.5, 1.0, 3.0}) {
        SCOPED_TRACE(tolerance);
        const FrameLod lod = chooseLods(rs, one, glm::dmat4(1.0), {}, tolerance);
        EXPECT_GT(lod.levels[0], 0);  // 2880 triangles far finer than a pixel: a coarser level
        EXPECT_LE(lod.maxErrorPx, tolerance);
        EXPECT_EQ(lod.tolerancePx, tolerance);
        EXPECT_EQ(submitted(rs, one, lod), lod.triangles);
        // A view drawing it twice (both eyes) submits it twice, at the same level.
        const std::vector<display::ScreenView> twice{one[0], one[0]};
        const FrameLod both = chooseLods(rs, twice, glm::dmat4(1.0), {}, tolerance);
        EXPECT_EQ(both.levels, lod.levels);
        EXPECT_EQ(both.triangles, 2 * lod.triangles);
    }
}

TEST(LodChoice, OneLevelForAllViewsTheFinestAnyViewNeeds) {
    const scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    const RenderScene rs(scene, true);
    // The same screen from 2 m further back: 3 m from the screen its pixels subtend a third of
    // the angle, so the cylinder (5 m instead of 3 m away) covers 3 x 3 / 5 = 1.8 times the
    // pixels per unit and needs a finer level.
    const display::ScreenView wide = viewsFrom({0, 0, 0}).at(0), narrow = viewsFrom({0, 0, 2}).at(0);
    int finer = 0;
    for (double tolerance : {0.02, 0.05, 0.1, 0.2, 0.5, 1.0}) {
        SCOPED_TRACE(tolerance);
        auto levelFor = [&](const std::vector<display::ScreenView>& views) {
            return chooseLods(rs, views, glm::dmat4(1.0), {}, tolerance).levels[0];
        };
        const int wideAlone = levelFor({wide}), narrowAlone = levelFor({narrow});
        EXPECT_LE(narrowAlone, wideAlone);
        finer += narrowAlone < wideAlone ? 1 : 0;
        EXPECT_EQ(levelFor({wide, narrow}), narrowAlone);
        EXPECT_EQ(levelFor({narrow, wide}), narrowAlone);
    }
    EXPECT_GT(finer, 0);  // else the views never disagreed and the test proves nothing
}

TEST(LodChoice, ABudgetRaisesTheToleranceUntilTheTrianglesFitOrFlagsItCannot) {
    const scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    const RenderScene rs(scene, true);
    const std::vector<display::ScreenView> views = viewsFrom({0, 0, 0});
    const FrameLod free = chooseLods(rs, views, glm::dmat4(1.0), {}, 0.5);
    EXPECT_FALSE(free.overBudget);
    // Half the unbudgeted count: the tolerance rises until the chosen level fits.
    const std::size_t budget = free.triangles / 2;
    const FrameLod capped = chooseLods(rs, views, glm::dmat4(1.0), {}, 0.5, budget);
    EXPECT_LE(capped.triangles, budget);
    EXPECT_GT(capped.tolerancePx, 0.5);
    EXPECT_LE(capped.maxErrorPx, capped.tolerancePx);
    EXPECT_EQ(submitted(rs, views, capped), capped.triangles);
    // A budget below the coarsest level cannot be met: flagged, coarsest level drawn.
    const FrameLod impossible = chooseLods(rs, views, glm::dmat4(1.0), {}, 0.5, 1);
    EXPECT_TRUE(impossible.overBudget);
    EXPECT_EQ(impossible.levels[0], rs.levelCount(0) - 1);
    // A cap on the tolerance keeps finer levels than the budget asks for.
    const FrameLod held = chooseLods(rs, views, glm::dmat4(1.0), {}, 0.5, 1, capped.tolerancePx);
    EXPECT_TRUE(held.overBudget);
    EXPECT_LE(held.tolerancePx, capped.tolerancePx);
    EXPECT_LE(held.levels[0], capped.levels[0]);
}

TEST(LodChoice, ObjectsNoViewDrawsStayAtLevelZeroAndCostNothing) {
    scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 5)), "behind");
    scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, -0.6, -4)), "filtered out");
    const RenderScene rs(scene, true);
    const std::vector<int> firstTwo{0, 1};
    DrawFilter filter;
    filter.objects = &firstTwo;
    const std::vector<display::ScreenView> views = viewsFrom({0, 0, 0});
    const FrameLod lod = chooseLods(rs, views, glm::dmat4(1.0), filter, 1.0);
    EXPECT_GT(lod.levels[0], 0);
    EXPECT_EQ(lod.levels[1], 0);  // culled
    EXPECT_EQ(lod.levels[2], 0);  // not in the filter
    EXPECT_EQ(lod.triangles, rs.indexCount(0, lod.levels[0]) / 3);
}

// A wall texture's levels (chooseFrustumLods): the wall quad is the screen, the sampling point
// the eye, the texture's texels the pixels. The display's screen (2 m wide, 1 m away, 256 px)
// as a quad gives the same frustum as the display view, so the choice equals chooseLods's.
TEST(LodChoice, AWallTexturesLevelsAreThoseOfItsFrustumAsAOneScreenView) {
    const scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    const RenderScene rs(scene, true);
    const display::ScreenView view = viewsFrom({0, 0, 0}).at(0);
    for (double tolerance : {0.25, 0.5, 1.0}) {
        SCOPED_TRACE(tolerance);
        const FrameLod wall = chooseFrustumLods(rs, view.frustum, {kPixels, kPixels}, {}, tolerance);
        const FrameLod display = chooseLods(rs, {view}, glm::dmat4(1.0), {}, tolerance);
        EXPECT_EQ(wall.levels, display.levels);
        EXPECT_EQ(wall.maxErrorPx, display.maxErrorPx);
        EXPECT_LE(wall.maxErrorPx, tolerance);
    }
}

TEST(LodChoice, AWallTextureOfMoreTexelsDrawsFinerLevelsWithinHalfATexel) {
    const scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    const RenderScene rs(scene, true);
    const display::OffAxisFrustum frustum =
        display::offAxisFrustum({{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}}, {0, 0, 0}, {0.05, INFINITY});
    // The error in texels grows with the texel count: 64 texels across allow a coarser level
    // than 1024 (16 times the texels per radian).
    const FrameLod coarse = chooseFrustumLods(rs, frustum, {64, 64}, {}, 0.5);
    const FrameLod fine = chooseFrustumLods(rs, frustum, {1024, 1024}, {}, 0.5);
    EXPECT_GT(coarse.levels[0], fine.levels[0]);
    EXPECT_LE(coarse.maxErrorPx, 0.5);
    EXPECT_LE(fine.maxErrorPx, 0.5);
    // The chosen level is the coarsest within half a texel: its error in texels is at most 0.5,
    // the next level's (if any) more.
    const scenes::MeshLod& lod = rs.lods()[0];
    const double perUnit = pixelsPerUnit(rs.objects()[0].worldBounds, rs.modelStretch(0),
                                         display::viewScreen(frustum, {64, 64}), frustum.viewFromFrame, 1.0);
    const int level = coarse.levels[0];
    EXPECT_LE(lod.levels[level].error * perUnit, 0.5);
    if (level + 1 < static_cast<int>(lod.levels.size())) {
        EXPECT_GT(lod.levels[level + 1].error * perUnit, 0.5);
    }
}

TEST(LodChoice, AWallTextureLeavesObjectsOutsideItsFrustumAtLevelZero) {
    scenes::Scene scene = cylinderScene({0.1, -0.6, -3});
    scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 5)), "behind the sampling point");
    scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(40, 0, -3)), "beside the wall");
    const RenderScene rs(scene, true);
    const display::OffAxisFrustum frustum =
        display::offAxisFrustum({{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}}, {0, 0, 0}, {0.05, INFINITY});
    const FrameLod lod = chooseFrustumLods(rs, frustum, {128, 128}, {}, 0.5);
    EXPECT_GT(lod.levels[0], 0);
    EXPECT_EQ(lod.levels[1], 0);
    EXPECT_EQ(lod.levels[2], 0);
    EXPECT_EQ(lod.triangles, rs.indexCount(0, lod.levels[0]) / 3);  // only the one in view counts
}

}  // namespace
}  // namespace cavewall::render
