#include "walls/rooms.h"

#include "config/error.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "scenes/primitives.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "tests/support/files.h"
#include "walls/auto_walls.h"
#include "walls/floor_grid.h"
#include "walls/room_cells.h"
#include "walls/storeys.h"
#include "walls/visibility.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;

// Plans are drawn in 0.1 m cells from (-1, -1): every wall edge below lies on a cell edge, so a
// gap of w metres is exactly w / 0.1 cells.
FloorGrid plan(glm::dvec2 size) {
    FloorGrid g = makeFloorGrid({-1.0, -1.0}, size + 1.0, 0.1);
    markFloorRect(g, {-0.1, -0.1}, size + 0.1);
    return g;
}

// A wall 0.2 m thick centred on x = `x` from z0 to z1 (and on z = `z`, from x0 to x1).
void wallAtX(FloorGrid& g, double x, double z0, double z1) { markWallRect(g, {x - 0.1, z0}, {x + 0.1, z1}); }
void wallAtZ(FloorGrid& g, double z, double x0, double x1) { markWallRect(g, {x0, z - 0.1}, {x1, z + 0.1}); }

// The outline of a w x d plan: walls centred on its edges.
void outline(FloorGrid& g, double w, double d) {
    wallAtX(g, 0.0, -0.1, d + 0.1);
    wallAtX(g, w, -0.1, d + 0.1);
    wallAtZ(g, 0.0, -0.1, w + 0.1);
    wallAtZ(g, d, -0.1, w + 0.1);
}

// Three rooms in a row, 12 m x 4 m: partitions at x = 4 (a 0.9 m door, z 1.5 to 2.4) and x = 8
// (a 1.0 m door, z 2.5 to 3.5).
FloorGrid threeRooms() {
    FloorGrid g = plan({12.0, 4.0});
    outline(g, 12.0, 4.0);
    wallAtX(g, 4.0, 0.0, 1.5);
    wallAtX(g, 4.0, 2.4, 4.0);
    wallAtX(g, 8.0, 0.0, 2.5);
    wallAtX(g, 8.0, 3.5, 4.0);
    return g;
}

// cellAt: the cell whose square holds the point (lower edges inside, upper ones the next
// cell's), -1 off the grid or for a point that is not a number.
TEST(FloorGrid, CellAtIsTheCellWhoseSquareHoldsThePoint) {
    const FloorGrid g = makeFloorGrid({-1.0, -1.0}, {1.0, 2.0}, 0.5);  // 4 x 6 cells
    ASSERT_EQ(g.nx, 4);
    ASSERT_EQ(g.nz, 6);
    EXPECT_EQ(g.cellAt({-1.0, -1.0}), g.index(0, 0));
    EXPECT_EQ(g.cellAt({-0.5, -0.75}), g.index(1, 0));  // on cell (1, 0)'s lower x edge
    EXPECT_EQ(g.cellAt({0.9, 1.9}), g.index(3, 5));
    EXPECT_EQ(g.centre(g.cellAt({0.2, 0.3})), g.centre(2, 2));
    EXPECT_EQ(g.cellAt({1.0, 0.0}), -1);  // the grid's upper x edge
    EXPECT_EQ(g.cellAt({-1.01, 0.0}), -1);
    EXPECT_EQ(g.cellAt({0.0, std::nan("")}), -1);
}

