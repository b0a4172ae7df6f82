#pragma once
// How a scene's objects are given to its cells (scene_description.h). GL-free.
//
// An object belongs to every cell it overlaps, so that a cell drawn as geometry draws all of
// what stands in it: a long wall, a ceiling over several rooms or a duct through them is drawn
// by each of those cells (objects are not cut at cell borders). It overlaps cell c when
//   - in plan, its world box's (x, z) rectangle grown by `reach` on every side shares area with
//     c's region (a room cell found in a floor plan stops at its walls' faces, so the walls
//     themselves lie just outside it), and
//   - in height, its box reaches above c's floor less kBelowFloor and starts below c's top
//     less kAboveTop, c's top being the lowest floor of the cells over it in plan that lie at
//     least kMinStoreyHeight higher (none: no top): the slab between two storeys belongs to
//     both, a wall standing on the upper floor only to the upper storey.
// A cell whose storey is open to the storey above (scenes/storey_voids.h: an atrium, a
// double-height hall, a stair's opening; found from the floor slabs, so the gaps between the
// upper storey's room cells are none) also holds the upper storey's objects seen over that void:
// those whose box starts at or above the cell's top less kAboveTop and below the upper storey's
// top less kAboveTop, and whose plan rectangle, grown by `reach` and by the box's height over the
// cell's top (a sight line at 45° through the void's edge; at most kVoidSightMetres), meets the
// void. A viewer under the void looking up at 45° or steeper sees no farther over the slab.
// The other way round, a cell of the upper storey whose region's plan bounds lie within
// kDownReachMetres of the void also holds the lower storey's objects seen through the void:
// those meeting the lower cell's height range whose plan rectangle, grown by `reach` and by the
// depth of the box's lowest point under the upper floor (at most kVoidSightMetres), meets the
// void within kDownReachMetres of the cell's plan bounds. An eye at most 2 m over the upper
// floor looking down at 45° or steeper crosses the floor's level within 2 m of where it stands,
// and its sight line then reaches under the slab beyond the void's edge as far as it descends.
// A lower object in no cell (drawn with every cell) is given no upper cell.
// Object::cell is the cell among them holding the box's centre in plan, else the one sharing
// the most area; Object::moreCells the others. An object overlapping no cell keeps
// findCell's cell of its centre (scenes/region.h) when its height range meets that cell's,
// else none (-1: drawn with every cell).

#include "scenes/scene.h"
#include "scenes/scene_description.h"

#include <vector>

namespace cavewall::scenes {

inline constexpr double kCellReachMetres = 0.3;  // metres an object's box is grown in plan
inline constexpr double kMinStoreyHeight = 1.0;  // metres between floors of two storeys
inline constexpr double kBelowFloor = 0.5;       // metres under a cell's floor it still holds
inline constexpr double kAboveTop = 0.05;        // metres an object must reach under a cell's top
inline constexpr double kVoidSightMetres = 6.0;  // most metres an object over a void is grown by
inline constexpr double kDownReachMetres = 2.0;  // metres from a void a cell looking down through it may lie

struct CellsOfBox {
    int cell = -1;               // -1: none
    std::vector<int> moreCells;  // ascending, without `cell`
};

// The cells a world box belongs to (see the top of this file), voids left out (they need the
// scene's slabs: assignCells).
CellsOfBox cellsOfBox(const std::vector<Cell>& cells, const Bounds& box, double reach = kCellReachMetres);

// Sets Object::cell and Object::moreCells of every object of `scene` from its world bounds,
// voids included.
void assignCells(Scene& scene, const std::vector<Cell>& cells, double reach = kCellReachMetres);

}  // namespace cavewall::scenes
