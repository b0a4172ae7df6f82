#pragma once
// Where a storey is open to the storey above (an atrium, a double-height hall, a stair's
// opening), found from the floor slabs. GL-free.
//
// A floor level's slab is every near-horizontal triangle (normal within kSlabTiltDeg of +Y or
// -Y, either face: a slab's top and its underside) lying within [level - kSlabBelow,
// level + kSlabAbove], marked on a plan grid (a sample is covered when its centre lies in such
// a triangle) and closed by `closeMetres` (dilated, then eroded): the joints under walls and
// between floor boards up to twice that wide are slab too, so the gaps between room cells are
// never a void. A plan sample is open from a lower floor level to an upper one when
//   - the lower level's slab covers it (the lower storey has floor there: not outdoors),
//   - the upper level's slab does not (no floor above: the void), and
//   - a near-horizontal surface (normal within kRoofTiltDeg of the vertical: a ceiling, a
//     roof) lies wholly more than kCoverAbove above the upper level over it (the void is
//     indoors: not the roof of a one-storey wing beside the upper storey, nor a courtyard).

#include "scenes/region.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::scenes {

inline constexpr double kSlabBelow = 0.5;     // metres under a floor level its slab reaches
inline constexpr double kSlabAbove = 0.3;     // metres over a floor level its slab reaches
inline constexpr double kCoverAbove = 1.0;    // metres over the upper level a void's covering lies
inline constexpr double kSlabTiltDeg = 10.0;  // a slab triangle's normal within this of the vertical
inline constexpr double kRoofTiltDeg = 60.0;  // a covering triangle's normal within this of the vertical

struct VoidOptions {
    double sampleMetres = 0.25;  // plan grid step (grown on very large plans: at most 2048 a side)
    double closeMetres = 0.5;    // slab closing radius
};

// Plan samples of one cell's void, with prefix sums to count them in a rectangle.
class PlanMask {
public:
    PlanMask() = default;
    // `open`: nx * nz samples, row by row along x; sample (i, j) is centred at
    // origin + step * (i + 0.5, j + 0.5).
    PlanMask(glm::dvec2 origin, double step, int nx, int nz, const std::vector<bool>& open);

    bool empty() const { return total() == 0; }
    long total() const { return _sums.empty() ? 0 : _sums.back(); }
    double area() const { return static_cast<double>(total()) * _step * _step; }
    // Open samples whose centres lie in the (x, z) rectangle [lo, hi].
    long count(glm::dvec2 lo, glm::dvec2 hi) const;

private:
    glm::dvec2 _origin{0.0};
    double _step = 1.0;
    int _nx = 0, _nz = 0;
    std::vector<long> _sums;  // (nx + 1) * (nz + 1) prefix sums
};

// Per cell, its void toward the floor at height tops[c] (cells' storey tops,
// scenes/cell_assignment.h; an infinite top: none): the samples of the cell's region open from
// its floor (Cell::floorY) to tops[c] (see the top of this file). `tops` and `bounds` (each
// cell's regionBounds, scenes/region.h) have one entry per cell.
std::vector<PlanMask> cellVoids(const Scene& scene, const std::vector<Cell>& cells, const std::vector<double>& tops,
                                const std::vector<PlanRect>& bounds, const VoidOptions& options = {});

}  // namespace cavewall::scenes
