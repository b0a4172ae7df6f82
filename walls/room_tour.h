#pragma once
// A walk through a storey's rooms (walls/rooms.h) that a person could walk. GL-free.
//
// The tour starts at the largest room's inner point and goes on to the nearest room it has not
// seen: the shortest way over the doorways' graph (a doorway's cost: the metres of its two
// legs), walked leg by leg; a leg goes from a room's inner point to a doorway's centre, or on
// from there to the next room's inner point. It ends in the last room it reaches (it does not
// walk back). Each leg keeps to the cells of its room and of its doorway, so the walk passes a
// wall only through a doorway the rooms finder found. When no doorway leads to a room not seen,
// the walk goes over other floor but a wall's (a closed opening narrower than a door's
// measure, floor that is no room) to the nearest such room's cell and on to its inner point:
// every room a person could walk to is visited, whether or not a doorway joins it.
// A leg is the cheapest walk over its cells (8-neighbours; a diagonal step only where both
// cells beside it are the leg's), where a metre costs 1 at `clearance` or more from the nearest
// other cell (a wall, a closed slit, the outside) and up to `nearWallCost` against it: the walk
// keeps `clearance` from the walls where the room allows. The walk is then thinned to its
// turns: a straight line replaces a run of cells where every cell it passes is the leg's and
// keeps the run's own clearance (at most `clearance`, less half a cell). When the tour reaches
// no other room, the walk goes from the largest room's inner point to its cell nearest the
// middle of its bounds.

#include "walls/floor_grid.h"
#include "walls/rooms.h"

#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace cavewall::walls {

struct RoomTourOptions {
    double clearance = 0.4;      // metres from the walls, where the floor allows
    double nearWallCost = 10.0;  // a metre's cost against a wall (1 at `clearance`), >= 1
};

// The tour of `plan`'s rooms (at least one) found in `grid`, at height eyeY: (x, eyeY, z)
// points, no two consecutive ones equal. With `holds`, a doorway whose legs have a point (x, z)
// where it is false is not walked through, the walks over other floor keep to cells whose
// centres it takes, and a room reached only through such points is not visited.
std::vector<glm::dvec3> roomTour(const FloorGrid& grid, const FloorPlan& plan, double eyeY,
                                 const RoomTourOptions& options = {},
                                 const std::function<bool(glm::dvec2)>& holds = {});

// The cheapest walk from `from` to `to` (x, z) over the cells of every room and doorway of
// `plan` and, where those do not join, over any other floor cell but a wall's (a closed
// opening, a slit), costed and thinned as a tour's leg (such a cell counts as against a wall):
// `from`, the cell nearest it (within 1 m), the walk's turns, the cell nearest `to`, `to`.
// Empty when either point has no such cell within 1 m or no walk joins them.
std::vector<glm::dvec2> roomRoute(const FloorGrid& grid, const FloorPlan& plan, glm::dvec2 from, glm::dvec2 to,
                                  const RoomTourOptions& options = {});

}  // namespace cavewall::walls