TEST(Rooms, ThreeRoomsWithTwoDoors) {
    const FloorPlan p = findRooms(threeRooms());
    ASSERT_EQ(p.rooms.size(), 3u);
    // Rooms are numbered by their first cell, row by row: all start on the first row inside
    // the outline, so left to right. Each is 3.8 m x 3.8 m inside its 0.2 m walls.
    for (int r = 0; r < 3; ++r) {
        EXPECT_NEAR(p.rooms[r].area, 3.8 * 3.8, 1e-6) << r;
        EXPECT_NEAR(p.rooms[r].lo.x, 4.0 * r + 0.1, 1e-6) << r;
    }
    ASSERT_EQ(p.doorways.size(), 2u);
    const Doorway& first = p.doorways[0];
    EXPECT_EQ(first.rooms, (std::array<int, 2>{0, 1}));
    EXPECT_NEAR(first.width, 0.9, 1e-4);
    EXPECT_NEAR(first.position.x, 4.0, 1e-6);  // the wall's middle: the opening spans its thickness
    EXPECT_NEAR(first.position.y, 1.95, 1e-6);
    EXPECT_FALSE(first.alongX);  // the partition runs along z
    const Doorway& second = p.doorways[1];
    EXPECT_EQ(second.rooms, (std::array<int, 2>{1, 2}));
    EXPECT_NEAR(second.width, 1.0, 1e-4);
    EXPECT_NEAR(second.position.x, 8.0, 1e-6);
    EXPECT_NEAR(second.position.y, 3.0, 1e-6);
    EXPECT_EQ(p.exits, 0);
}

// A corridor 16 m x 2 m along x (z 0 to 2) with four rooms of 4 m x 4 m on its north side,
// each with a 0.9 m door into the corridor.
TEST(Rooms, ACorridorWithFourRooms) {
    FloorGrid g = plan({16.0, 6.0});
    outline(g, 16.0, 6.0);
    for (double x : {4.0, 8.0, 12.0}) wallAtX(g, x, 2.0, 6.0);
    for (int r = 0; r < 4; ++r) {
        const double door = 4.0 * r + 1.5;  // each door from 1.5 m to 2.4 m into its room's width
        wallAtZ(g, 2.0, 4.0 * r, door);
        wallAtZ(g, 2.0, door + 0.9, 4.0 * r + 4.0);
    }
    const FloorPlan p = findRooms(g);
    // The corridor holds the lowest rows: room 0.
    ASSERT_EQ(p.rooms.size(), 5u);
    EXPECT_NEAR(p.rooms[0].area, 15.8 * 1.8, 1e-6);
    ASSERT_EQ(p.doorways.size(), 4u);
    for (int d = 0; d < 4; ++d) {
        SCOPED_TRACE(d);
        EXPECT_EQ(p.doorways[d].rooms, (std::array<int, 2>{0, d + 1}));
        EXPECT_NEAR(p.doorways[d].width, 0.9, 1e-4);
        EXPECT_NEAR(p.doorways[d].position.x, 4.0 * d + 1.95, 1e-6);
        EXPECT_NEAR(p.doorways[d].position.y, 2.0, 1e-6);
        EXPECT_TRUE(p.doorways[d].alongX);
    }
}

TEST(Rooms, AWallWithoutAGapGivesNoDoorway) {
    FloorGrid g = plan({8.0, 4.0});
    outline(g, 8.0, 4.0);
    wallAtX(g, 4.0, 0.0, 4.0);
    const FloorPlan p = findRooms(g);
    EXPECT_EQ(p.rooms.size(), 2u);
    EXPECT_TRUE(p.doorways.empty());
}

// Gaps by width against the default door widths (0.6 m to 1.2 m): a 0.3 m slit closes but
// joins nothing, a 2 m opening stays open floor (one room), a 1.2 m one is still a door.
TEST(Rooms, OnlyGapsOfADoorsWidthAreDoorways) {
    struct Case {
        double gap;
        std::size_t rooms, doorways;
    };
    for (const Case c : {Case{0.3, 2, 0}, Case{2.0, 1, 0}, Case{1.2, 2, 1}, Case{0.6, 2, 1}}) {
        SCOPED_TRACE(c.gap);
        FloorGrid g = plan({8.0, 4.0});
        outline(g, 8.0, 4.0);
        wallAtX(g, 4.0, 0.0, 1.0);
        wallAtX(g, 4.0, 1.0 + c.gap, 4.0);
        const FloorPlan p = findRooms(g);
        EXPECT_EQ(p.rooms.size(), c.rooms);
        EXPECT_EQ(p.doorways.size(), c.doorways);
    }
}

