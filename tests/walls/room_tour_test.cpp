#include "walls/room_tour.h"

#include "scenes/region.h"
#include "scenes/scene_description.h"
#include "walls/floor_grid.h"
#include "walls/room_cells.h"
#include "walls/rooms.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cavewall::walls {
namespace {

// A wall's footprint, (x, z) from lo to hi.
struct WallRect {
    glm::dvec2 lo, hi;
};

// Four rooms in a 12 m x 8 m outline, walls 0.2 m thick, doorways 0.9 m wide:
//   A, x 0-6: a U around a stub wall along z = 4.5 from x = 0 to 4.6 (its open end 1.3 m wide,
//      wider than a door: A stays one room); a door at x = 6, z 6.5-7.4, into C;
//   B, x 6-12, z 0-4: a door at z = 4, x 7.0-7.9, into C;
//   C, x 6-9, z 4-8, and D, x 9-12, z 4-8: a door at x = 9, z 5.0-5.9.
// A's inner point lies in its lower half (the deeper), so the straight line from it to its
// door crosses the stub.
std::vector<WallRect> fourRooms() {
    return {
        {{-0.1, -0.1}, {0.1, 8.1}},   // the outline: x = 0,
        {{11.9, -0.1}, {12.1, 8.1}},  // x = 12,
        {{-0.1, -0.1}, {12.1, 0.1}},  // z = 0
        {{-0.1, 7.9}, {12.1, 8.1}},   // and z = 8
        {{5.9, 0.0}, {6.1, 6.5}},     // x = 6 below A's door
        {{5.9, 7.4}, {6.1, 8.0}},     // and above it
        {{0.0, 4.4}, {4.6, 4.6}},     // A's stub
        {{6.0, 3.9}, {7.0, 4.1}},     // z = 4 left of B's door
        {{7.9, 3.9}, {12.0, 4.1}},    // and right of it
        {{8.9, 4.0}, {9.1, 5.0}},     // x = 9 below D's door
        {{8.9, 5.9}, {9.1, 8.0}},     // and above it
    };
}

// The rectangles drawn in 0.1 m cells from (-1, -1), floor under the outline.
FloorGrid gridOf(const std::vector<WallRect>& walls) {
    FloorGrid g = makeFloorGrid({-1.0, -1.0}, {13.0, 9.0}, 0.1);
    markFloorRect(g, {-0.1, -0.1}, {12.1, 8.1});
    for (const WallRect& w : walls) markWallRect(g, w.lo, w.hi);
    return g;
}

// True when the segment p -> q (x, z) meets the rectangle (the slab test, Liang and Barsky).
bool crosses(glm::dvec2 p, glm::dvec2 q, const WallRect& r) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 d = q - p;
    for (int axis = 0; axis < 2; ++axis) {
        if (std::abs(d[axis]) < 1e-12) {
            if (p[axis] < r.lo[axis] || p[axis] > r.hi[axis]) return false;
            continue;
        }
        double a = (r.lo[axis] - p[axis]) / d[axis], b = (r.hi[axis] - p[axis]) / d[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

// True when the segments p -> q and a -> b (x, z) meet.
bool segmentsMeet(glm::dvec2 p, glm::dvec2 q, glm::dvec2 a, glm::dvec2 b) {
    auto side = [](glm::dvec2 o, glm::dvec2 u, glm::dvec2 v) {
        return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
    };
    const double d1 = side(a, b, p), d2 = side(a, b, q), d3 = side(p, q, a), d4 = side(p, q, b);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

double distanceToRect(glm::dvec2 p, const WallRect& r) { return glm::length(p - glm::clamp(p, r.lo, r.hi)); }

glm::dvec2 xz(const glm::dvec3& p) { return {p.x, p.z}; }

// The four rooms with A's door narrowed to a 0.5 m slit: narrower than a door, so no doorway,
// but a person walks through it.
struct SlitRooms {
    std::vector<WallRect> walls;
    FloorGrid grid;
    FloorPlan plan;
};

SlitRooms slitRooms() {
    SlitRooms s{fourRooms(), {}, {}};
    s.walls[5] = {{5.9, 7.0}, {6.1, 8.0}};  // x = 6 above the slit, z 6.5 to 7.0
    s.grid = gridOf(s.walls);
    s.plan = findRooms(s.grid);
    return s;
}

// Each segment of the polyline `points` crosses none of `walls`.
void expectCrossesNoWall(const std::vector<glm::dvec2>& points, const std::vector<WallRect>& walls) {
    for (std::size_t n = 0; n + 1 < points.size(); ++n)
        for (std::size_t w = 0; w < walls.size(); ++w)
            EXPECT_FALSE(crosses(points[n], points[n + 1], walls[w])) << "segment " << n << ", wall " << w;
}

TEST(RoomTour, WalksThroughTheDoorwaysAroundWallsAndVisitsEveryRoom) {
    const std::vector<WallRect> walls = fourRooms();
    const FloorGrid g = gridOf(walls);
    const FloorPlan plan = findRooms(g);
    ASSERT_EQ(plan.rooms.size(), 4u);
    ASSERT_EQ(plan.doorways.size(), 3u);
    // The straight line from A (room 0, the largest) to its doorway crosses the stub (wall 6).
    const auto aToC =
        std::find_if(plan.doorways.begin(), plan.doorways.end(), [](const Doorway& d) { return d.rooms[0] == 0; });
    ASSERT_NE(aToC, plan.doorways.end());
    ASSERT_LT(plan.rooms[0].inner.y, 4.4);
    EXPECT_TRUE(crosses(plan.rooms[0].inner, aToC->position, walls[6]));

    const std::vector<glm::dvec3> tour = roomTour(g, plan, 1.7);
    ASSERT_GE(tour.size(), 2u);
    EXPECT_EQ(xz(tour.front()), plan.rooms[0].inner);  // from the largest room
    for (std::size_t n = 0; n + 1 < tour.size(); ++n) {
        SCOPED_TRACE(n);
        EXPECT_NE(tour[n], tour[n + 1]);
        EXPECT_DOUBLE_EQ(tour[n].y, 1.7);
        for (std::size_t w = 0; w < walls.size(); ++w) {
            EXPECT_FALSE(crosses(xz(tour[n]), xz(tour[n + 1]), walls[w])) << "wall " << w;
            // The clearance, 0.4 m, less half a cell of thinning and the grid's own half cell:
            // the doorways are 0.9 m wide, so their middles keep 0.45 m.
            for (int t = 0; t <= 100; ++t) {
                const glm::dvec2 p = glm::mix(xz(tour[n]), xz(tour[n + 1]), t / 100.0);
                ASSERT_GE(distanceToRect(p, walls[w]), 0.3) << "wall " << w << " at " << p.x << ", " << p.y;
            }
        }
    }
    // Every room holds a point of the walk.
    std::vector<bool> visited(plan.rooms.size(), false);
    for (const glm::dvec3& p : tour)
        if (const int r = plan.room[g.cellAt(xz(p))]; r >= 0) visited[r] = true;
    for (std::size_t r = 0; r < visited.size(); ++r) EXPECT_TRUE(visited[r]) << "room " << r;
}

// The rooms in the order the tour stands in them (a room again after another counts again;
// doorway cells count for none).
std::vector<int> roomsWalked(const FloorGrid& g, const FloorPlan& plan, const std::vector<glm::dvec3>& tour) {
    std::vector<int> rooms;
    for (std::size_t n = 0; n + 1 < tour.size(); ++n)
        for (int t = 0; t <= 20; ++t) {
            const int r = plan.room[g.cellAt(glm::mix(xz(tour[n]), xz(tour[n + 1]), t / 20.0))];
            if (r >= 0 && (rooms.empty() || rooms.back() != r)) rooms.push_back(r);
        }
    return rooms;
}

// From A the only doorway leads to C, from C to B and D: the tour goes A, C, then the nearer of
// B and D, back through C to the other and stops there; a depth-first tour that walks every
// way back would stand in A, C, B, C, D, C, A.
TEST(RoomTour, GoesToTheNearestRoomNotSeenAndDoesNotWalkBack) {
    const FloorGrid g = gridOf(fourRooms());
    const FloorPlan plan = findRooms(g);
    ASSERT_EQ(plan.rooms.size(), 4u);
    const std::vector<int> rooms = roomsWalked(g, plan, roomTour(g, plan, 1.7));
    ASSERT_EQ(rooms.size(), 5u);
    const int a = rooms[0], c = rooms[1];
    EXPECT_EQ(a, 0);  // the largest room
    EXPECT_EQ(rooms[3], c);
    EXPECT_NE(rooms[2], rooms[4]);
    EXPECT_NE(rooms[4], a);
}

// A's door narrowed to a 0.5 m slit is no doorway, but a person walks through it: the tour
// reaches C over the slit's floor and from there every room, crossing no wall.
TEST(RoomTour, ReachesRoomsNoDoorwayJoinsOverOtherFloor) {
    const SlitRooms s = slitRooms();
    ASSERT_EQ(s.plan.rooms.size(), 4u);
    ASSERT_EQ(s.plan.doorways.size(), 2u);  // B-C and C-D only
    const std::vector<glm::dvec3> tour = roomTour(s.grid, s.plan, 1.7);
    std::vector<glm::dvec2> plan;
    for (const glm::dvec3& p : tour) plan.push_back(xz(p));
    expectCrossesNoWall(plan, s.walls);
    std::vector<int> rooms = roomsWalked(s.grid, s.plan, tour);
    std::sort(rooms.begin(), rooms.end());
    rooms.erase(std::unique(rooms.begin(), rooms.end()), rooms.end());
    EXPECT_EQ(rooms, (std::vector<int>{0, 1, 2, 3}));
}

// The cells cut along the rooms walk the same tour, which crosses none of their real walls
// (the quads along the walls where two cells meet).
TEST(RoomTour, RoomCellsWalkItWithoutCrossingTheirRealWalls) {
    const FloorGrid g = gridOf(fourRooms());
    const FloorPlan plan = findRooms(g);
    scenes::SceneDescription base;
    base.name = "tour";
    const scenes::SceneDescription d = describeRooms(base, g, plan, 0.0, 3.0, 1.7);
    EXPECT_EQ(d.walkPath, roomTour(g, plan, 1.7));
    ASSERT_FALSE(d.realWalls.empty());
    for (std::size_t n = 0; n + 1 < d.walkPath.size(); ++n) {
        EXPECT_GE(scenes::findCell(d.cells, d.walkPath[n]), 0) << n;
        for (const scenes::RealWall& w : d.realWalls)
            EXPECT_FALSE(segmentsMeet(xz(d.walkPath[n]), xz(d.walkPath[n + 1]), xz(w.lowerLeft), xz(w.lowerRight)))
                << "segment " << n << " crosses " << w.name;
    }
}

// Rooms no doorway joins are joined by other floor off the walls: A's door narrowed to a 0.5 m
// slit (narrower than a door: no doorway) still lets a route from A into C through it.
TEST(RoomTour, RoutesTakeOtherFloorWhereNoDoorwayJoins) {
    const SlitRooms s = slitRooms();
    ASSERT_EQ(s.plan.rooms.size(), 4u);
    ASSERT_EQ(s.plan.doorways.size(), 2u);  // B-C and C-D only
    const std::vector<glm::dvec2> route = roomRoute(s.grid, s.plan, {2.0, 6.0}, {7.5, 6.0});
    ASSERT_GE(route.size(), 2u);
    expectCrossesNoWall(route, s.walls);
}

// A tour kept to x < 9 (a grid candidate's rectangle) leaves D, beyond its doorway at x = 9, out.
TEST(RoomTour, KeepsToWhereItIsHeld) {
    const FloorGrid g = gridOf(fourRooms());
    const FloorPlan plan = findRooms(g);
    const std::vector<glm::dvec3> tour = roomTour(g, plan, 1.7, {}, [](glm::dvec2 p) { return p.x < 9.0; });
    ASSERT_GE(tour.size(), 2u);
    for (const glm::dvec3& p : tour) EXPECT_LT(p.x, 9.0);
    EXPECT_GT(roomTour(g, plan, 1.7).size(), tour.size());
}

// A route between two points walks over rooms and doorways: from B through C into A's upper
// half, crossing no wall; a point 2 m outside the outline has no room cell within 1 m.
TEST(RoomTour, RoutesKeepToRoomsAndDoorways) {
    const std::vector<WallRect> walls = fourRooms();
    const FloorGrid g = gridOf(walls);
    const FloorPlan plan = findRooms(g);
    const glm::dvec2 from(10.0, 2.0), to(2.0, 6.0);
    const std::vector<glm::dvec2> route = roomRoute(g, plan, from, to);
    ASSERT_GE(route.size(), 4u);  // at least a turn at each of the two doorways
    EXPECT_EQ(route.front(), from);
    EXPECT_EQ(route.back(), to);
    for (std::size_t n = 0; n + 1 < route.size(); ++n)
        for (std::size_t w = 0; w < walls.size(); ++w)
            EXPECT_FALSE(crosses(route[n], route[n + 1], walls[w])) << "segment " << n << ", wall " << w;
    EXPECT_TRUE(roomRoute(g, plan, from, {2.0, 10.0}).empty());
}

}  // namespace
}  // namespace cavewall::walls
