#pragma once
// Where a person can walk, found from a building's horizontal surfaces alone. GL-free.
//
// The (x, z) plane is cut into square cells of `cell` metres. Every near-horizontal facet
// (walls/storeys.h) covers the cells whose centres lie inside its triangle (a triangle smaller
// than a cell covers the cell of its centre), at its plane's height over the centre. In each
// cell the upward heights within `levelGap` of each other are one level (the highest of them:
// a floor finish on its slab). A level is walkable when no facet of the cell, up or down, lies
// between `clearance` and `headroom` above it (a shelf, a table top over the floor, the slab
// over a duct's top). Two walkable levels of 4-adjacent cells are joined when their heights
// differ by at most `maxStep`: a stair's treads (0.15–0.2 m rise over 0.25–0.3 m going) and a
// ramp's slope join, a table's top or a ceiling's top over the floor do not.
//
// climb() is the shortest walk (in steps) from any level at one floor's height to any at
// another's: a stair or a ramp the geometry shows. route() is the shortest walk between two
// points on the walkable levels. Both return floor points (cell centres at their levels'
// heights), simplified to where the walk turns or changes its slope.

#include "walls/storeys.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace cavewall::walls {

struct WalkGridOptions {
    double cell = 0.25;      // metres, > 0
    double levelGap = 0.1;   // metres: heights closer than this are one level
    double clearance = 0.3;  // metres: facets up to this above a level are its own (a finish, a kerb)
    double headroom = 2.0;   // metres free above a walkable level
    double maxStep = 0.25;   // metres, the largest step between adjacent cells
    double tolerance = 0.1;  // metres: a level within this of a floor's height is on that floor
};

class WalkGrid {
public:
    // The grid of the facets whose heights lie in [bottomY, topY] (bottomY <= topY).
    WalkGrid(const std::vector<Facet>& facets, double bottomY, double topY, const WalkGridOptions& options = {});

    // The shortest walk from a level at height fromY to one at toY (each within options.tolerance):
    // its first point on the lower floor, its last on the upper. Empty when none.
    std::vector<glm::dvec3> climb(double fromY, double toY) const;

    // The shortest walk from the walkable level nearest `from` to the one nearest `to` (each
    // within 0.5 m in height and 2 m across); empty when either has none or no walk joins them.
    std::vector<glm::dvec3> route(glm::dvec3 from, glm::dvec3 to) const;

    std::size_t levels() const { return nodes_.size(); }

private:
    struct Node {
        std::int64_t cell = 0;
        double y = 0.0;
    };
    std::int64_t key(long long i, long long j) const;
    glm::dvec3 point(int node) const;
    // Breadth first from `sources` until a node with `target(node)` true; the walk to it.
    template <class Target>
    std::vector<int> search(const std::vector<int>& sources, Target target) const;
    int nearest(glm::dvec3 p) const;
    std::vector<glm::dvec3> simplified(const std::vector<int>& walk) const;

    WalkGridOptions options_;
    std::vector<Node> nodes_;
    std::unordered_map<std::int64_t, std::vector<int>> byCell_;  // nodes of a cell, by height
};

}  // namespace cavewall::walls
