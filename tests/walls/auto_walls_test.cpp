#include "walls/auto_walls.h"

#include "config/error.h"
#include "scenes/generate.h"
#include "scenes/primitives.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace cavewall::walls {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A hall 40 m (x) by 10 m (z), 4 m high: a floor slab with its top at y = 0, a ceiling slab from
// y = 4, two long hall walls 0.1 m thick centred on z = +-5, and 1 m crates every 2 m along x in
// two rows (so every cut has a free gap within a metre) plus one crate astride x = 0.
scenes::Scene hall() {
    scenes::Scene s;
    s.name = "hall";
    auto box = [&](glm::dvec3 size, glm::dvec3 centre, const std::string& name) {
        s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), name);
    };
    box({40, 0.1, 10}, {0, -0.05, 0}, "floor");
    box({40, 0.1, 10}, {0, 4.05, 0}, "ceiling");
    box({40, 4, 0.1}, {0, 2, -5}, "wall-north");
    box({40, 4, 0.1}, {0, 2, 5}, "wall-south");
    for (int i = 0; i < 20; ++i)
        for (double z : {-2.5, 2.5})
            box({1, 1, 1}, {-19.0 + 2.0 * i, 0.5, z}, "crate " + std::to_string(i) + (z < 0 ? "n" : "s"));
    box({1, 1, 1}, {0.0, 0.5, 0.0}, "astride");
    return s;
}

// The description of a bare model file (validation wants the file to exist; the scene itself
// comes from hall()). One folder per test: ctest runs the tests in parallel processes, and a
// TempFolder empties its folder when it is made.
scenes::SceneDescription bare() {
    static const test::TempFolder folder(std::string("auto_walls_") +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    test::writeFile(folder / "hall.glb", "glTF");
    scenes::SceneDescription d;
    d.name = "hall";
    d.folder = folder.path();
    scenes::ModelFile hall;
    hall.file = "hall.glb";
    d.models.push_back(hall);
    return d;
}

AutoWallsOptions options() {
    AutoWallsOptions o;
    o.plan.maxResolution = 64;  // small textures: quick plans
    o.minCellSize = 5.0;
    o.maxCellsPerAxis = 4;
    // Crates cost (the hall has only 492 triangles) and wall layers are cheap: cells pay.
    o.msPerMillionTriangles = 1e4;
    o.msPerWallSide = 0.1;
    return o;
}

TEST(AutoWalls, FindsFloorCeilingAndHallWallsAsStructure) {
    const AutoWallsResult r = proposeWalls(hall(), bare(), options());
    EXPECT_THAT(r.structure, ElementsAre("ceiling", "floor", "wall-north", "wall-south"));
    EXPECT_NEAR(r.floorY, 0.0, 1e-9);    // the floor slab's top
    EXPECT_NEAR(r.ceilingY, 4.0, 1e-9);  // the ceiling slab's bottom
    // Walkable: the floor's x extent, between the hall walls' inner faces in z.
    EXPECT_NEAR(r.floorMin.x, -20.0, 1e-9);
    EXPECT_NEAR(r.floorMax.x, 20.0, 1e-9);
    EXPECT_NEAR(r.floorMin.y, -4.95, 1e-9);
    EXPECT_NEAR(r.floorMax.y, 4.95, 1e-9);
    // The proposal names them as structure nodes of the model.
    EXPECT_THAT(r.description.models.front().structureNodes,
                ElementsAre("ceiling", "floor", "wall-north", "wall-south"));
}

TEST(AutoWalls, TheProposalIsValidAndNoWallCutsACrate) {
    const scenes::Scene scene = hall();
    const AutoWallsResult r = proposeWalls(scene, bare(), options());
    ASSERT_GT(r.description.walls.size(), 0u);
    const std::string text = scenes::writeSceneDescription(r.description);
    EXPECT_EQ(scenes::parseSceneDescription(text, "proposal", r.description.folder).cells, r.description.cells);
    EXPECT_NO_THROW(scenes::validateSceneDescription(r.description, "proposal"));
    for (const scenes::VirtualWall& w : r.description.walls) {
        // Every proposed wall is upright on x = c or z = c; no crate's box spans the plane.
        const bool alongZ = w.lowerLeft.x == w.lowerRight.x;
        const int axis = alongZ ? 0 : 2;
        const double c = w.lowerLeft[axis];
        for (const scenes::Object& o : scene.objects) {
            if (o.name.rfind("crate", 0) != 0 && o.name != "astride") continue;
            EXPECT_FALSE(o.worldBounds.min[axis] < c - 1e-9 && o.worldBounds.max[axis] > c + 1e-9)
                << w.name << " at " << c << " cuts " << o.name;
        }
        // Its front faces cells[0]: the normal points towards that cell's centre.
        const glm::dvec3 n = glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft);
        glm::dvec2 centre(0.0);
        for (const glm::dvec2& p : r.description.cells[w.cells[0]].region) centre += p / 4.0;
        EXPECT_GT(n.x * (centre.x - w.lowerLeft.x) + n.z * (centre.y - w.lowerLeft.z), 0.0) << w.name;
    }
}

