#pragma once
// Cells, portals and virtual walls cut along a storey's rooms (walls/rooms.h). GL-free.
//
// Cells must be convex and must not overlap (scenes/region.h), rooms are neither, so the rooms
// are cut into rectangles along their walls. The root rectangle is the bounds of the rooms'
// cells; a rectangle holding more than one room (the largest holds less than `dominantShare`
// of its room cells) is split in two by the straight cut, along x or z at a grid line, that
// crosses the least open floor (cells with room cells on both sides; walls, doorways and the
// outside are free to cut), at most `maxOpenCut` metres of it or `maxOpenShare` of the cut's
// length, the more (a building-wide cut crosses every corridor), each side keeping at least
// `minRoomArea` of room cells; each metre off the rectangle's middle counts `offMiddleWeight`
// metres of open floor (balanced cuts first, the nearest the middle among equals). The
// rectangle with the most room cells is split first, up to `maxCells` rectangles; a rectangle
// no cut splits keeps its rooms together (merged rooms).
// Where two cells meet, the shared edge is walked cell by cell: along a doorway it is a portal
// (from the floor to `portalHeight`, at most the ceiling), across room cells on both sides a
// virtual wall (floor to ceiling), along walls a real wall (runs of any length: a stub left
// out where a cut crosses a wall would join the two cells as if open). Elsewhere (no floor, as
// over a void, or floor that is no room on a side) the edge stays bare: one sees across it, so
// the two cells see each other directly (walls/visibility.h) and are drawn together.
// The walk path is the rooms' tour through their doorways (walls/room_tour.h) at eye height.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/floor_grid.h"
#include "walls/rooms.h"

namespace cavewall::walls {

struct RoomCellOptions {
    double maxOpenCut = 3.0;        // metres of open floor a cut may cross (a corridor's width)
    double maxOpenShare = 0.25;     // or this share of its length, the more
    double offMiddleWeight = 0.02;  // open metres per metre off the middle
    double dominantShare = 0.9;     // a rectangle with one room holding this share is a cell
    int maxCells = 48;              // per storey
    double portalHeight = 2.1;      // metres above the floor
    double minRoomArea = 2.0;       // m² of room cells either side of a cut
};

// A storey's grid, its rooms and the options they were found with.
struct StoreyRooms {
    StoreyGrid grid;
    FloorPlan plan;
};

// Rasterises storey [floorY, ceilingY) over (x, z) [lo, hi] and finds its rooms. A storey
// without wall elements has no rooms (nothing bounds one): its plan is left empty, every cell
// of no room and no doorway, without the distance transforms the search would cost.
StoreyRooms findStoreyRooms(const scenes::Scene& scene, double floorY, double ceilingY, glm::dvec2 lo, glm::dvec2 hi,
                            const FloorGridOptions& gridOptions = {}, const RoomOptions& roomOptions = {});

// `base` with its cells, walls, real walls and walk path replaced by the rooms' (needs at
// least one room).
scenes::SceneDescription describeRooms(const scenes::SceneDescription& base, const FloorGrid& grid,
                                       const FloorPlan& plan, double floorY, double ceilingY, double eyeHeight,
                                       const RoomCellOptions& options = {});

}  // namespace cavewall::walls