// A door in the outline leads to cells without floor: an exit, not a doorway.
TEST(Rooms, ADoorToTheOutsideIsAnExit) {
    FloorGrid g = plan({4.0, 4.0});
    wallAtX(g, 0.0, -0.1, 4.1);
    wallAtX(g, 4.0, -0.1, 4.1);
    wallAtZ(g, 4.0, -0.1, 4.1);
    wallAtZ(g, 0.0, -0.1, 1.5);
    wallAtZ(g, 0.0, 2.4, 4.1);
    const FloorPlan p = findRooms(g);
    EXPECT_EQ(p.rooms.size(), 1u);
    EXPECT_TRUE(p.doorways.empty());
    EXPECT_EQ(p.exits, 1);
}

TEST(Rooms, RejectsBadOptionsByName) {
    RoomOptions o;
    o.maxDoorWidth = 0.5;  // below the minimum door width
    EXPECT_THAT([&] { findRooms(threeRooms(), o); },
                ::testing::ThrowsMessage<Error>(HasSubstr("maximum door width out of range")));
    FloorGridOptions grid;
    grid.cellSize = 0.0;
    EXPECT_THAT(
        [&] {
            rasteriseStorey(scenes::Scene{}, 0.0, 3.0, {0.0, 0.0}, {1.0, 1.0}, grid);
        },
        ::testing::ThrowsMessage<Error>(HasSubstr("floor grid: cell size out of range")));
}

// Boxes with their bottom at y0: a floor slab, walls 3 m high with a 0.9 m gap, a door leaf
// 2.1 m high standing in the gap and a table. Only the walls are wall elements.
TEST(Rooms, SlicesWallElementsFoundByShapeButNotDoorLeavesOrTables) {
    scenes::Scene s;
    auto box = [&](glm::dvec3 size, glm::dvec3 lowCentre) {
        s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(1.0f)));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1,
                          glm::translate(glm::dmat4(1.0), lowCentre + glm::dvec3(0.0, 0.5 * size.y, 0.0)), "box");
    };
    box({8.2, 0.2, 4.2}, {4.0, -0.2, 2.0});  // slab, its top at y 0
    box({0.2, 3.0, 4.2}, {0.0, 0.0, 2.0});
    box({0.2, 3.0, 4.2}, {8.0, 0.0, 2.0});
    box({8.2, 3.0, 0.2}, {4.0, 0.0, 0.0});
    box({8.2, 3.0, 0.2}, {4.0, 0.0, 4.0});
    box({0.2, 3.0, 1.5}, {4.0, 0.0, 0.75});   // partition, z 0 to 1.5
    box({0.2, 3.0, 1.6}, {4.0, 0.0, 3.2});    // and z 2.4 to 4
    box({0.05, 2.1, 0.9}, {4.0, 0.0, 1.95});  // the door leaf, shut
    box({1.0, 0.75, 1.0}, {2.0, 0.0, 2.0});   // a table
    const StoreyRooms found = findStoreyRooms(s, 0.0, 3.0, {-0.1, -0.1}, {8.1, 4.1});
    EXPECT_EQ(found.grid.wallElements, 6);
    ASSERT_EQ(found.plan.rooms.size(), 2u);
    ASSERT_EQ(found.plan.doorways.size(), 1u);
    // The clear width in whole cells: each jamb's slice marks the cell it lies in, and a jamb
    // on a cell edge may mark the cell beyond it, so 0.9 m give 7 to 9 cells of 0.1 m.
    EXPECT_GE(found.plan.doorways[0].width, 0.7 - 1e-6);
    EXPECT_LE(found.plan.doorways[0].width, 0.9 + 1e-6);
    EXPECT_NEAR(found.plan.doorways[0].position.x, 4.0, 0.1);
    EXPECT_NEAR(found.plan.doorways[0].position.y, 1.95, 0.1);
}

