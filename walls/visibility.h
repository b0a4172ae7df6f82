#pragma once
// Cell-to-cell visibility (Teller's lookup table, simplified as in Ebbesmeyer 1997, section 5)
// and the classification of scene objects against virtual walls.
//
// Cells joined by an open boundary (a shared floor edge not covered by any wall's footprint)
// see each other directly and are drawn as geometry. Virtual walls and portals occlude: the
// cells behind them (reached through further virtual walls, portals or open boundaries, and at
// least partly behind the wall's plane) are shown by the wall's textures. Real walls occlude
// completely; cells joined only through a real wall without a portal are hidden.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/plan.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::walls {

enum class CellVisibility : std::uint8_t { Hidden, Geometry, Texture };
const char* toString(CellVisibility v);

struct VisibilityTable {
    int cellCount = 0;
    std::vector<CellVisibility> entries;  // [from * cellCount + to]
    std::vector<std::vector<int>> walls;  // [from * cellCount + to]: walls whose textures show `to`

    CellVisibility at(int from, int to) const { return entries[std::size_t(from) * cellCount + to]; }
    const std::vector<int>& throughWalls(int from, int to) const { return walls[std::size_t(from) * cellCount + to]; }
};

VisibilityTable computeVisibility(const scenes::SceneDescription& description);

// Cells that see each other directly (Geometry entries between two cells: joined, perhaps
// through others, by edges no wall covers). A frame draws such a group whole from any of its
// cells, so one large group costs what the cells were meant to save.
struct DirectGroups {
    int pairs = 0;         // unordered pairs of cells that see each other directly
    int largest = 0;       // cells in the largest group (0 when there is no pair)
    int largestCell = -1;  // its first cell by index
};
DirectGroups directGroups(const VisibilityTable& table);
// One line for `plan` and `walls`: "pairs of cells that see each other directly (...): N; the
// largest group, M cells with NAME, is drawn whole from any of them", or "" when there are none.
std::string describeDirectGroups(const VisibilityTable& table, const scenes::SceneDescription& description);

// Length (metres) of the boundary cells a and b share that no wall (virtual, portal or real)
// reaching into the first metre above a's floor covers; 0 between cells whose floors differ by
// more than 1 m (different storeys, stacked or side by side).
double openBoundaryLength(const scenes::SceneDescription& description, int a, int b);

// The parts of cell a's boundary that no wall (virtual, portal or real) reaching into the first
// metre above its floor covers, as floor segments (x, z), each longer than a millimetre: where
// the cell is open to its neighbours and to floor no cell holds.
std::vector<std::array<glm::dvec2, 2>> openBoundary(const scenes::SceneDescription& description, int a);

// Where an axis-aligned box is relative to a wall seen from `side` (0: the front, i.e. the side
// the wall's normal points to). Exact for the box.
enum class Placement : std::uint8_t {
    Behind,        // entirely on the far side of the plane (touching allowed): baked
    Intersecting,  // crosses the plane within the wall rectangle: drawn as geometry, never baked
    InFront,       // entirely on the viewer's side
    Beside,        // crosses the plane outside the rectangle: drawn by its own cell, not baked
};
const char* toString(Placement p);
Placement classify(const scenes::Bounds& bounds, const display::ScreenQuad& wall, int side);

struct WallContents {
    std::vector<int> baked;         // object indices in the wall's texture for this side
    std::vector<int> intersecting;  // content objects crossing the wall (drawn as geometry)
    double depthBehind = 0.0;       // metres: deepest baked box corner behind the plane
    double depthNear = 0.0;         // metres: nearest baked box corner behind the plane (>= 0;
                                    // 0 when nothing is baked)
};

// What the textures of `wall` seen from `side` show: content objects behind the plane whose
// cell the table shows through this wall (or whose cell is unknown). Structure never.
// Only objects of such cells and objects whose box touches the wall rectangle's box are
// classified (the rest can be neither), so a wall costs little beyond a pass over the objects.
WallContents wallContents(const scenes::Scene& scene, const scenes::SceneDescription& description,
                          const VisibilityTable& table, int wall, int side);

// Sets every PlannedWall::depthBehind to the largest of its two sides' depths and depthNear to
// the smallest nearest depth of its sides that bake something (0 when neither does).
void assignDepthBehind(Plan& plan, const scenes::Scene& scene, const scenes::SceneDescription& description,
                       const VisibilityTable& table);

// The same per wall of `description`, as (depthNear, depthBehind): planZones' depthSpans.
std::vector<glm::dvec2> wallDepthSpans(const scenes::Scene& scene, const scenes::SceneDescription& description,
                                       const VisibilityTable& table);

// The span of one wall from its sides' contents (nullptr for a side without a cell).
glm::dvec2 depthSpanOf(const WallContents* front, const WallContents* back);

}  // namespace cavewall::walls
