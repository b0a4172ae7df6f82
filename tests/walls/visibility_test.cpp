#include "scenes/primitives.h"
#include "walls/visibility.h"

#include "tests/walls/test_scenes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <random>
#include <string>

namespace cavewall::walls {
namespace {

// A hand-made house (floor plan, x to the right, z down):
//   hall [0,4]x[0,4] | door (portal in a real wall) | kitchen [4,8]x[0,4] | open | annex [8,12]x[0,4]
//   garden [0,4]x[4,8] below the hall behind a virtual wall; cellar [4,8]x[4,8] walled off by
//   real walls from the kitchen and the garden.
enum Cells { kHall, kKitchen, kAnnex, kGarden, kCellar };

scenes::SceneDescription house() {
    scenes::SceneDescription d;
    auto square = [](double x, double z) { return Polygon2{{x, z}, {x + 4, z}, {x + 4, z + 4}, {x, z + 4}}; };
    d.cells = {{"hall", square(0, 0), 0},
               {"kitchen", square(4, 0), 0},
               {"annex", square(8, 0), 0},
               {"garden", square(0, 4), 0},
               {"cellar", square(4, 4), 0}};
    scenes::VirtualWall door{"door",        {4, 0, 1.5},       {4, 0, 2.5},
                             {4, 2.1, 1.5}, {kHall, kKitchen}, scenes::WallKind::Portal};
    scenes::VirtualWall cut{"hall|garden", {4, 0, 4},        {0, 0, 4},
                            {4, 3, 4},     {kHall, kGarden}, scenes::WallKind::Virtual};
    d.walls = {door, cut};
    d.realWalls = {{"hall|kitchen a", {4, 0, 0}, {4, 0, 1.5}, {4, 3, 0}},
                   {"hall|kitchen b", {4, 0, 2.5}, {4, 0, 4}, {4, 3, 2.5}},
                   {"kitchen|cellar", {4, 0, 4}, {8, 0, 4}, {4, 3, 4}},
                   {"garden|cellar", {4, 0, 4}, {4, 0, 8}, {4, 3, 4}}};
    return d;
}

TEST(Visibility, OpenBoundariesAreWhatNoWallCovers) {
    const auto d = house();
    EXPECT_NEAR(openBoundaryLength(d, kKitchen, kAnnex), 4.0, 1e-12);  // nothing on x = 8
    EXPECT_NEAR(openBoundaryLength(d, kHall, kKitchen), 0.0, 1e-12);   // real walls + the door
    EXPECT_NEAR(openBoundaryLength(d, kHall, kGarden), 0.0, 1e-12);    // the virtual wall
    EXPECT_NEAR(openBoundaryLength(d, kHall, kAnnex), 0.0, 1e-12);     // not neighbours
}

// The kitchen and the annex see each other over the open boundary: one pair, one group of two.
TEST(Visibility, DirectGroupsAreTheCellsJoinedByOpenBoundaries) {
    const DirectGroups g = directGroups(computeVisibility(house()));
    EXPECT_EQ(g.pairs, 1);
    EXPECT_EQ(g.largest, 2);
    EXPECT_EQ(g.largestCell, kKitchen);
    EXPECT_EQ(describeDirectGroups(computeVisibility(house()), house()),
              "pairs of cells that see each other directly (joined by edges no wall, portal or virtual wall "
              "covers): 1; the largest group, 2 cells with kitchen, is drawn whole from any of them");
    scenes::SceneDescription closed = house();
    closed.realWalls.push_back({"kitchen|annex", {8, 0, 0}, {8, 0, 4}, {8, 3, 0}});
    const DirectGroups none = directGroups(computeVisibility(closed));
    EXPECT_EQ(none.pairs, 0);
    EXPECT_EQ(none.largest, 0);
    EXPECT_EQ(none.largestCell, -1);
    EXPECT_EQ(describeDirectGroups(computeVisibility(closed), closed), "");
}

TEST(Visibility, HouseTable) {
    const auto d = house();
    const VisibilityTable t = computeVisibility(d);
    using V = CellVisibility;
    // Rows: from; columns: hall, kitchen, annex, garden, cellar. Each entry is argued in the
    // comment of its row.
    const V expected[5][5] = {
        // hall: the door shows the kitchen and, through the open boundary, the annex; the
        // virtual wall shows the garden; the cellar is behind real walls everywhere.
        {V::Geometry, V::Texture, V::Texture, V::Texture, V::Hidden},
        // kitchen: the annex is open to it; the door shows the hall and (through the virtual
        // wall behind the hall, still behind the door's plane) the garden.
        {V::Texture, V::Geometry, V::Geometry, V::Texture, V::Hidden},
        // annex: same group as the kitchen.
        {V::Texture, V::Geometry, V::Geometry, V::Texture, V::Hidden},
        // garden: the virtual wall shows the hall and, through the door, the kitchen and annex.
        {V::Texture, V::Texture, V::Texture, V::Geometry, V::Hidden},
        // cellar: walled in.
        {V::Hidden, V::Hidden, V::Hidden, V::Hidden, V::Geometry},
    };
    for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 5; ++b) {
            SCOPED_TRACE(d.cells[a].name + " -> " + d.cells[b].name);
            EXPECT_EQ(t.at(a, b), expected[a][b]) << toString(t.at(a, b));
        }
    EXPECT_EQ(t.throughWalls(kHall, kAnnex), std::vector<int>{0});   // the door
    EXPECT_EQ(t.throughWalls(kHall, kGarden), std::vector<int>{1});  // the virtual wall
    EXPECT_EQ(t.throughWalls(kKitchen, kGarden), std::vector<int>{0});
}

TEST(Visibility, ClassifiesBoxesAgainstAWall) {
    // Wall in the plane z = 0, x in [-2, 2], y in [0, 3], front (side 0) towards +z.
    const display::ScreenQuad wall{{-2, 0, 0}, {2, 0, 0}, {-2, 3, 0}};
    auto box = [](glm::dvec3 lo, glm::dvec3 hi) {
        scenes::Bounds b;
        b.add(lo), b.add(hi);
        return b;
    };
    const struct {
        const char* name;
        scenes::Bounds bounds;
        Placement front, back;
    } cases[] = {
        {"behind", box({-1, 0, -3}, {1, 1, -1}), Placement::Behind, Placement::InFront},
        {"touching from behind", box({-1, 0, -1}, {1, 1, 0}), Placement::Behind, Placement::InFront},
        {"in front", box({-1, 0, 1}, {1, 1, 2}), Placement::InFront, Placement::Behind},
        {"through the middle", box({-0.5, 0, -1}, {0.5, 1, 1}), Placement::Intersecting, Placement::Intersecting},
        {"through an edge", box({1.5, 0, -1}, {3, 1, 1}), Placement::Intersecting, Placement::Intersecting},
        {"beside the wall", box({3, 0, -1}, {4, 1, 1}), Placement::Beside, Placement::Beside},
        {"above the wall", box({-1, 3.5, -1}, {1, 4, 1}), Placement::Beside, Placement::Beside},
        // Crosses the plane only in its corner region beyond x = 2 although its box spans
        // x = 1.9..: the section at z = 0 is x in [1.9, 2.5], which overlaps [-2, 2].
        {"just overlapping the side", box({1.9, 0, -0.1}, {2.5, 0.5, 0.1}), Placement::Intersecting,
         Placement::Intersecting},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(classify(c.bounds, wall, 0), c.front) << toString(classify(c.bounds, wall, 0));
        EXPECT_EQ(classify(c.bounds, wall, 1), c.back) << toString(classify(c.bounds, wall, 1));
    }
}

TEST(Visibility, WallContentsAndDepthBehind) {
    // The hall test scene: wall at z = 0 facing +z between "front" (z > 0) and "back" (z < 0).
    const auto d = testing::hall();
    scenes::Scene scene;
    scene.meshes.push_back(scenes::makeBox({1, 1, 1}, {1, 1, 1, 1}));
    auto place = [&](glm::dvec3 centre, scenes::Role role, int cell) {
        const int i = scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), centre), "box", role);
        scene.objects[i].cell = cell;
        return i;
    };
    const int deep = place({0, 0.5, -7.5}, scenes::Role::Content, 1);  // 8 m behind at its far face
    const int shallow = place({2, 0.5, -1}, scenes::Role::Content, 1);
    const int structure = place({0, 0.5, -9.5}, scenes::Role::Structure, 1);  // never baked
    const int crossing = place({-3, 0.5, 0}, scenes::Role::Content, 0);
    const int front = place({0, 0.5, 3}, scenes::Role::Content, 0);
    const VisibilityTable t = computeVisibility(d);
    const WallContents fromFront = wallContents(scene, d, t, 0, 0);
    EXPECT_EQ(fromFront.baked, (std::vector<int>{deep, shallow}));
    EXPECT_EQ(fromFront.intersecting, std::vector<int>{crossing});
    EXPECT_DOUBLE_EQ(fromFront.depthBehind, 8.0);
    const WallContents fromBack = wallContents(scene, d, t, 0, 1);
    EXPECT_EQ(fromBack.baked, std::vector<int>{front});
    EXPECT_DOUBLE_EQ(fromBack.depthBehind, 3.5);
    (void)structure;
}