// A model file for descriptions to name (validation wants it to exist; the scene itself is
// built in memory), in a folder of its own.
scenes::SceneDescription bareDescription(const std::string& name) {
    const test::TempFolder folder("rooms_" + name);  // left in place: it only holds the file
    test::writeFile(folder / "plan.glb", "glTF");
    scenes::SceneDescription base;
    base.name = name;
    base.folder = folder.path();
    scenes::ModelFile model;
    model.file = "plan.glb";
    base.models.push_back(model);
    return base;
}

// threeRooms() built of unnamed boxes on a slab: walls 3 m high, 0.2 m thick.
scenes::Scene threeRoomScene() {
    scenes::Scene s;
    auto box = [&](glm::dvec3 size, glm::dvec3 lowCentre) {
        s.meshes.push_back(scenes::makeBox(glm::vec3(size), glm::vec4(1.0f)));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1,
                          glm::translate(glm::dmat4(1.0), lowCentre + glm::dvec3(0.0, 0.5 * size.y, 0.0)), "box");
    };
    box({12.2, 0.2, 4.2}, {6.0, -0.2, 2.0});
    box({0.2, 3.0, 4.2}, {0.0, 0.0, 2.0});
    box({0.2, 3.0, 4.2}, {12.0, 0.0, 2.0});
    box({12.2, 3.0, 0.2}, {6.0, 0.0, 0.0});
    box({12.2, 3.0, 0.2}, {6.0, 0.0, 4.0});
    box({0.2, 3.0, 1.5}, {4.0, 0.0, 0.75});
    box({0.2, 3.0, 1.6}, {4.0, 0.0, 3.2});
    box({0.2, 3.0, 2.5}, {8.0, 0.0, 1.25});
    box({0.2, 3.0, 0.5}, {8.0, 0.0, 3.75});
    return s;
}

// proposeWalls on the unnamed three rooms: no line of named wall pieces, so the rooms come from
// the floor plan; the storey reports them and --rooms chooses them.
TEST(Rooms, ProposeWallsOffersTheFloorPlansRoomsAndRoomsChoosesThem) {
    AutoWallsOptions o;
    o.plan.maxResolution = 64;  // small textures: a quick plan
    o.preferRooms = true;
    const AutoWallsResult r = proposeWalls(threeRoomScene(), bareDescription("propose"), o);
    ASSERT_EQ(r.storeys.size(), 1u);
    EXPECT_EQ(r.storeys[0].wallElements, 8);  // the slab is no wall element
    EXPECT_EQ(r.storeys[0].rooms, 3);
    EXPECT_EQ(r.storeys[0].doorways, 2);
    const AutoWallsCandidate& chosen = r.candidates.at(r.chosen);
    EXPECT_TRUE(chosen.rooms);
    EXPECT_TRUE(chosen.floorPlan);
    EXPECT_EQ(r.description.cells.size(), 3u);
    EXPECT_EQ(chosen.portals, 2);
    EXPECT_EQ(chosen.virtualWalls, 0);
}

// The three rooms as cells: one rectangle each, cut along the partitions, a portal at each
// doorway, no virtual wall, and a walk through both doors.
TEST(Rooms, RoomCellsAreRectanglesWithPortalsAtTheDoorways) {
    const FloorGrid g = threeRooms();
    const FloorPlan p = findRooms(g);
    const scenes::SceneDescription d = describeRooms(bareDescription("cells"), g, p, 0.0, 3.0, 1.7);
    EXPECT_NO_THROW(scenes::validateSceneDescription(d, "rooms"));
    ASSERT_EQ(d.cells.size(), 3u);
    for (const scenes::Cell& c : d.cells) EXPECT_GT(std::abs(scenes::regionArea(c.region)), 3.8 * 3.8);
    ASSERT_EQ(d.walls.size(), 2u);
    for (const scenes::VirtualWall& w : d.walls) {
        SCOPED_TRACE(w.name);
        EXPECT_EQ(w.kind, scenes::WallKind::Portal);
        EXPECT_NEAR(glm::length(w.lowerRight - w.lowerLeft), w.lowerLeft.z < 2.45 ? 0.9 : 1.0, 1e-6);
        EXPECT_NEAR(w.upperLeft.y, 2.1, 1e-9);
    }
    EXPECT_FALSE(d.realWalls.empty());
    // The tour: the first room's inner point, a door, the middle room, ... back to the start.
    ASSERT_GE(d.walkPath.size(), 5u);
    for (const glm::dvec3& e : d.walkPath) EXPECT_GE(scenes::findCell(d.cells, e), 0);
}