TEST(AutoWalls, ChoosesTheCheapestCandidateWithinTheBudget) {
    const AutoWallsResult r = proposeWalls(hall(), bare(), options());
    ASSERT_GT(r.candidates.size(), 1u);
    const AutoWallsCandidate& chosen = r.candidates[r.chosen];
    EXPECT_TRUE(chosen.withinBudget);
    for (const AutoWallsCandidate& c : r.candidates)
        if (c.withinBudget) {
            EXPECT_GE(c.expectedMs, chosen.expectedMs) << c.nx << "x" << c.nz;
        }
    EXPECT_EQ(static_cast<int>(r.description.cells.size()), chosen.nx * chosen.nz);
    // More cells draw fewer triangles: one cell draws every crate (41 x 12 triangles).
    EXPECT_DOUBLE_EQ(r.candidates.front().meanCellTriangles, 41.0 * 12.0);
    EXPECT_LT(chosen.meanCellTriangles, r.candidates.front().meanCellTriangles);
}

TEST(AutoWalls, ATinyBudgetLeavesOneCellWithoutWalls) {
    AutoWallsOptions o = options();
    o.textureBudgetMB = 1e-6;
    const AutoWallsResult r = proposeWalls(hall(), bare(), o);
    EXPECT_EQ(r.description.cells.size(), 1u);
    EXPECT_TRUE(r.description.walls.empty());
    for (std::size_t i = 1; i < r.candidates.size(); ++i) EXPECT_FALSE(r.candidates[i].withinBudget);
}

// hall() with a second storey instead of its ceiling: a slab from y 3.8 to 4, a roof slab from
// 7.8 to 8, the hall walls 8 m high, and ten crates upstairs (along x at z = 2.5).
scenes::Scene twoStoreyHall() {
    scenes::Scene s = hall();
    std::erase_if(s.objects, [](const scenes::Object& o) { return o.name == "ceiling"; });
    auto box = [&](glm::dvec3 size, glm::dvec3 centre, const std::string& name) {
        s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), name);
    };
    box({40, 0.2, 10}, {0, 3.9, 0}, "slab");
    box({40, 0.2, 10}, {0, 7.9, 0}, "roof");
    box({40, 8, 0.1}, {0, 4, -5}, "upper-north");
    box({40, 8, 0.1}, {0, 4, 5}, "upper-south");
    for (int i = 0; i < 10; ++i) box({1, 1, 1}, {-18.0 + 4.0 * i, 4.5, 2.5}, "upper crate " + std::to_string(i));
    return s;
}

