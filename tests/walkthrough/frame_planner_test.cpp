// The frame planner (walkthrough/frame_planner.h) without GL: residency is a plain set of texture ids,
// time is FrameInput::time, so fallbacks and the warp-morph are tested frame by frame.
//
// Scene: the hall of test_scenes.h (wall "middle" on z = 0 from x = -6 to 6, 3 m high, facing
// cell 0 "front", z > 0) with a floor (structure), a box in each cell and nothing else. The
// viewer stands in the front cell; the CAVE (cave4) faces -z, towards the wall, unless turned.
#include "tests/walls/test_scenes.h"

#include "config/display_config.h"
#include "scenes/region.h"
#include "walls/angular_error.h"
#include "walls/depth_wall.h"
#include "walkthrough/frame_planner.h"
#include "walls/wall_setup.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace cavewall::walkthrough {
namespace {

// cave4 drawn mono, one view per screen from the head (the preset is stereo).
config::DisplayConfig monoCave4() {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    c.stereo = config::StereoMode::Mono;
    return c;
}

using namespace walls;

scenes::Object object(const char* name, scenes::Role role, glm::dvec3 min, glm::dvec3 max, int cell) {
    scenes::Object o;
    o.name = name;
    o.role = role;
    o.cell = cell;
    o.worldBounds.add(min);
    o.worldBounds.add(max);
    return o;
}

scenes::Scene hallScene() {
    scenes::Scene s;
    s.name = "hall";
    s.objects.push_back(object("floor", scenes::Role::Structure, {-6, 0, -10}, {6, 0, 10}, -1));
    s.objects.push_back(object("front box", scenes::Role::Content, {-1, 0, 4}, {1, 2, 6}, 0));
    s.objects.push_back(object("back box", scenes::Role::Content, {-2, 0, -7}, {2, 2.5, -3}, 1));
    return s;
}

using TextureSet = std::vector<std::pair<int, double>>;

class FramePlannerTest : public ::testing::Test {
protected:
    const scenes::SceneDescription description = testing::hall();
    const scenes::Scene scene = hallScene();
    const display::Display display{monoCave4()};