// The metres of the edge between room cells a and b (rectangles on grid lines) that no wall,
// portal or virtual wall covers, from the plan itself: steps with a wall or doorway on neither
// side and room floor on at most one (a void, floor that is no room). Everything else is
// covered: a doorway by a portal, room floor on both sides by a virtual wall, a wall by a real
// wall however short its run.
double bareMetres(const FloorGrid& g, const FloorPlan& p, const scenes::Cell& a, const scenes::Cell& b) {
    auto box = [](const scenes::Cell& c) {
        glm::dvec2 lo = c.region[0], hi = c.region[0];
        for (const glm::dvec2& v : c.region) lo = glm::min(lo, v), hi = glm::max(hi, v);
        return std::array<glm::dvec2, 2>{lo, hi};
    };
    const auto ba = box(a), bb = box(b);
    double bare = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        const int other = 1 - axis;
        double line = 0.0;
        if (std::abs(ba[1][axis] - bb[0][axis]) < 1e-9)
            line = ba[1][axis];
        else if (std::abs(bb[1][axis] - ba[0][axis]) < 1e-9)
            line = bb[1][axis];
        else
            continue;
        const double from = std::max(ba[0][other], bb[0][other]), to = std::min(ba[1][other], bb[1][other]);
        for (double t = from + 0.5 * g.cellSize; t < to; t += g.cellSize) {
            glm::dvec2 before, after;
            before[axis] = line - 0.5 * g.cellSize, after[axis] = line + 0.5 * g.cellSize;
            before[other] = after[other] = t;
            const int c0 = g.cellAt(before), c1 = g.cellAt(after);
            if (c0 < 0 || c1 < 0) continue;
            const bool covered = p.opening[c0] >= 0 || p.opening[c1] >= 0 || p.barrier[c0] || p.barrier[c1] ||
                                 (p.room[c0] >= 0 && p.room[c1] >= 0);
            bare += covered ? 0.0 : g.cellSize;
        }
    }
    return bare;
}

// Every pair of `d`'s cells: the bare metres openBoundaryLength finds are those of bareMetres.
void expectBareOnlyWhereNothingStands(const FloorGrid& g, const FloorPlan& p, const scenes::SceneDescription& d) {
    for (int a = 0; a < static_cast<int>(d.cells.size()); ++a)
        for (int b = a + 1; b < static_cast<int>(d.cells.size()); ++b)
            EXPECT_NEAR(openBoundaryLength(d, a, b), bareMetres(g, p, d.cells[a], d.cells[b]), 1e-6)
                << d.cells[a].name << " | " << d.cells[b].name;
}

