#pragma once
// Rooms and doorways of one storey, found in its occupancy grid (walls/floor_grid.h). GL-free.
//
// 1. Wall interiors. A wall's slice is its outline; the free cells it encloses (4-connected
//    components of non-wall cells lying wholly within `sliverWidth` / 2 of a wall, by a 3-4
//    chamfer distance) become wall.
// 2. Gaps. Along every row and every column, a run of free cells between two wall cells that
//    is at most `maxDoorWidth` long is a gap, its width the run's length (a closing of the
//    walls by a line as long as a door, in both axes; a diagonal wall's doorway is found where
//    it spans at most maxDoorWidth along x or z). Widths are clear widths in whole cells: a
//    slice marks every cell it passes, so a gap measures up to two cells less than the
//    geometry's opening.
// 3. Openings. The gap cells make 4-connected blobs; a blob of at most maxDoorWidth x
//    `maxWallThickness` m² fills an opening in a wall and closes it. A larger blob is open
//    floor between walls (a corridor narrower than a door, a closet) and stays open.
// 4. Rooms. The floor cells neither wall nor closed opening make 4-connected components; those
//    of at least `minRoomArea` are rooms, in the order of their first cell (row by row, z then x),
//    but for those outside: more than `maxOpenEdgeShare` of their edges, or more than
//    `maxOpenEdge` metres of them, lead to free cells without floor (a roof or a terrace at
//    the floor's height is bounded by its edge, not by walls; a gallery along a void keeps its
//    rooms when the void's edge is shorter).
// 5. Doorways. A closed opening next to two rooms (4-neighbours; with three or more, the two
//    with most neighbouring cells) whose width (its longest gap) is at least `minDoorWidth`
//    joins them. An opening next to one room and to free cells without floor is an exit (an
//    outside door); one next to a single room only is a niche or a window, nothing.

#include "walls/floor_grid.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace cavewall::walls {

struct RoomOptions {
    double minDoorWidth = 0.6;      // metres, a narrower opening is a slit
    double maxDoorWidth = 1.2;      // metres, a wider opening is open floor
    double maxWallThickness = 0.6;  // metres, the deepest opening
    double sliverWidth = 0.5;       // metres, the widest wall interior
    double minRoomArea = 2.0;       // m²
    double maxOpenEdgeShare = 0.5;  // of a room's edges, leading to free cells without floor
    double maxOpenEdge = 30.0;      // metres of them
};

// Throws cavewall::Error naming the option when it is out of range.
void validateRoomOptions(const RoomOptions& options);

struct Room {
    double area = 0.0;            // m² of its cells
    glm::dvec2 lo{0.0}, hi{0.0};  // (x, z) bounds of its cells
    glm::dvec2 inner{0.0};        // the centre of its cell farthest from anything else
};

struct Doorway {
    glm::dvec2 position{0.0};          // (x, z), the opening's centroid
    double width = 0.0;                // metres
    bool alongX = true;                // the opening (and its wall) runs along x; else along z
    std::array<int, 2> rooms{-1, -1};  // indices into FloorPlan::rooms, rooms[0] < rooms[1]
};

struct FloorPlan {
    std::vector<Room> rooms;
    std::vector<Doorway> doorways;
    int exits = 0;                      // openings between one room and the outside
    std::vector<int> room;              // per grid cell: its room, -1 for none
    std::vector<int> opening;           // per grid cell: its doorway, -1 for none
    std::vector<std::uint8_t> barrier;  // per grid cell: wall or closed opening
};

// The rooms and doorways of `grid`. Throws cavewall::Error for bad options.
FloorPlan findRooms(const FloorGrid& grid, const RoomOptions& options = {});

}  // namespace cavewall::walls