    WallSetup setup(double alphaDeg) const {
        PlanOptions options;
        options.alphaDeg = alphaDeg;
        return prepareWalls(scene, description, options);
    }
    // The CAVE's head (0, 1.7, 0) at world `eye`, turned by `yaw` about +Y (0: facing -z).
    static FrameInput at(glm::dvec3 eye, double time = 0.0, double yaw = 0.0) {
        FrameInput in;
        in.time = time;
        in.worldFromCave =
            glm::rotate(glm::translate(glm::dmat4(1.0), eye - glm::dvec3(0, 1.7, 0)), yaw, glm::dvec3(0, 1, 0));
        return in;
    }
    std::vector<display::ScreenView> views(const FrameInput& in) const { return display.views(in.head); }
    // One frame: requests, then the plan against `resident` (nullptr: everything resident).
    FramePlan frame(FramePlanner& planner, const FrameInput& in, const std::set<int>* resident = nullptr) const {
        planner.requests(in, views(in));
        return planner.plan([resident](int id) { return !resident || resident->count(id) > 0; });
    }
    static const WallState& row(const FramePlan& p) {
        EXPECT_EQ(p.walls.size(), 1u);
        return p.walls.front();
    }
    static bool drawsObject(const FramePlan& p, int object) {
        return std::find(p.objects.begin(), p.objects.end(), object) != p.objects.end();
    }
    // The selection's blend of the wall at eye (x, 1.7, z).
    static WallBlend blendAt(const FrameSelector& selector, double x, double z) {
        const FrameSelection s = selector.select({x, 1.7, z});
        return s.walls.empty() ? WallBlend{} : s.walls.front();
    }
};

constexpr int kBackBox = 2;  // hallScene's object in the cell behind the wall

// Geometry paging (walls/geometry_pager.h): while the back cell's geometry is not resident, a
// wall blending into it shows its textures alone (renormalised, counted); in its geometry zone,
// where no texture is proven, the cell is drawn anyway and reported as forced.
// An object standing in several cells (a wall between two rooms, scenes/cell_assignment.h) is
// drawn with each of them; structure and objects of no cell with any.
TEST(ObjectsOfCells, AnObjectIsDrawnWithAnyOfItsCells) {
    scenes::Scene s;
    s.objects.push_back(object("room 0 chair", scenes::Role::Content, {0, 0, 0}, {1, 1, 1}, 0));
    s.objects.push_back(object("wall of rooms 1 and 2", scenes::Role::Content, {0, 0, 0}, {1, 3, 1}, 1));
    s.objects.back().moreCells = {2};
    s.objects.push_back(object("room 2 desk", scenes::Role::Content, {0, 0, 0}, {1, 1, 1}, 2));
    s.objects.push_back(object("nowhere", scenes::Role::Content, {0, 0, 0}, {1, 1, 1}, -1));
    EXPECT_EQ(objectsOfCells(s, {false, false, true}), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(objectsOfCells(s, {false, true, false}), (std::vector<int>{1, 3}));
    EXPECT_EQ(objectsOfCells(s, {true, false, false}), (std::vector<int>{0, 3}));
}

TEST_F(FramePlannerTest, ACellNotResidentKeepsTheWallTexturesUnlessNoneIsProven) {
    const WallSetup walls = setup(10.0);
    const FrameSelector selector(walls.plan, walls.table, description);
    std::optional<glm::dvec3> strip, zone;  // blending textures and geometry; geometry alone
    for (double z = 9.5; z > 0.05; z -= 0.05) {
        const WallBlend b = blendAt(selector, 0.0, z);
        if (!strip && !b.textures.empty() && b.geometryWeight > 0.0 && b.geometryWeight < 1.0)
            strip = glm::dvec3(0, 1.7, z);
        if (!zone && b.textures.empty()) zone = glm::dvec3(0, 1.7, z);
    }
    ASSERT_TRUE(strip && zone);
    const std::set<int> everything = [&] {
        std::set<int> ids;
        for (const Texture& t : walls.plan.textures) ids.insert(t.id);
        return ids;
    }();
    auto frameWithCells = [&](FramePlanner& planner, glm::dvec3 eye, bool backResident) {
        const FrameInput in = at(eye);
        planner.requestCells(true);
        const TextureRequests r = planner.requests(in, views(in));
        EXPECT_EQ(std::count(r.cellsNow.begin(), r.cellsNow.end(), 0), 1);    // the viewer's cell
        EXPECT_EQ(std::count(r.cellsSoon.begin(), r.cellsSoon.end(), 1), 1);  // one wall away
        return planner.plan([&](int id) { return everything.count(id) > 0; },
                            [&](int cell) { return cell == 0 || backResident; });
    };
    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    const FramePlan resident = frameWithCells(planner, *strip, true);
    EXPECT_TRUE(drawsObject(resident, kBackBox));
    EXPECT_GT(row(resident).geometryWeight, 0.0);
    EXPECT_EQ(resident.geometryMisses, 0);

    const FramePlan missing = frameWithCells(planner, *strip, false);
    EXPECT_FALSE(drawsObject(missing, kBackBox));
    EXPECT_EQ(row(missing).geometryWeight, 0.0);
    EXPECT_TRUE(row(missing).fallback);
    double sum = 0.0;
    for (const auto& [id, weight] : row(missing).textures) sum += weight;
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_EQ(missing.geometryMisses, 1);
    EXPECT_TRUE(missing.geometryForced.empty());
    EXPECT_EQ(missing.texturesOverAlpha, 0);  // the kept textures are the proven ones

    FramePlanner fresh(scene, description, display, &walls, Transition::Blend, 0.5);
    const FramePlan forced = frameWithCells(fresh, *zone, false);
    EXPECT_TRUE(drawsObject(forced, kBackBox));  // nothing proven to show instead
    EXPECT_EQ(forced.geometryForced, std::vector<int>{1});
    EXPECT_EQ(forced.geometryMisses, 0);
}

// The control (drawTextures off, the demo's "cells without textures"): at every eye along the
// hall it draws exactly the objects the walls draw with every texture resident, requests and
// draws no texture, and reports no texture error; where the walls blend into the cell behind,
// so does the control (the same geometry weight).
TEST_F(FramePlannerTest, TheControlDrawsTheWallsCellsAndNoTexture) {
    const WallSetup walls = setup(10.0);
    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    FramePlanner control(scene, description, display, &walls, Transition::Blend, 0.5);
    control.drawTextures(false);
    int textured = 0, blended = 0;
    for (double z = 9.5; z > 0.05; z -= 0.05) {  // finer than the 0.2 m blend strips
        SCOPED_TRACE("eye z = " + std::to_string(z));
        const FrameInput in = at({0.0, 1.7, z}, 10.0 - z);
        const FramePlan w = frame(planner, in);
        const TextureRequests r = control.requests(in, views(in));
        EXPECT_TRUE(r.now.empty());
        EXPECT_TRUE(r.soon.empty());
        const FramePlan c = control.plan([](int) { return true; });
        EXPECT_EQ(c.objects, w.objects);
        EXPECT_EQ(c.geometryCells, w.geometryCells);
        EXPECT_TRUE(c.wallDraws.empty());
        EXPECT_EQ(c.maxErrorDeg, 0.0);
        ASSERT_EQ(c.walls.size(), w.walls.size());
        EXPECT_TRUE(row(c).textures.empty());
        EXPECT_EQ(row(c).geometryWeight, row(w).geometryWeight);
        textured += !w.wallDraws.empty();
        blended += row(w).geometryWeight > 0.0 && row(w).geometryWeight < 1.0;
    }
    EXPECT_GT(textured, 50);  // the walls draw textures over most of the hall ...
    EXPECT_GT(blended, 0);    // ... and blend into the cell behind somewhere
}

TEST_F(FramePlannerTest, AMissingTextureKeepsThePreviousOneWithinAlphaElseTheGeometry) {
    const WallSetup walls = setup(10.0);
    const FrameSelector selector(walls.plan, walls.table, description);
    // `first`: one texture, no geometry; `next`: along the wall, the first point where that
    // texture is no longer drawn but still within alpha; `far`: where it is beyond alpha.
    std::optional<glm::dvec3> first, next, far;
    for (double z = 9.5; z > 0.5 && !first; z -= 0.25)
        for (double x = -5.5; x < 5.5 && !first; x += 0.25) {
            const WallBlend b = blendAt(selector, x, z);
            if (b.textures.size() == 1 && b.geometryWeight == 0.0) first = glm::dvec3(x, 1.7, z);
        }
    ASSERT_TRUE(first);
    const int t1 = blendAt(selector, first->x, first->z).textures[0].first;
    const Texture& texture = walls.plan.textures[t1];
    ASSERT_EQ(texture.id, t1);
    const PlannedWall& wall = walls.plan.walls[0];
    const double alpha = glm::radians(walls.plan.alphaDeg);
    for (double x = -5.5; x < 5.5; x += 0.05) {
        const glm::dvec3 eye(x, 1.7, first->z);
        const WallBlend b = blendAt(selector, x, first->z);
        const bool without = std::none_of(b.textures.begin(), b.textures.end(), [&](auto& t) { return t.first == t1; });
        if (!without || b.textures.empty()) continue;
        const double error = maxAngularError(eye, texture.samplingPoint, wall.quad, wall.depthBehind);
        if (error <= alpha && !next) next = eye;
        if (error > alpha + 1e-6) far = eye;
    }
    ASSERT_TRUE(next) << "no neighbouring zone where the first texture is still within alpha";
    ASSERT_TRUE(far) << "no zone where the first texture is beyond alpha";

    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    planner.portalCulling(true);  // FramePlan::portals filled (checked in expectGeometry)
    const std::set<int> none, onlyFirst{t1};
    // The one wall drawn as geometry for want of a texture: the cell behind drawn, no quad.
    auto expectGeometry = [&](const FramePlan& plan, const char* name) {
        SCOPED_TRACE(name);
        EXPECT_TRUE(row(plan).fallback);
        EXPECT_TRUE(row(plan).textures.empty());
        EXPECT_EQ(row(plan).geometryWeight, 1.0);
        EXPECT_TRUE(plan.geometryCells[1]);
        EXPECT_TRUE(drawsObject(plan, kBackBox));
        EXPECT_TRUE(plan.wallDraws.empty());
        EXPECT_EQ(plan.geometryFallbacks, 1);
        // Portal culling: the cell behind is seen through the openings of the eye's cell, the
        // wall among them (seen from its front); the floor and the eye's cell without test.
        ASSERT_EQ(plan.portals.objectSet.size(), scene.objects.size());
        EXPECT_EQ(plan.portals.objectSet[0], -1);
        EXPECT_EQ(plan.portals.objectSet[1], -1);
        const int set = plan.portals.objectSet[kBackBox];
        ASSERT_GE(set, 0);
        std::vector<display::ScreenQuad> through;
        for (int c : plan.portals.sets[set])
            for (int p : plan.portals.chains[c]) through.push_back(plan.portals.portals.at(p));
        const display::ScreenQuad front = quadSeenFrom(wall.quad, 0);
        EXPECT_NE(std::find(through.begin(), through.end(), front), through.end());
    };
    // Cold: nothing resident and nothing drawn before: geometry, the cell behind drawn.
    expectGeometry(frame(planner, at(*first), &none), "cold");
    const FramePlan warm = frame(planner, at(*first), &onlyFirst);
    EXPECT_FALSE(row(warm).fallback);
    EXPECT_EQ(row(warm).textures, (TextureSet{{t1, 1.0}}));
    EXPECT_FALSE(warm.geometryCells[1]);
    EXPECT_FALSE(drawsObject(warm, kBackBox));
    EXPECT_EQ(warm.geometryFallbacks, 0);
    // The next zone's texture is missing: the wall keeps the one it drew (within alpha there).
    const FramePlan kept = frame(planner, at(*next), &onlyFirst);
    EXPECT_TRUE(row(kept).fallback);
    EXPECT_EQ(row(kept).textures, (TextureSet{{t1, 1.0}}));
    ASSERT_EQ(kept.wallDraws.size(), 1u);
    EXPECT_EQ(kept.wallDraws[0].textures, (TextureSet{{t1, 1.0}}));
    EXPECT_FALSE(drawsObject(kept, kBackBox));
    EXPECT_EQ(kept.geometryFallbacks, 0);  // a fallback, but to the previous texture
    // Far along the wall the old texture would be wrong by more than alpha: geometry instead.
    const FramePlan jumped = frame(planner, at(*far), &onlyFirst);
    expectGeometry(jumped, "jumped");
    EXPECT_EQ(jumped.maxErrorDeg, 0.0);  // nothing textured, nothing wrong
}

TEST_F(FramePlannerTest, WallsOutOfViewAreNeitherRequestedNorDrawnButKeepARow) {
    const WallSetup walls = setup(10.0);
    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    const glm::dvec3 eye(0.0, 1.7, 8.0);  // a texture zone: something would be requested
    const TextureRequests facing = planner.requests(at(eye), views(at(eye)));
    EXPECT_FALSE(facing.now.empty());
    planner.plan([](int) { return true; });
    // Turned round (the CAVE's front towards +z) and rendering the front screen only: the wall
    // is behind the viewer, outside every rendered view.
    const FrameInput turned = at(eye, 0.0, glm::pi<double>());
    std::vector<display::ScreenView> front = views(turned);
    std::erase_if(front, [&](const display::ScreenView& v) { return display.screens()[v.screen].name != "front"; });
    ASSERT_FALSE(front.empty());
    const TextureRequests away = planner.requests(turned, front);
    EXPECT_TRUE(away.now.empty());
    EXPECT_TRUE(away.soon.empty());
    const FramePlan p = planner.plan([](int) { return true; });
    EXPECT_TRUE(p.wallDraws.empty());
    ASSERT_EQ(p.walls.size(), 1u);
    EXPECT_EQ(p.walls[0].wall, 0);
    EXPECT_TRUE(p.walls[0].textures.empty());
    EXPECT_FALSE(p.walls[0].fallback);
}

// Prefetching along the way: an eye moving at 40 m/s towards the wall from 5 m before it asks
// soon for what it will draw 0.125, 0.25 and 0.5 s ahead (5, 10 and 12 m on, at most: the
// last two in the back cell, through the wall), which the 1.5 m neighbours of a still eye at
// the same place do not reach; what it wants now is the same.
TEST_F(FramePlannerTest, AMovingEyePrefetchesWhatItWillDrawAlongItsWay) {
    const WallSetup walls = setup(10.0);
    const FrameSelector selector(walls.plan, walls.table, description);
    FramePlanner moving(scene, description, display, &walls, Transition::Blend, 0.5);
    FramePlanner still(scene, description, display, &walls, Transition::Blend, 0.5);
    const double z = 5.0;
    frame(moving, at({0.0, 1.7, z + 2.0 / 3.0}, 0.0));  // 2/3 m a frame at 60 Hz
    const FrameInput now = at({0.0, 1.7, z}, 1.0 / 60.0);
    const TextureRequests m = moving.requests(now, views(now));
    const TextureRequests s = still.requests(now, views(now));
    EXPECT_EQ(m.now, s.now);
    auto has = [](const std::vector<int>& v, int id) { return std::find(v.begin(), v.end(), id) != v.end(); };
    int ahead = 0, beyondNeighbours = 0;
    for (double metres : {5.0, 10.0, 12.0}) {
        const FrameSelection sel = selector.select({0.0, 1.7, z - metres});
        for (const std::vector<WallBlend>* blends : {&sel.walls, &sel.beyond})
            for (const WallBlend& b : *blends)
                for (const auto& [id, weight] : b.textures) {
                    ++ahead;
                    EXPECT_TRUE(has(m.soon, id)) << id << " " << metres << " m ahead";
                    beyondNeighbours += !has(s.soon, id) && !has(s.now, id);
                }
    }
    EXPECT_GT(ahead, 0);
    EXPECT_GT(beyondNeighbours, 0);
    // Standing still, nothing beyond the neighbours is asked for.
    const TextureRequests again = still.requests(now, views(now));
    EXPECT_EQ(again.soon, s.soon);
}

TEST_F(FramePlannerTest, AWarpMorphStartsOnASwitchLastsMorphSecondsThenEnds) {
    const WallSetup walls = setup(10.0);
    const FrameSelector selector(walls.plan, walls.table, description);
    std::optional<glm::dvec3> textured, geometry;
    for (double z = 9.5; z > 0.05; z -= 0.05) {
        const WallBlend b = blendAt(selector, 0.0, z);
        if (!textured && b.textures.size() == 1 && b.geometryWeight == 0.0) textured = glm::dvec3(0, 1.7, z);
        if (b.geometryWeight == 1.0) geometry = glm::dvec3(0, 1.7, z);
    }
    ASSERT_TRUE(textured && geometry);
    const glm::dvec3 samplingPoint =
        walls.plan.textures[blendAt(selector, 0.0, textured->z).textures[0].first].samplingPoint;
    const double morph = 0.5;
    FramePlanner planner(scene, description, display, &walls, Transition::Warp, morph);
    const FramePlan before = frame(planner, at(*textured, 0.0));
    EXPECT_EQ(before.wallDraws.size(), 1u);
    ASSERT_EQ(before.warpWalls.size(), 1u);  // structure warped into the texture, no morph
    EXPECT_EQ(before.warpWalls[0].cell, -1);
    EXPECT_TRUE(before.morphs.empty());
    // Texture -> geometry at t = 0.1: the morph runs for `morph` seconds of input time.
    for (double t : {0.1, 0.35, 0.5999}) {
        SCOPED_TRACE(t);
        const FramePlan p = frame(planner, at(*geometry, t));
        const double s = (t - 0.1) / morph;
        ASSERT_EQ(p.morphs.size(), 1u);
        EXPECT_EQ(p.morphs[0].phase, MorphPhase::ToGeometry);
        EXPECT_NEAR(p.morphs[0].share, s, 1e-12);
        ASSERT_EQ(p.warpWalls.size(), 1u);
        EXPECT_EQ(p.warpWalls[0].cell, 1);  // the cell behind, drawn warped ...
        EXPECT_FALSE(p.geometryCells[1]);   // ... and not by the scene renderer
        EXPECT_FALSE(drawsObject(p, kBackBox));
        // The viewpoint moves from the sampling point (s = 0) to the eye (s = 1).
        EXPECT_LT(glm::distance(p.warpWalls[0].samplingPoint, glm::mix(samplingPoint, *geometry, s)), 1e-9);
        EXPECT_TRUE(p.wallDraws.empty());
        EXPECT_TRUE(row(p).textures.empty());
        EXPECT_EQ(row(p).geometryWeight, 1.0);
    }
    const FramePlan after = frame(planner, at(*geometry, 0.7));  // past 0.5 s after the switch: ended
    EXPECT_TRUE(after.morphs.empty());
    EXPECT_TRUE(after.warpWalls.empty());
    EXPECT_TRUE(after.geometryCells[1]);
    EXPECT_TRUE(drawsObject(after, kBackBox));
    // Geometry -> texture at t = 1: a morph towards the sampling point.
    const FramePlan back = frame(planner, at(*textured, 1.0));
    ASSERT_EQ(back.morphs.size(), 1u);
    EXPECT_EQ(back.morphs[0].phase, MorphPhase::ToTexture);
    EXPECT_LT(glm::distance(back.warpWalls.at(0).samplingPoint, *textured), 1e-9);  // s = 0: the eye
    EXPECT_TRUE(frame(planner, at(*textured, 1.6)).morphs.empty());
}

TEST_F(FramePlannerTest, AnIllConditionedWarpFallsBackToGeometryAndIsCounted) {
    // Even at alpha 90° the plan keeps a geometry zone in front of the wall; without it the
    // texture zone reaches the wall plane (as for a wall seen edge-on from afar) and only the
    // guard stands between an eye 0.1 mm from the plane and a singular warp. Its condition
    // grows like 3 m / distance (display/warp.h): about 3e4 at 0.1 mm, over kMaxWarpCondition
    // = 1e4; about 60 at 5 cm.
    WallSetup walls = setup(90.0);
    for (WallSide& side : walls.plan.sides) side.hasGeometry = false;
    const FrameSelector selector(walls.plan, walls.table, description);
    const WallBlend b = blendAt(selector, 0.0, 1e-4);
    ASSERT_FALSE(b.textures.empty());
    ASSERT_LT(b.geometryWeight, 0.5);
    FramePlanner warp(scene, description, display, &walls, Transition::Warp, 0.5);
    const FramePlan p = frame(warp, at({0.0, 1.7, 1e-4}));
    EXPECT_EQ(p.warpFallbacks, 1);
    EXPECT_TRUE(row(p).fallback);
    EXPECT_TRUE(row(p).textures.empty());
    EXPECT_EQ(row(p).geometryWeight, 1.0);
    EXPECT_TRUE(p.geometryCells[1]);
    EXPECT_TRUE(p.wallDraws.empty());
    EXPECT_TRUE(p.warpWalls.empty());
    // 5 cm from the plane the warp is fine; the blend transition never warps.
    EXPECT_EQ(frame(warp, at({0.0, 1.7, 0.05}), nullptr).warpFallbacks, 0);
    FramePlanner blend(scene, description, display, &walls, Transition::Blend, 0.5);
    const FramePlan blended = frame(blend, at({0.0, 1.7, 1e-4}));
    EXPECT_EQ(blended.warpFallbacks, 0);
    EXPECT_FALSE(row(blended).textures.empty());
}

TEST_F(FramePlannerTest, DrawnWeightsSumToOneAndErrorsAreTheExactAngularError) {
    const WallSetup walls = setup(10.0);
    const PlannedWall& wall = walls.plan.walls[0];
    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    int textured = 0, blended = 0;
    for (double z = 0.3; z < 10.0; z += 0.37)
        for (double x = -5.7; x < 6.0; x += 0.53) {
            const glm::dvec3 eye(x, 1.7, z);
            const FramePlan p = frame(planner, at(eye));
            const WallState& s = row(p);
            double sum = s.geometryWeight, worst = 0.0;
            for (const auto& [id, weight] : s.textures) {
                sum += weight;
                worst = std::max(
                    worst, maxAngularError(eye, walls.plan.textures[id].samplingPoint, wall.quad, wall.depthBehind));
            }
            // Continuous weights meet at zone borders; 1e-12 covers their rounding.
            EXPECT_NEAR(sum, 1.0, 1e-12) << "eye " << x << ", " << z;
            EXPECT_EQ(s.errorDeg, glm::degrees(worst));
            EXPECT_EQ(p.maxErrorDeg, glm::degrees(worst));
            // Everything resident: each drawn texture is within the plan's alpha.
            EXPECT_LE(worst, glm::radians(walls.plan.alphaDeg) + kErrorTolerance);
            if (s.textures.empty()) continue;
            ++textured;
            blended += s.textures.size() > 1 || s.geometryWeight > 0.0;
            ASSERT_EQ(p.wallDraws.size(), 1u);
            double drawn = 0.0;
            for (const auto& [id, weight] : p.wallDraws[0].textures) drawn += weight;
            EXPECT_NEAR(drawn, 1.0 - s.geometryWeight, 1e-12);
            EXPECT_LE(p.wallDraws[0].textures.size(), static_cast<std::size_t>(kMaxWallTextures));
            EXPECT_GT(p.maxErrorPixels, 0.0);
        }
    // The sweep crosses texture zones and blend strips, not only one of them.
    EXPECT_GT(textured, 20);
    EXPECT_GT(blended, 5);
}

// The error in pixels is each wall's angle at the pixels per degree of the screens it appears
// on. From (0, 1.7, 9) facing -z, the wall (z = 0, x in [-6, 6], y in [0, 3]) shows on cave4's
// front screen only: the side screens see directions with |x| > |z| and the floor what lies
// within 1.5 m of the feet. The front screen, 1.5 m from the head with its foot point on it,
// has 1.5 m / (3 m / 1024) = 512 pixels per radian there, 8.94 per degree: the floor's 1.7 m
// would give 10.13, and the old figure, the most pixels per radian anywhere on any screen (the
// front screen's corner 1.5 m aside and 1.7 m down: 7.39 / (1.5 * 3 / 1024)), 29.35.
TEST_F(FramePlannerTest, ErrorInPixelsIsAtThePixelsPerDegreeOfTheScreensShowingTheWall) {
    const WallSetup walls = setup(10.0);
    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    const FramePlan p = frame(planner, at({0.0, 1.7, 9.0}));
    ASSERT_FALSE(row(p).textures.empty());
    ASSERT_GT(p.maxErrorDeg, 0.0);
    const double perDegree = 512.0 * glm::pi<double>() / 180.0;
    EXPECT_NEAR(perDegree, 8.936, 1e-3);
    EXPECT_NEAR(p.maxErrorPixels, p.maxErrorDeg * perDegree, 1e-9 * p.maxErrorPixels);
}

// Depth walls (PlanOptions::wallKind): the error reported and counted over alpha is the depth
// walls' own bound (the smaller of depthEyeBound and depthSegmentEyeBound over the wall's depth
// span, from the boxes: 3 .. 7 m behind the plane), not the flat one.
TEST_F(FramePlannerTest, DepthWallsReportTheirOwnBound) {
    PlanOptions options;
    options.wallKind = WallKind::Depth;
    const WallSetup walls = prepareWalls(scene, description, options);
    const PlannedWall& wall = walls.plan.walls[0];
    EXPECT_EQ(wall.depthNear, 3.0);
    EXPECT_EQ(wall.depthBehind, 7.0);
    FramePlanner planner(scene, description, display, &walls, Transition::Blend, 0.5);
    int textured = 0, belowFlat = 0;
    for (double z = 0.3; z < 10.0; z += 0.37)
        for (double x = -5.7; x < 6.0; x += 0.53) {
            const glm::dvec3 eye(x, 1.7, z);
            const FramePlan p = frame(planner, at(eye));
            const WallState& s = row(p);
            double worst = 0.0, flat = 0.0;
            for (const auto& [id, weight] : s.textures) {
                const Texture& t = walls.plan.textures[id];
                const double h = texelDiagonal(wall.quad, t.resolution);
                worst = std::max(worst, std::min(depthEyeBound(eye, t.samplingPoint, wall.quad, {3.0, 7.0}, h),
                                                 depthSegmentEyeBound(eye, t.samplingPoint, wall.quad, {3.0, 7.0}, h)));
                flat = std::max(flat, maxAngularError(eye, t.samplingPoint, wall.quad, wall.depthBehind));
            }
            EXPECT_EQ(s.errorDeg, glm::degrees(worst));
            EXPECT_EQ(p.texturesOverAlpha, 0);
            EXPECT_LE(worst, glm::radians(walls.plan.alphaDeg));
            if (s.textures.empty()) continue;
            ++textured;
            belowFlat += worst < flat;
        }
    EXPECT_GT(textured, 20);
    EXPECT_GT(belowFlat, textured / 2);  // a narrow span: mostly below the flat error
}

TEST_F(FramePlannerTest, WithoutWallsEverythingIsGeometryAndNothingIsRequested) {
    FramePlanner planner(scene, description, display, nullptr, Transition::Blend, 0.5);
    EXPECT_FALSE(planner.hasWalls());
    const FrameInput in = at({1.0, 1.7, -4.0});
    const TextureRequests r = planner.requests(in, views(in));
    EXPECT_TRUE(r.now.empty() && r.soon.empty());
    const FramePlan p = planner.plan([](int) { return false; });
    EXPECT_EQ(p.cell, scenes::findCell(description.cells, {1.0, 1.7, -4.0}));  // reported only
    EXPECT_EQ(p.objects, (std::vector<int>{0, 1, 2}));
    EXPECT_TRUE(p.walls.empty());
    EXPECT_NEAR(glm::distance(p.eyeWorld, glm::dvec3(1.0, 1.7, -4.0)), 0.0, 1e-12);
}

}  // namespace
}  // namespace cavewall::walkthrough
