#pragma once
// A plan grid: the (x, z) plane in square cells, triangles marked at cell centres and masks
// closed by a separable square window. GL-free. The one rasteriser of the storeys' voids
// (scenes/storey_voids.h) and of the rooms' floor plans (walls/floor_grid.h).
//
// Cell (i, k) spans x in [origin.x + i cellSize, + cellSize) and z likewise with k. A mask
// (PlanBits) holds one flag per cell, 0 or 1, at index k * nx + i.

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cavewall::scenes {

using PlanBits = std::vector<std::uint8_t>;

struct PlanGrid {
    glm::dvec2 origin{0.0};  // (x, z) of cell (0, 0)'s lower corner
    double cellSize = 0.1;   // metres
    int nx = 0, nz = 0;

    std::size_t cellCount() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz); }
    // A mask with no cell set.
    PlanBits blank() const { return PlanBits(cellCount(), 0); }
    int index(int i, int k) const { return k * nx + i; }
    bool inside(int i, int k) const { return i >= 0 && k >= 0 && i < nx && k < nz; }
    glm::dvec2 centre(int i, int k) const { return origin + cellSize * glm::dvec2(i + 0.5, k + 0.5); }
    glm::dvec2 centre(int c) const { return centre(c % nx, c / nx); }
    // The index of the cell holding (x, z) point p, -1 off the grid (or not finite).
    int cellAt(glm::dvec2 p) const {
        const glm::dvec2 q = glm::floor((p - origin) / cellSize);
        if (!(q.x >= 0.0 && q.y >= 0.0 && q.x < nx && q.y < nz)) return -1;
        return index(static_cast<int>(q.x), static_cast<int>(q.y));
    }
};

// Cells i in [i0, i1], k in [k0, k1] (inclusive; none when i0 > i1 or k0 > k1).
struct CellRange {
    int i0 = 0, i1 = -1, k0 = 0, k1 = -1;
};

// The cells of `g` whose centres lie in the (x, z) rectangle [lo, hi]; none when a bound is not
// finite.
CellRange centresIn(const PlanGrid& g, glm::dvec2 lo, glm::dvec2 hi);

struct TriangleOptions {
    // A centre counts when, for each edge, twice the area of the triangle it makes with that
    // edge (signed, positive inside) is at least -edgeTolerance times twice the triangle's
    // area: 0 takes centres inside or on an edge; 1e-9 also those an edge misses by rounding.
    double edgeTolerance = 0.0;
};

// Sets in `mask` (g.cellCount() flags) every cell whose centre lies in the (x, z) triangle
// a, b, c, either winding. A degenerate triangle or one with a coordinate that is not finite
// marks nothing.
void markTriangle(const PlanGrid& g, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, PlanBits& mask,
                  const TriangleOptions& options = {});

// Every cell with a set cell within `radius` cells of it along x and z (a square window of
// 2 radius + 1 cells a side, clipped to the grid). radius <= 0: the mask itself.
PlanBits dilated(const PlanGrid& g, const PlanBits& mask, int radius);
// Every cell whose whole square window is set, cells beyond the grid counting as set.
PlanBits eroded(const PlanGrid& g, const PlanBits& mask, int radius);
// Dilated, then eroded: a gap of at most 2 radius cells between set cells along x or z is
// filled; a wider one is kept.
PlanBits closed(const PlanGrid& g, PlanBits mask, int radius);

}  // namespace cavewall::scenes