TEST(AutoWalls, EveryStoreyGetsItsOwnCellsWallsAndWalk) {
    const AutoWallsResult r = proposeWalls(twoStoreyHall(), bare(), options());
    ASSERT_EQ(r.storeys.size(), 2u);
    // Floors at the slabs' tops; ceilings at the undersides of the slab and the roof above them.
    EXPECT_NEAR(r.storeys[0].storey.floorY, 0.0, 1e-6);
    EXPECT_NEAR(r.storeys[0].storey.ceilingY, 3.8, 1e-6);
    EXPECT_NEAR(r.storeys[1].storey.floorY, 4.0, 1e-6);
    EXPECT_NEAR(r.storeys[1].storey.ceilingY, 7.8, 1e-6);
    EXPECT_TRUE(r.stairs.empty());
    // Each storey's candidates count its own crates only: one cell draws 41 crates downstairs
    // and 10 upstairs, 12 triangles each.
    for (int storey : {0, 1}) {
        const auto first = std::find_if(r.candidates.begin(), r.candidates.end(),
                                        [&](const AutoWallsCandidate& c) { return c.storey == storey; });
        ASSERT_NE(first, r.candidates.end());
        EXPECT_DOUBLE_EQ(first->meanCellTriangles, (storey == 0 ? 41.0 : 10.0) * 12.0);
        EXPECT_EQ(r.candidates[r.storeys[storey].chosen].storey, storey);
    }
    // Cells of each storey carry its floor and are named by it; walls span their storey.
    const scenes::SceneDescription& d = r.description;
    EXPECT_EQ(static_cast<int>(d.cells.size()), r.storeys[0].cells + r.storeys[1].cells);
    for (const scenes::Cell& c : d.cells) {
        const bool upper = c.name.rfind("1/", 0) == 0;
        EXPECT_TRUE(upper || c.name.rfind("0/", 0) == 0) << c.name;
        EXPECT_NEAR(c.floorY, upper ? 4.0 : 0.0, 1e-6) << c.name;
    }
    for (const scenes::VirtualWall& w : d.walls) {
        const double floorY = d.cells[w.cells[0]].floorY;
        EXPECT_NEAR(d.cells[w.cells[1]].floorY, floorY, 1e-9) << w.name;
        EXPECT_NEAR(w.lowerLeft.y, floorY, 1e-6) << w.name;
        EXPECT_NEAR(w.upperLeft.y, floorY + 3.8, 1e-6) << w.name;
    }
    // A viewer at eye height above either floor is in that storey's cell.
    EXPECT_NEAR(d.cells[scenes::findCell(d.cells, {1.0, 1.7, 1.0})].floorY, 0.0, 1e-6);
    EXPECT_NEAR(d.cells[scenes::findCell(d.cells, {1.0, 5.7, 1.0})].floorY, 4.0, 1e-6);
    // The walk visits both storeys and, without stairs, walks each on its own: one break where
    // the upper storey's piece starts, and every point at one floor's eye height.
    ASSERT_FALSE(d.walkPath.empty());
    EXPECT_NEAR(d.walkPath.front().y, 1.7, 1e-6);
    EXPECT_NEAR(d.walkPath.back().y, 5.7, 1e-6);
    ASSERT_EQ(d.walkBreaks.size(), 1u);
    const int upper = d.walkBreaks[0];
    for (int i = 0; i < static_cast<int>(d.walkPath.size()); ++i)
        EXPECT_NEAR(d.walkPath[i].y, i < upper ? 1.7 : 5.7, 1e-6) << i;
    for (std::size_t i = 0; i + 1 < d.walkPath.size(); ++i) EXPECT_NE(d.walkPath[i], d.walkPath[i + 1]) << i;
    // It plans: the storeys' walls do not see each other.
    EXPECT_NO_THROW(planZones(d, options().plan));
}

