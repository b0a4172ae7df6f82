// scene.json parsing and validation: one case per rule, with its message.
#include "config/error.h"
#include "scenes/loader.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::scenes {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Two 4 m x 4 m cells side by side along x, split by a virtual wall at x = 0 facing A (-x).
const std::string kCells = R"(
  "cells": [{"name": "A", "region": [[-4, 2], [0, 2], [0, -2], [-4, -2]]},
            {"name": "B", "region": [[0, 2], [4, 2], [4, -2], [0, -2]]}])";
// Its front (lowerLeft->lowerRight x lowerLeft->upperLeft) points to -x: A, its first cell.
const std::string kWall = R"({"name": "AB", "cells": ["A", "B"],
   "lowerLeft": [0, 0, -2], "lowerRight": [0, 0, 2], "upperLeft": [0, 3, -2]})";

std::filesystem::path folder() {
    const auto dir = testing::testOutput("description");
    testing::triangleFile().write("../description/model.gltf");
    return dir;
}

std::string scene(const std::string& extra, const std::string& walls = kWall, const std::string& cells = kCells) {
    return R"({"models": [{"file": "model.gltf"}],)" + cells + R"(, "walls": [)" + walls + "]" + extra + "}";
}

SceneDescription load(const std::string& text) {
    SceneDescription d = parseSceneDescription(text, "scene.json", folder());
    validateSceneDescription(d, "scene.json");
    return d;
}

TEST(SceneDescription, ParsesEveryFieldAndRoundTrips) {
    const SceneDescription d = load(scene(R"(, "name": "two", "viewer": {"eyeHeight": 1.6, "headHeightRange": [1, 2.2]},
        "planning": {"minZone": 2.5, "maxRes": 256},
        "realWalls": [{"name": "north", "lowerLeft": [-4, 0, -2], "lowerRight": [4, 0, -2], "upperLeft": [-4, 3, -2]}],
        "walkPath": [[-2, 1.6, 0], [2, 1.6, 0], [2, 1.6, 1]], "walkBreaks": [2],
        "wallPath": [[-0.3, 1.6, 1], [0.3, 1.6, 1], [0.3, 1.6, -1]])"));
    EXPECT_EQ(d.name, "two");
    ASSERT_EQ(d.cells.size(), 2u);
    ASSERT_EQ(d.walls.size(), 1u);
    EXPECT_EQ(d.walls[0].cells, (std::array<int, 2>{0, 1}));
    EXPECT_EQ(d.walls[0].kind, WallKind::Virtual);
    EXPECT_EQ(d.eyeHeight, 1.6);
    EXPECT_EQ(d.headHeightRange, glm::dvec2(1, 2.2));
    EXPECT_EQ(d.walkPath.size(), 3u);
    EXPECT_EQ(d.walkBreaks, std::vector<int>{2});
    EXPECT_EQ(d.wallPath.size(), 3u);
    EXPECT_EQ(d.planning, (SceneDescription::Planning{2.5, 256}));
    // The file lists A clockwise seen from above; it is stored counter-clockwise (positive area).
    EXPECT_EQ(regionArea(d.cells[0].region), 16.0);
    const SceneDescription again = parseSceneDescription(writeSceneDescription(d), "again.json", d.folder);
    EXPECT_EQ(again, d);
    EXPECT_EQ(writeSceneDescription(again), writeSceneDescription(d));  // stable bytes
}

TEST(SceneDescription, SplitMetresRoundTrips) {
    const SceneDescription d = load(R"({"models": [{"file": "model.gltf", "splitMetres": 3}],)" + kCells.substr(1) +
                                    R"(, "walls": [)" + kWall + "]}");
    EXPECT_EQ(d.models[0].splitMetres, 3.0);
    const SceneDescription again = parseSceneDescription(writeSceneDescription(d), "again.json", d.folder);
    EXPECT_EQ(again, d);
}

TEST(SceneDescription, PlacementUnitsAndUpAxisMoveObjects) {
    const SceneDescription d = load(R"({"models": [
        {"file": "model.gltf", "metresPerUnit": 0.5, "up": "z", "position": [10, 0, 0], "structureNodes": ["no*e 0"]}]})");
    const Scene s = loadScene(d);
    ASSERT_EQ(s.objects.size(), 1u);
    // Vertex (0, 1, 0) of the triangle: halved to (0, 0.5, 0); Z-up to Y-up sends +Y to -Z:
    // (0, 0, -0.5); then moved by (10, 0, 0).
    const glm::dvec4 p = s.objects[0].worldFromModel * glm::dvec4(0, 1, 0, 1);
    EXPECT_NEAR(p.x, 10.0, 1e-12);
    EXPECT_NEAR(p.y, 0.0, 1e-12);
    EXPECT_NEAR(p.z, -0.5, 1e-12);
    EXPECT_EQ(s.objects[0].role, Role::Structure);  // "node 0" matches "no*e 0"
    EXPECT_EQ(s.objects[0].cell, -1);               // no cells
}

