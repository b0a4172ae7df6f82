#pragma once
// A storey's floor plan as a 2D occupancy grid, rasterised from the geometry. GL-free.
//
// The grid covers an (x, z) rectangle in square cells of `cellSize` metres (a plan grid,
// scenes/plan_raster.h: cell (i, k) spans x in [origin.x + i cellSize, + cellSize) and z likewise
// with k). Each cell holds two flags:
// wall (a slice through a wall element crosses it) and floor (walkable surface lies under it).
//
// The walking floor: a storey's floor found over a whole building can sit between a slab and
// the ducts or a lower roof near it, so the grid's floor is the 0.05 m height bin with the most
// upward area (normal within 10 degrees of +Y) from `floorSearchBelow` under the storey's floor
// to `floorSearchAbove` over it; every height below is measured from it.
// Wall elements are found from geometry alone (no names or IFC types are needed): an object is
// a wall element of storey [floorY, ceilingY) when
//   - its box reaches from at most `maxBottom` above the floor to at least `minTop` above it
//     (capped 0.1 m under the ceiling: a door leaf, about 2.1 m high, falls short; a wall
//     reaches a suspended ceiling, the slab or the roof),
//   - at least `minVerticalShare` of its triangles' area is vertical (normal within 15 degrees
//     of the horizontal plane), and
//   - its footprint is thin: its vertices' extent along their minor principal axis in (x, z)
//     is at most `maxThickness` (a wall, a partition or a column; not a lift shaft or a
//     cabinet block).
// Each wall element's triangles are cut by the horizontal planes `sliceHeights` above the
// floor and the cut segments marked as wall. Two heights: a doorway is open at both, a window
// only above its sill, so the lower slice closes windows.
// Floor cells: the upward triangles (normal within 10 degrees of +Y) whose mean height lies
// within `floorTolerance` of floorY, filled at cell centres.

#include "scenes/plan_raster.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace cavewall::walls {

// Cells and their (x, z) spans as scenes::PlanGrid (scenes/plan_raster.h).
struct FloorGrid : scenes::PlanGrid {
    std::vector<std::uint8_t> wall, floor;  // nx * nz each, index k * nx + i, 0 or 1
};

// An empty grid (no wall, no floor) covering [lo, hi] with cells of `cellSize` (> 0).
FloorGrid makeFloorGrid(glm::dvec2 lo, glm::dvec2 hi, double cellSize);

// Marks as wall every cell the segment a -> b (x, z) passes through.
void markWallSegment(FloorGrid& g, glm::dvec2 a, glm::dvec2 b);

// Marks as wall, or as floor, every cell whose centre lies in the rectangle [lo, hi] (x, z).
void markWallRect(FloorGrid& g, glm::dvec2 lo, glm::dvec2 hi);
void markFloorRect(FloorGrid& g, glm::dvec2 lo, glm::dvec2 hi);

// Marks as floor every cell whose centre lies in the triangle (x, z), either winding.
void markFloorTriangle(FloorGrid& g, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);

// The 3-4 chamfer distance, in cells, from every cell of `g` to the nearest cell where `source`
// (nx * nz flags, as FloorGrid::wall) is set; 1e9 / 3 everywhere when none is.
std::vector<float> chamferDistance(const FloorGrid& g, const std::vector<std::uint8_t>& source);

struct FloorGridOptions {
    double cellSize = 0.1;                       // metres, > 0
    std::vector<double> sliceHeights{0.5, 1.2};  // metres above the floor
    double maxBottom = 0.3;                      // a wall element's box starts at most this above the floor
    double minTop = 2.3;                         // and ends at least this above it
    double minVerticalShare = 0.5;               // of its triangles' area
    double maxThickness = 0.8;                   // metres across its minor principal axis
    double floorTolerance = 0.3;                 // metres around floorY
    double margin = 1.0;                         // metres around the storey's floor bounds
    double floorSearchBelow = 0.5;               // metres, the walking floor's search range
    double floorSearchAbove = 1.0;
};

// The grid of storey [floorY, ceilingY) over its floor's (x, z) bounds [lo, hi] widened by
// options.margin, how many objects were taken as wall elements and the walking floor. Cells are
// options.cellSize, coarser where the grid would exceed 16 million cells (400 m x 400 m at 0.1 m).
// Throws cavewall::Error for a cell size that is not positive.
struct StoreyGrid {
    FloorGrid grid;
    int wallElements = 0;
    double floorY = 0.0;  // the walking floor
};

StoreyGrid rasteriseStorey(const scenes::Scene& scene, double floorY, double ceilingY, glm::dvec2 lo, glm::dvec2 hi,
                           const FloorGridOptions& options = {});

}  // namespace cavewall::walls