TEST(AutoWalls, AStairCarriesTheWalkBetweenStoreys) {
    scenes::Scene s = twoStoreyHall();
    // Treads 0.8 m wide (z -4.9 to -4.1), 0.3 m deep along +x from x = 5.02, rising 0.2 m to
    // 3.8 m, under a well cut in the slab (x 4.8 to 10.72, z -5 to -4).
    std::erase_if(s.objects, [](const scenes::Object& o) { return o.name == "slab"; });
    auto box = [&](glm::dvec3 size, glm::dvec3 centre, const std::string& name) {
        s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(1.0f)));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre), name);
    };
    box({24.8, 0.2, 10}, {-7.6, 3.9, 0}, "slab west");
    box({9.28, 0.2, 10}, {15.36, 3.9, 0}, "slab east");
    box({5.92, 0.2, 9}, {7.76, 3.9, 0.5}, "slab beside the well");
    for (int i = 0; i < 19; ++i) box({0.3, 0.05, 0.8}, {5.17 + 0.3 * i, 0.2 * (i + 1) - 0.025, -4.5}, "tread");
    const AutoWallsResult r = proposeWalls(s, bare(), options());
    ASSERT_EQ(r.storeys.size(), 2u);
    ASSERT_EQ(r.stairs.size(), 1u);
    const Stair& stair = r.stairs.front();
    EXPECT_LT(stair.bottom.x, stair.top.x);  // the treads climb along +x
    // The walk climbs the stair's walk at eye height, one piece with no break, and every point
    // is at eye height above the ground floor, a tread or the upper floor.
    const scenes::SceneDescription& d = r.description;
    EXPECT_TRUE(d.walkBreaks.empty());
    auto near = [](glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-6; };
    const auto at = std::find_if(d.walkPath.begin(), d.walkPath.end(), [&](const glm::dvec3& p) {
        return near(p, stair.path.front() + glm::dvec3(0, 1.7, 0));
    });
    ASSERT_NE(at, d.walkPath.end());
    ASSERT_GE(d.walkPath.end() - at, static_cast<long>(stair.path.size()));
    for (std::size_t k = 0; k < stair.path.size(); ++k)
        EXPECT_TRUE(near(*(at + k), stair.path[k] + glm::dvec3(0, 1.7, 0))) << k;
    for (const glm::dvec3& p : d.walkPath) {
        const double floor = p.y - 1.7;
        const bool onFloor = std::abs(floor) < 1e-6 || std::abs(floor - 4.0) < 1e-6;
        const bool onTread =
            p.x > 5.02 && p.x < 10.72 && std::abs(floor - 0.2 * std::floor((p.x - 5.02) / 0.3 + 1.0)) < 1e-6;
        EXPECT_TRUE(onFloor || onTread) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(AutoWalls, IsDeterministic) {
    const std::string a = scenes::writeSceneDescription(proposeWalls(hall(), bare(), options()).description);
    const std::string b = scenes::writeSceneDescription(proposeWalls(hall(), bare(), options()).description);
    EXPECT_EQ(a, b);
}

TEST(AutoWalls, EvaluatesTheGivenWallsWithTheSameModel) {
    const scenes::Scene scene = hall();
    const AutoWallsResult first = proposeWalls(scene, bare(), options());
    const AutoWallsResult again = proposeWalls(scene, first.description, options());
    ASSERT_TRUE(again.given.has_value());
    EXPECT_DOUBLE_EQ(again.given->expectedMs, first.candidates[first.chosen].expectedMs);
    EXPECT_EQ(again.given->textures, first.candidates[first.chosen].textures);
}

// The walk cost (6.): eyes along the input's walk path, each also drawing the neighbours whose
// geometry zones hold it. A walk down the hall's centre line runs along the cut of a grid of
// 1 x 2 cells (the cut moves 0.55 m off z = 0, past the crate astride it: inside the geometry
// zones of its wall),
// so that grid draws both cells most of the walk, more than the floor cost's one cell; a grid
// of 2 x 1 cells is crossed once, and its eyes mostly draw their own cell only.
TEST(AutoWalls, TheWalkCostCountsNeighboursDrawnInGeometryZonesAlongTheWalkPath) {
    const scenes::Scene scene = hall();
    scenes::SceneDescription walk = bare();
    walk.walkPath = {{-18.0, 1.7, 0.0}, {18.0, 1.7, 0.0}};
    AutoWallsOptions o = options();
    o.minCellSize = 4.0;  // the walkable 9.9 m across the hall: up to 2 cells along z
    const AutoWallsResult floor = proposeWalls(scene, walk, o);
    o.walkCost = true;
    const AutoWallsResult walked = proposeWalls(scene, walk, o);
    ASSERT_EQ(floor.candidates.size(), walked.candidates.size());
    auto find = [](const AutoWallsResult& r, int nx, int nz) {
        for (const AutoWallsCandidate& c : r.candidates)
            if (c.nx == nx && c.nz == nz && !c.rooms) return c;
        ADD_FAILURE() << "no " << nx << "x" << nz << " candidate";
        return AutoWallsCandidate{};
    };
    // One cell: every crate (41 x 12 triangles) from every eye, either way.
    EXPECT_DOUBLE_EQ(find(walked, 1, 1).meanCellTriangles, 41.0 * 12.0);
    EXPECT_DOUBLE_EQ(find(floor, 1, 1).meanCellTriangles, 41.0 * 12.0);
    EXPECT_GT(find(walked, 1, 2).meanCellTriangles, find(floor, 1, 2).meanCellTriangles);
    EXPECT_LT(find(walked, 2, 1).meanCellTriangles, find(walked, 1, 2).meanCellTriangles);
    // Textures and budgets do not depend on the eyes.
    for (std::size_t i = 0; i < floor.candidates.size(); ++i) {
        EXPECT_EQ(walked.candidates[i].textures, floor.candidates[i].textures);
        EXPECT_EQ(walked.candidates[i].withinBudget, floor.candidates[i].withinBudget);
    }
}

// The generated house (six rooms, real walls 0.15 m thick, 0.9 m x 2.1 m doorways with lintels):
// its rooms are found again from the geometry alone, each doorway a portal of the same size.
TEST(AutoWalls, FindsTheRoomsOfAHouseAndItsDoorwaysAsPortals) {
    scenes::GenerateOptions g;
    g.triangles = 2000;
    scenes::GeneratedScene house = scenes::generateHouse(g);
    static const test::TempFolder folder("auto_walls_house");
    test::writeFile(folder / "house.glb", "glTF");
    scenes::SceneDescription base = house.description;
    base.folder = folder.path();
    AutoWallsOptions o = options();
    o.minCellSize = 2.0;
    o.maxCellsPerAxis = 2;  // few grids: a quick test
    o.preferRooms = true;
    std::vector<std::string> warnings;
    const AutoWallsResult r = proposeWalls(house.scene, base, o, &warnings);
    const AutoWallsCandidate& chosen = r.candidates.at(r.chosen);
    ASSERT_TRUE(chosen.rooms);
    EXPECT_EQ(chosen.nx * chosen.nz, 6);
    EXPECT_EQ(chosen.portals, 6);
    EXPECT_EQ(chosen.virtualWalls, 0);
    EXPECT_EQ(r.description.realWalls.size(), house.description.realWalls.size());
    // Every proposed portal is one of the generator's doorways: same corners as a set (within
    // half the wall thickness along its line), 2.1 m high.
    ASSERT_EQ(r.description.walls.size(), house.description.walls.size());
    for (const scenes::VirtualWall& w : r.description.walls) {
        SCOPED_TRACE(w.name);
        EXPECT_EQ(w.kind, scenes::WallKind::Portal);
        EXPECT_NEAR(w.upperLeft.y - w.lowerLeft.y, 2.1, 1e-6);
        const glm::dvec3 mid = 0.5 * (w.lowerLeft + w.lowerRight);
        const bool known = std::any_of(
            house.description.walls.begin(), house.description.walls.end(), [&](const scenes::VirtualWall& d) {
                return glm::length(0.5 * (d.lowerLeft + d.lowerRight) - mid) < 0.08 &&
                       std::abs(glm::length(d.lowerRight - d.lowerLeft) - glm::length(w.lowerRight - w.lowerLeft)) <
                           1e-6;
            });
        EXPECT_TRUE(known);
    }
    // Without --rooms the cost model decides; the rooms stay among the candidates.
    o.preferRooms = false;
    const AutoWallsResult free = proposeWalls(house.scene, base, o);
    EXPECT_EQ(std::count_if(free.candidates.begin(), free.candidates.end(),
                            [](const AutoWallsCandidate& c) { return c.rooms; }),
              1);
}

TEST(AutoWalls, RejectsBadOptionsByName) {
    struct Case {
        const char* name;
        void (*edit)(AutoWallsOptions&);
        const char* message;
    };
    const Case cases[] = {
        {"budget", [](AutoWallsOptions& o) { o.textureBudgetMB = 0.0; }, "texture budget"},
        {"cell size", [](AutoWallsOptions& o) { o.minCellSize = -1.0; }, "minimum cell size"},
        {"cells per axis", [](AutoWallsOptions& o) { o.maxCellsPerAxis = 0; }, "cells per axis"},
        {"cost", [](AutoWallsOptions& o) { o.msPerMillionTriangles = -2.0; }, "ms per million triangles"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        AutoWallsOptions o = options();
        c.edit(o);
        EXPECT_THAT([&] { proposeWalls(hall(), bare(), o); }, ::testing::ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    EXPECT_THAT([] { proposeWalls(scenes::Scene{}, bare(), options()); },
                ::testing::ThrowsMessage<Error>(HasSubstr("scene '': the model has no triangles")));
    AutoWallsOptions noLimit = options();
    noLimit.planLimitMetres = 0.0;
    EXPECT_THAT([&] { proposeWalls(hall(), bare(), noLimit); },
                ::testing::ThrowsMessage<Error>(HasSubstr("planning limit out of range (expected > 0 m")));
}

// The hall's grids (40 m x 9.9 m, up to 4 x 1) have 0, 9.9, 19.8 and 29.7 m of virtual wall:
// within 30 m (each within 12 m) the first two are planned, each reported as it is, and the
// rest are counted.
TEST(AutoWalls, PlansOnlyTheGridsWithinThePlanningLimitAndSaysSo) {
    AutoWallsOptions o = options();
    o.planLimitMetres = 30.0;
    std::vector<std::string> lines;
    o.progress = [&](const std::string& line) { lines.push_back(line); };
    const AutoWallsResult r = proposeWalls(hall(), bare(), o);
    ASSERT_EQ(r.candidates.size(), 2u);
    EXPECT_EQ(r.candidates[1].nx, 2);
    EXPECT_EQ(r.limit.planned, 2);
    EXPECT_EQ(r.limit.skipped, 2);
    EXPECT_NEAR(r.limit.plannedMetres, 9.9, 1e-6);  // single-precision mesh bounds
    EXPECT_NEAR(r.limit.skippedMetres, 19.8, 1e-6);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_THAT(lines[0], HasSubstr("storey 0: grid 1 x 1 (1 cells, 0 m of virtual wall): 0 textures"));
    EXPECT_THAT(lines[1], HasSubstr("storey 0: grid 2 x 1 (2 cells, 10 m of virtual wall)"));
    // The default limit plans them all.
    EXPECT_EQ(proposeWalls(hall(), bare(), options()).limit.skipped, 0);
}

}  // namespace
}  // namespace cavewall::walls