TEST(SceneDescription, UnitNamesGiveMetresPerUnit) {
    const std::pair<const char*, double> units[] = {
        {"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}};
    for (const auto& [name, metres] : units) {
        SCOPED_TRACE(name);
        const SceneDescription d =
            load(std::string(R"({"models": [{"file": "model.gltf", "units": ")") + name + "\"}]}");
        EXPECT_EQ(d.models[0].metresPerUnit, metres);
    }
}

TEST(SceneDescription, ObjectsGetTheCellOfTheirCentre) {
    SceneDescription d = load(scene(R"(, "models": [{"file": "model.gltf", "position": [1, 0, 0]}])"));
    // The triangle's centre (0.5, 0.5, 0) moved to x = 1.5 lies in B.
    EXPECT_EQ(loadScene(d).objects[0].cell, 1);
}

struct BadCase {
    const char* name;
    std::string json;
    const char* message;
};

TEST(SceneDescription, EveryRuleHasItsMessage) {
    const BadCase cases[] = {
        {"unknown key", scene(R"(, "walkpath": [])"), "scene.json: unknown key 'walkpath'"},
        {"unknown wall key", scene("", R"({"name": "x", "cell": []})"), "scene.json: walls[0]: unknown key 'cell'"},
        {"unknown planning key", scene(R"(, "planning": {"alpha": 5})"), "scene.json: planning: unknown key 'alpha'"},
        {"texture side out of range", scene(R"(, "planning": {"maxRes": 8})"),
         "scene.json: planning.maxRes: expected an integer in [16, 16384], got 8"},
        {"zone size out of range", scene(R"(, "planning": {"minZone": 0})"),
         "scene.json: planning.minZone: expected a number in [0.01, 1000], got 0"},
        {"no models", R"({"models": []})", "scene.json: models: expected an array of at least 1 elements, got 0"},
        {"missing file", R"({"models": [{"file": "nope.glb"}]})",
         "scene.json: models[0].file: 'nope.glb' does not exist"},
        {"wall names a missing cell", scene("", R"({"name": "x", "cells": ["A", "C"], "lowerLeft": [0,0,2],
           "lowerRight": [0,0,-2], "upperLeft": [0,3,2]})"),
         "scene.json: walls[0].cells[1]: cell 'C' does not exist (expected one of: A, B)"},
        {"wall names one cell twice", scene("", R"({"name": "x", "cells": ["A", "A"], "lowerLeft": [0,0,2],
           "lowerRight": [0,0,-2], "upperLeft": [0,3,2]})"),
         "scene.json: walls[0].cells: names the same cell twice (expected two different cells, got 'A' twice)"},
        {"wall not a rectangle", scene("", R"({"name": "x", "cells": ["A", "B"], "lowerLeft": [0,0,2],
           "lowerRight": [0,0,-2], "upperLeft": [0,3,3]})"),
         // right = (0, 0, -4), up = (0, 3, 1): cos = -4 / (4 * sqrt(10)), acos = 108.435°.
         "scene.json: walls[0]: not a rectangle (expected a right angle at lowerLeft, got 108.435°)"},
        {"wall facing its second cell", scene("", R"({"name": "x", "cells": ["A", "B"], "lowerLeft": [0,0,2],
           "lowerRight": [0,0,-2], "upperLeft": [0,3,2]})"),
         "scene.json: walls[0]: 'x' faces its second cell 'B' (expected its front, lowerLeft->lowerRight x "
         "lowerLeft->upperLeft, pointing to (1, 0, 0), to face its first cell 'A'); swap the two cells, or lowerLeft "
         "with lowerRight"},
        {"wall not vertical", scene("", R"({"name": "x", "cells": ["A", "B"], "lowerLeft": [0,0,2],
           "lowerRight": [0,0,-2], "upperLeft": [1,3,2]})"),
         "scene.json: walls[0]: not vertical (expected a normal with no vertical component"},
        {"wall collinear", scene("", R"({"name": "x", "cells": ["A", "B"], "lowerLeft": [0,0,2],
           "lowerRight": [0,0,-2], "upperLeft": [0,0,4]})"),
         "scene.json: walls[0]: corners are collinear or repeated (expected a non-zero area, got 0 m²)"},
        {"real wall upside down", scene(R"(, "realWalls": [{"name": "r", "lowerLeft": [0,3,2], "lowerRight": [0,3,-2],
           "upperLeft": [0,0,2]}])"),
         "scene.json: realWalls[0]: upperLeft is not above lowerLeft"},
        {"cell without region", scene("", "", R"("cells": [{"name": "A"}])"),
         "scene.json: cells[0]: missing required key 'region'"},
        {"cell with two points", scene("", "", R"("cells": [{"name": "A", "region": [[0,0],[1,0]]}])"),
         "scene.json: cells[0].region: expected a polygon of at least 3 points, got 2"},
        {"degenerate cell", scene("", "", R"("cells": [{"name": "A", "region": [[0,0],[1,0],[2,0]]}])"),
         "scene.json: cells[0].region: degenerate polygon (expected a non-zero area, got 0 m²)"},
        {"non-convex cell", scene("", "", R"("cells": [{"name": "A", "region": [[0,0],[4,0],[4,-4],[2,-1],[0,-4]]}])"),
         "scene.json: cells[0].region: not convex (expected every corner to turn left seen from above, got a right "
         "turn at point 3)"},
        {"overlapping cells", scene("", "", R"("cells": [{"name": "A", "region": [[0,0],[4,0],[4,-4],[0,-4]]},
           {"name": "B", "region": [[3,0],[6,0],[6,-4],[3,-4]]}])"),
         "scene.json: cells[1]: overlaps cells[0] 'A' (expected cells that at most touch, got 4 m² in common)"},
        {"duplicate cell", scene("", "", R"("cells": [{"name": "A", "region": [[0,0],[4,0],[4,-4]]},
           {"name": "A", "region": [[5,0],[6,0],[6,-4]]}])"),
         "scene.json: cells[1].name: duplicate cell name 'A' (expected unique names)"},
        {"path leaves the cells", scene(R"(, "walkPath": [[0, 1.7, 0], [9, 1.7, 0]])"),
         "scene.json: walkPath[1]: point (9, 1.7, 0) is outside every cell (expected a point inside a cell's region)"},
        {"walk break past the path", scene(R"(, "walkPath": [[0, 1.7, 0], [1, 1.7, 0]], "walkBreaks": [2])"),
         "scene.json: walkBreaks[0]: expected an index of walkPath above 0 and below 2, got 2"},
        {"walk breaks out of order",
         scene(R"(, "walkPath": [[0, 1.7, 0], [1, 1.7, 0], [1, 1.7, 1]], "walkBreaks": [2, 1])"),
         "scene.json: walkBreaks[1]: expected an index of walkPath above 2 and below 3, got 1"},
        {"wall path leaves the cells", scene(R"(, "wallPath": [[0, 1.7, 0], [0, 1.7, 9]])"),
         "scene.json: wallPath[1]: point (0, 1.7, 9) is outside every cell (expected a point inside a cell's region)"},
        {"bad head range", scene(R"(, "viewer": {"headHeightRange": [2, 1]})"),
         "scene.json: viewer.headHeightRange: expected [low, high] with low < high, got [2, 1]"},
        {"bad kind", scene("", R"({"name": "x", "kind": "door"})"),
         "scene.json: walls[0].kind: expected one of \"virtual\", \"portal\", got \"door\""},
        {"units and metresPerUnit", R"({"models": [{"file": "model.gltf", "units": "mm", "metresPerUnit": 1}]})",
         "scene.json: models[0]: give either 'units' or 'metresPerUnit', not both"},
        {"split too fine", R"({"models": [{"file": "model.gltf", "splitMetres": 0.01}]})",
         "scene.json: models[0].splitMetres: expected a number in [0.1, 1e+06], got 0.01"},
        {"unknown unit", R"({"models": [{"file": "model.gltf", "units": "yd"}]})",
         "scene.json: models[0].units: expected one of \"m\", \"cm\", \"mm\", \"in\", \"ft\", got \"yd\""},
        {"matrix and position", R"({"models": [{"file": "model.gltf", "matrix": [], "position": [0,0,0]}]})",
         "scene.json: models[0]: give either 'matrix' or 'position'/'rotation'/'scale', not both"},
        // Hostile input that would be planned or drawn wrong if accepted.
        {"portal far from its cells", scene("", R"({"name": "x", "kind": "portal", "cells": ["A", "B"],
           "lowerLeft": [100,0,2], "lowerRight": [100,0,-2], "upperLeft": [100,3,2]})"),
         // The footprint x = 100, z in [-2, 2] is 100 m from A's edge x = 0.
         "scene.json: walls[0]: 'x' is 100 m from cell 'A' that it joins (expected its footprint within 0.5 m of "
         "the cell's region)"},
        {"model at 1e300", R"({"models": [{"file": "model.gltf", "position": [1e300, 0, 0]}]})",
         "scene.json: models[0]: point (1e+300, 0, 0) is out of range (expected coordinates within 100000 m of the "
         "origin)"},
        {"cell of 1e308",
         scene("", "", R"("cells": [{"name": "A", "region": [[0,0],[1e308,0],[1e308,-1e308],[0,-1e308]]}])"),
         "scene.json: cells[0].region[1]: point (1e+308, 0, 0) is out of range"},
    };
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { load(c.json); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(SceneDescription, LoadSceneFileAcceptsFolderJsonAndBareGltf) {
    const auto dir = folder();
    std::ofstream(dir / "scene.json") << scene("");
    SceneDescription d;
    const Scene fromFolder = loadSceneFile(dir, &d);
    EXPECT_EQ(d.cells.size(), 2u);
    EXPECT_EQ(d.name, "description");  // the folder's name
    EXPECT_EQ(fromFolder.objects.size(), 1u);
    const Scene bare = loadSceneFile(dir / "model.gltf", &d);
    EXPECT_TRUE(d.cells.empty());
    EXPECT_EQ(bare.triangleCount(), 1u);
    EXPECT_THAT([&] { loadSceneFile(dir / "absent.json"); },
                ThrowsMessage<Error>(HasSubstr("absent.json: cannot open")));
}

TEST(Region, ContainsOverlapAndConvexity) {
    const std::vector<glm::dvec2> square = {{0, 0}, {2, 0}, {2, -2}, {0, -2}};  // CCW from above
    EXPECT_EQ(regionArea(square), 4.0);
    EXPECT_TRUE(regionContains(square, {1, -1}));
    EXPECT_TRUE(regionContains(square, {2, -1}));  // on the boundary
    EXPECT_FALSE(regionContains(square, {1, 1}));
    EXPECT_EQ(firstNonConvexCorner(square), -1);
    // Shifted by (1, -1): overlaps in a 1 x 1 square.
    const std::vector<glm::dvec2> shifted = {{1, -1}, {3, -1}, {3, -3}, {1, -3}};
    EXPECT_NEAR(overlapArea(square, shifted), 1.0, 1e-12);
    const std::vector<glm::dvec2> touching = {{2, 0}, {4, 0}, {4, -2}, {2, -2}};
    EXPECT_EQ(overlapArea(square, touching), 0.0);
}

// regionContains takes either orientation: the square walked clockwise holds the same points,
// its edges included, and refuses the same ones; the tolerance widens both alike.
TEST(Region, ContainsEitherOrientation) {
    const std::vector<glm::dvec2> ccw = {{0, 0}, {2, 0}, {2, -2}, {0, -2}};
    const std::vector<glm::dvec2> cw(ccw.rbegin(), ccw.rend());
    ASSERT_LT(regionArea(cw), 0.0);
    // A pentagon, clockwise seen from above, so that no edge is axis-aligned everywhere.
    const std::vector<glm::dvec2> pentagon = {{0, 0}, {0, -2}, {1, -3}, {2, -2}, {2, 0}};
    ASSERT_LT(regionArea(pentagon), 0.0);
    struct Case {
        const char* name;
        glm::dvec2 p;
        bool inSquare, inPentagon;
    };
    const Case cases[] = {
        {"centre", {1, -1}, true, true},
        {"on an edge", {2, -1}, true, true},
        {"a corner", {0, 0}, true, true},
        {"outside, +z", {1, 1}, false, false},
        {"outside, +x", {2.5, -1}, false, false},
        // Below the square but inside the pentagon's tip (x + z >= -2 holds it: 1 - 2.5 = -1.5).
        {"the pentagon's tip", {1, -2.5}, false, true},
        // Beside the tip, right of its edge from (1, -3) to (2, -2): x - z <= 4 fails (1.9 + 2.9).
        {"beside the tip", {1.9, -2.9}, false, false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(regionContains(ccw, c.p), c.inSquare);
        EXPECT_EQ(regionContains(cw, c.p), c.inSquare);
        EXPECT_EQ(regionContains(pentagon, c.p), c.inPentagon);
    }
    // 1 mm outside an edge: refused at the default 1e-9 m, held at 2 mm, either way round.
    for (const auto* r : {&ccw, &cw}) {
        EXPECT_FALSE(regionContains(*r, {2.001, -1}));
        EXPECT_TRUE(regionContains(*r, {2.001, -1}, 2e-3));
    }
}

// findCell holds a clockwise cell as it does a counter-clockwise one, and picks by storey.
TEST(Cell, FindCellTakesClockwiseRegionsAndTheEyesStorey) {
    const std::vector<glm::dvec2> ccw = {{0, 0}, {2, 0}, {2, -2}, {0, -2}};
    Cell ground{.name = "ground", .region = std::vector<glm::dvec2>(ccw.rbegin(), ccw.rend()), .floorY = 0.0};
    Cell upstairs{.name = "upstairs", .region = ccw, .floorY = 3.0};
    Cell beside{.name = "beside", .region = {{2, 0}, {2, -2}, {4, -2}, {4, 0}}, .floorY = 0.0};  // clockwise
    const std::vector<Cell> cells = {upstairs, ground, beside};
    EXPECT_EQ(findCell(cells, {1, 1.7, -1}), 1);   // the ground floor: upstairs is 1.3 m above the eye
    EXPECT_EQ(findCell(cells, {1, 4.7, -1}), 0);   // upstairs
    EXPECT_EQ(findCell(cells, {1, 2.6, -1}), 0);   // the upper floor 0.4 m above the eye (within 0.5 m): upstairs
    EXPECT_EQ(findCell(cells, {1, -2.0, -1}), 1);  // below every floor: the lowest
    EXPECT_EQ(findCell(cells, {3, 1.7, -1}), 2);   // the clockwise neighbour
    EXPECT_EQ(findCell(cells, {2, 1.7, -1}), 1);   // on the shared edge: the first of equal floors
    EXPECT_EQ(findCell(cells, {5, 1.7, -1}), -1);  // outside every cell
}

}  // namespace
}  // namespace cavewall::scenes