// A gallery around a void (no floor) of 4 m x 4 m in a 10 m x 10 m outline, cut in two by
// partitions from the outline to the void at x = 5. The cells' shared edge runs along the
// partitions, covered by real walls, and across the void, left bare: one sees across a void, so
// the two cells see each other directly (walls/visibility.h) and are drawn as geometry together.
TEST(Rooms, RoomCellsLeaveAnEdgeOverAVoidBareAndCoverTheRest) {
    FloorGrid g = makeFloorGrid({-1.0, -1.0}, {11.0, 11.0}, 0.1);
    markFloorRect(g, {-0.1, -0.1}, {10.1, 3.0});
    markFloorRect(g, {-0.1, 7.0}, {10.1, 10.1});
    markFloorRect(g, {-0.1, 3.0}, {3.0, 7.0});
    markFloorRect(g, {7.0, 3.0}, {10.1, 7.0});
    outline(g, 10.0, 10.0);
    wallAtX(g, 5.0, 0.0, 3.0);
    wallAtX(g, 5.0, 7.0, 10.0);
    const FloorPlan p = findRooms(g);
    ASSERT_EQ(p.rooms.size(), 2u);
    const scenes::SceneDescription d = describeRooms(bareDescription("gallery"), g, p, 0.0, 3.0, 1.7);
    EXPECT_NO_THROW(scenes::validateSceneDescription(d, "gallery"));
    ASSERT_EQ(d.cells.size(), 2u);
    EXPECT_NEAR(openBoundaryLength(d, 0, 1), 4.0, 1e-6);
    expectBareOnlyWhereNothingStands(g, p, d);
    EXPECT_EQ(computeVisibility(d).at(0, 1), CellVisibility::Geometry);
    EXPECT_TRUE(d.walls.empty());
}

// A grey picture of a floor plan for looking at it: walls black, rooms in greys, doorways
// white, no floor mid grey; the cells over it (red edges, portals green, virtual walls blue).
void writePlanImage(const FloorGrid& g, const FloorPlan& p, const scenes::SceneDescription& cells,
                    const std::filesystem::path& file) {
    scenes::Image image;
    image.width = g.nx;
    image.height = g.nz;
    image.rgba.assign(static_cast<std::size_t>(g.nx) * g.nz * 4, 255);
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i) {
            const int c = g.index(i, k);
            std::uint8_t v = 128;
            if (p.opening[c] >= 0)
                v = 255;
            else if (p.barrier[c])
                v = 0;
            else if (p.room[c] >= 0)
                v = static_cast<std::uint8_t>(160 + (p.room[c] * 37) % 80);
            std::uint8_t* px = &image.rgba[4 * (static_cast<std::size_t>(k) * g.nx + i)];
            px[0] = px[1] = px[2] = v;
        }
    // The cells' edges in red, the portals in green.
    auto paint = [&](glm::dvec2 a, glm::dvec2 b, glm::u8vec3 colour) {
        const int steps = static_cast<int>(glm::length(b - a) / (0.5 * g.cellSize)) + 1;
        for (int t = 0; t <= steps; ++t) {
            const glm::dvec2 q = (glm::mix(a, b, double(t) / steps) - g.origin) / g.cellSize;
            const int i = std::clamp(static_cast<int>(q.x), 0, g.nx - 1),
                      k = std::clamp(static_cast<int>(q.y), 0, g.nz - 1);
            std::uint8_t* px = &image.rgba[4 * (static_cast<std::size_t>(k) * g.nx + i)];
            px[0] = colour.r;
            px[1] = colour.g;
            px[2] = colour.b;
        }
    };
    for (const scenes::Cell& c : cells.cells)
        for (std::size_t v = 0; v < c.region.size(); ++v)
            paint(c.region[v], c.region[(v + 1) % c.region.size()], {220, 0, 0});
    for (const scenes::VirtualWall& w : cells.walls)
        paint({w.lowerLeft.x, w.lowerLeft.z}, {w.lowerRight.x, w.lowerRight.z},
              w.kind == scenes::WallKind::Portal ? glm::u8vec3(0, 200, 0) : glm::u8vec3(0, 0, 255));
    scenes::writeImage(file, image);
}

// Where a walk goes, sampled every 5 cm: how many samples lie in wall cells, how many on floor
// of neither a room nor a doorway (a closed opening, floor that is no room), and which rooms it
// enters.
struct WalkCount {
    int onWalls = 0, offRooms = 0;
    std::vector<bool> rooms;
};