// The rule of wallContents (visibility.h) applied to every object, without any filtering: the
// reference the filtered implementation must equal.
WallContents everyObjectContents(const scenes::Scene& scene, const scenes::SceneDescription& d,
                                 const VisibilityTable& t, int wall, int side) {
    WallContents out;
    const scenes::VirtualWall& w = d.walls[wall];
    const display::ScreenQuad q{w.lowerLeft, w.lowerRight, w.upperLeft};
    const int viewer = w.cells[side];
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        const scenes::Object& o = scene.objects[i];
        if (o.role == scenes::Role::Structure || o.worldBounds.empty()) continue;
        const Placement p = classify(o.worldBounds, q, side);
        if (p == Placement::Intersecting) out.intersecting.push_back(i);
        if (p != Placement::Behind) continue;
        // Shown through the wall from one of its cells (cells out of the table show nothing).
        bool shown = o.cell < 0 || viewer < 0;
        for (int c : scenes::cellsOf(o)) {
            if (c >= t.cellCount) continue;
            const auto& through = t.throughWalls(viewer, c);
            shown = shown || std::find(through.begin(), through.end(), wall) != through.end();
        }
        if (shown) out.baked.push_back(i);
    }
    return out;
}

TEST(Visibility, WallContentsEqualsClassifyingEveryObject) {
    // wallContents classifies only objects that may be shown through the wall or touch its
    // rectangle's box. Random boxes of every size in random (also wrong or unknown) cells,
    // many touching a wall's edges, must give exactly the lists of classifying them all.
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> u(0, 1);
    int baked = 0, intersecting = 0;
    for (const scenes::SceneDescription& d : {house(), testing::threeInARow()}) {
        SCOPED_TRACE(d.name);
        glm::dvec3 lo(1e9), hi(-1e9);
        for (const scenes::Cell& c : d.cells)
            for (const glm::dvec2& p : c.region) {
                lo = glm::min(lo, {p.x, -1, p.y});
                hi = glm::max(hi, {p.x, 5, p.y});
            }
        scenes::Scene scene;
        for (int i = 0; i < 600; ++i) {
            scenes::Object o;
            // Every third box is centred near a wall's rectangle (within a metre of its plane).
            const scenes::VirtualWall& w = d.walls[i % d.walls.size()];
            const glm::dvec3 onWall = w.lowerLeft + (u(rng) * 1.4 - 0.2) * (w.lowerRight - w.lowerLeft) +
                                      (u(rng) * 1.4 - 0.2) * (w.upperLeft - w.lowerLeft) +
                                      glm::dvec3(u(rng) - 0.5, 0, u(rng) - 0.5);
            const glm::dvec3 centre =
                i % 3 == 0 ? onWall : lo - 1.0 + (hi - lo + 2.0) * glm::dvec3(u(rng), u(rng), u(rng));
            const glm::dvec3 half = glm::dvec3(u(rng), u(rng), u(rng)) * (i % 10 == 0 ? 4.0 : 0.6);
            o.worldBounds.add(centre - half), o.worldBounds.add(centre + half);
            o.cell = int(u(rng) * (d.cells.size() + 2)) - 1;  // -1 (unknown) .. cellCount (out of the table)
            if (o.cell >= 0 && i % 4 == 1) o.moreCells = {int(u(rng) * (d.cells.size() + 1))};  // a second cell
            o.role = i % 17 == 0 ? scenes::Role::Structure : scenes::Role::Content;
            scene.objects.push_back(o);
        }
        // A box exactly on a wall's plane edge-to-edge with its rectangle, and an empty one.
        const scenes::VirtualWall& w0 = d.walls[0];
        scene.objects.push_back({});
        scene.objects.back().worldBounds.add(w0.lowerLeft),
            scene.objects.back().worldBounds.add(w0.upperLeft + (w0.lowerRight - w0.lowerLeft));
        scene.objects.push_back({});
        const VisibilityTable t = computeVisibility(d);
        for (int wall = 0; wall < int(d.walls.size()); ++wall)
            for (int side = 0; side < 2; ++side) {
                if (d.walls[wall].cells[side] < 0) continue;
                SCOPED_TRACE(d.walls[wall].name + " side " + std::to_string(side));
                const WallContents expected = everyObjectContents(scene, d, t, wall, side);
                const WallContents got = wallContents(scene, d, t, wall, side);
                EXPECT_EQ(got.baked, expected.baked);
                EXPECT_EQ(got.intersecting, expected.intersecting);
                baked += int(expected.baked.size());
                intersecting += int(expected.intersecting.size());
            }
    }
    // Both lists are well populated, so a filter dropping objects would show.
    EXPECT_GT(baked, 200);
    EXPECT_GT(intersecting, 100);
}

}  // namespace
}  // namespace cavewall::walls