WalkCount countWalk(const FloorGrid& g, const FloorPlan& p, const std::vector<glm::dvec3>& walk) {
    WalkCount out;
    out.rooms.assign(p.rooms.size(), false);
    for (std::size_t n = 0; n + 1 < walk.size(); ++n) {
        const glm::dvec2 a(walk[n].x, walk[n].z), b(walk[n + 1].x, walk[n + 1].z);
        const int steps = 1 + static_cast<int>(glm::length(b - a) / 0.05);
        for (int t = 0; t <= steps; ++t) {
            const int c = g.cellAt(glm::mix(a, b, double(t) / steps));
            if (c < 0 || g.wall[c]) {
                ++out.onWalls;
                continue;
            }
            if (p.room[c] >= 0) out.rooms[p.room[c]] = true;
            out.offRooms += p.room[c] < 0 && p.opening[c] < 0 ? 1 : 0;
        }
    }
    return out;
}

// The clinic (a real two-storey BIM building, 1,091 wall elements and 254 doors in the IFC
// model): both storeys fall into rooms joined by doorways. The ranges are wide: the counts
// depend on how the geometry meets the grid; the figures measured are in the results.
TEST(Rooms, TheClinicsStoreysHaveRoomsAndDoorways) {
    const std::filesystem::path file = std::filesystem::path(CAVEWALL_REAL_SCENES) / "clinic" / "clinic.gltf";
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const scenes::Scene scene = scenes::loadSceneFile(file);
    const Storeys found = findStoreys(scene);
    ASSERT_EQ(found.storeys.size(), 2u);
    static const test::TempFolder folder("rooms_clinic");
    for (std::size_t i = 0; i < found.storeys.size(); ++i) {
        SCOPED_TRACE(i);
        const Storey& s = found.storeys[i];
        const auto start = std::chrono::steady_clock::now();
        const StoreyRooms rooms = findStoreyRooms(scene, s.floorY, s.ceilingY, s.floorMin, s.floorMax);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        scenes::SceneDescription base;
        base.name = "clinic";
        const scenes::SceneDescription cells =
            describeRooms(base, rooms.grid.grid, rooms.plan, s.floorY, s.ceilingY, 1.7);
        writePlanImage(rooms.grid.grid, rooms.plan, cells, folder / ("storey" + std::to_string(i) + ".png"));
        // Cells share bare edges only where nothing stands (a void, floor that is no room),
        // not where a cut crosses a wall, however short the wall's run along the edge.
        expectBareOnlyWhereNothingStands(rooms.grid.grid, rooms.plan, cells);
        // The walk keeps off the walls (no point every 5 cm of it lies on one) and reaches
        // nearly every room, over doorways or other floor.
        const WalkCount walk = countWalk(rooms.grid.grid, rooms.plan, cells.walkPath);
        const auto reached = std::count(walk.rooms.begin(), walk.rooms.end(), true);
        std::printf("storey %zu: walk %zu points, %d samples on walls, %d off rooms and doorways, %ld of %zu rooms\n",
                    i, cells.walkPath.size(), walk.onWalls, walk.offRooms, static_cast<long>(reached),
                    walk.rooms.size());
        EXPECT_EQ(walk.onWalls, 0);
        EXPECT_GE(static_cast<double>(reached), 0.9 * static_cast<double>(walk.rooms.size()));
        std::vector<double> widths;
        for (const Doorway& d : rooms.plan.doorways) widths.push_back(d.width);
        std::sort(widths.begin(), widths.end());
        const double median = widths.empty() ? 0.0 : widths[widths.size() / 2];
        std::printf(
            "storey %zu: %d wall elements, %zu rooms, %zu doorways (median clear width %.2f m), %d exits, "
            "%.1f s\n",
            i, rooms.grid.wallElements, rooms.plan.rooms.size(), rooms.plan.doorways.size(), median, rooms.plan.exits,
            seconds);
        EXPECT_GE(rooms.plan.rooms.size(), 20u);
        EXPECT_LE(rooms.plan.rooms.size(), 300u);
        EXPECT_GE(rooms.plan.doorways.size(), 20u);
        EXPECT_LE(rooms.plan.doorways.size(), 254u);
    }
}

}  // namespace
}  // namespace cavewall::walls
