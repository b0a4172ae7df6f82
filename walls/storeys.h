#pragma once
// Storeys of a building found from its geometry alone. GL-free.
//
// Floors are where much walkable surface lies at one height: every upward-facing,
// near-horizontal triangle (normal within `maxTiltDeg` of +Y) adds its area projected on (x, z)
// to a histogram of heights (bins of `binMetres`, the triangle's mean y). Runs of adjacent
// non-empty bins form levels; a level's height is that of its bin with the most area (the
// area-weighted mean within that bin: a run can reach from a ceiling's top through the ducts
// above it to the slab, and its mean is no walkable height). Levels closer than
// `mergeMetres` merge into the one with more area (a slab's top and a floor finish, a raised
// step). A level is a floor when its area is at least `minFloorShare` of the largest level's
// (a mezzanine, a table top or a stair tread is not a floor) and downward-facing area of at
// least `minFloorShare` of its own lies more than `minHeadroom` / 2 above it (a roof is covered
// by nothing). Downward-facing triangles make the same histogram for ceilings.
// Each storey spans from its floor to its ceiling: the highest ceiling level (area at least
// `minFloorShare` of the floor's) between the floor + `minHeadroom` and the next floor (a
// slab's underside), else the next floor; for the top storey the highest ceiling level above
// it, else the model's top. A model without any floor has one storey from its bottom to its top.
//
// Stairs: the shortest walk over the walkable levels of walls/walk_grid.h from the lower floor's
// height to the upper one's (treads of 0.15-0.2 m rise over 0.25-0.3 m going, or a sloped
// walkable surface); furniture, ceiling tops and ducts are no step of it (covered, or too
// high a step). A building without one has no stair.

#include "scenes/scene.h"
#include "scenes/scene_description.h"

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <vector>

namespace cavewall::walls {

class WalkGrid;

struct StoreyOptions {
    double binMetres = 0.05;     // histogram bin, > 0
    double maxTiltDeg = 10.0;    // a floor triangle's normal within this of +Y (a ceiling's, of -Y)
    double mergeMetres = 2.0;    // levels closer than this are one floor
    double minFloorShare = 0.3;  // a floor's area / the largest level's area
    double minHeadroom = 2.0;    // metres between a floor and its ceiling, at least
};

// One horizontal-ish triangle's contribution: its mean height (world y, metres) and its area
// projected on (x, z) in m², its centre for the stair columns and its (x, z) bounds.
struct Facet {
    double y = 0.0;
    double area = 0.0;
    glm::dvec2 centre{0.0};       // (x, z)
    bool up = true;               // faces +Y (a floor); false: faces -Y (a ceiling)
    glm::dvec2 lo{0.0}, hi{0.0};  // (x, z)
    glm::dvec2 corners[3]{};      // the triangle's (x, z)
    glm::dvec2 slope{0.0};        // dy/dx, dy/dz of its plane: y + slope . ((x, z) - centre)
};

struct Storey {
    double floorY = 0.0, ceilingY = 0.0;  // world y, metres
    double floorArea = 0.0;               // upward area at the floor level, m²
    // The (x, z) bounds of the upward facets within 0.25 m of floorY (empty, lo > hi, for
    // the one storey of a model without floors).
    glm::dvec2 floorMin{1.0}, floorMax{-1.0};
};

// A stair or ramp between storeys `from` and `from + 1`: its walk (floor points, the first on
// the lower floor, the last on the upper), that walk's (x, z) bounds and its two ends.
struct Stair {
    int from = 0;
    glm::dvec2 lo{0.0}, hi{0.0};
    glm::dvec2 bottom{0.0}, top{0.0};
    std::vector<glm::dvec3> path;
};

// A storey's own walk on its floor from `from` to `to` (floor points, x, floor y, z): its
// points from `from` to `to`; empty when it has none.
using FloorRoute = std::function<std::vector<glm::dvec3>(int storey, glm::dvec3 from, glm::dvec3 to)>;

struct Storeys {
    std::vector<Storey> storeys;  // bottom to top, at least one
    std::vector<Stair> stairs;    // by `from`, at most one each
    // The walkable levels of every storey (null for one storey): routes along the floors.
    std::shared_ptr<const WalkGrid> walk;
};

// The facets of every triangle of `scene` (world frame) whose normal is within
// options.maxTiltDeg of +Y or -Y; degenerate triangles are skipped.
std::vector<Facet> horizontalFacets(const scenes::Scene& scene, const StoreyOptions& options = {});

// The storeys made by `facets` within the model's heights [bottomY, topY].
Storeys findStoreys(const std::vector<Facet>& facets, double bottomY, double topY, const StoreyOptions& options = {});

// The same from a whole scene (its bounds give bottomY and topY).
Storeys findStoreys(const scenes::Scene& scene, const StoreyOptions& options = {});

// The storey holding height y: the highest whose floor is at or below y + 0.5 m, else the
// lowest (the rule scenes::findCell uses for cells).
int storeyAt(const std::vector<Storey>& storeys, double y);

// One description of every storey's cells, walls and real walls (perStorey[i]: storey i's own,
// all from one base), their names prefixed with the storey's number from 0 at the lowest
// ("1/A1"), the walls' cell indices moved along, and one walk path: each storey's in turn. From
// one to the next it walks over the walkable levels to the first stair found between them
// whose every point holds the eye in a cell, climbs the stair's walk and walks on to the upper
// path's start, at eye height above the levels it crosses. Without such a stair the upper path
// starts a new piece (walkBreaks): nothing is walked between the storeys. Everything else
// (models, viewer) is perStorey[0]'s. `perStorey` and `found.storeys` have the same size.
// `route`, when set, walks on a storey's floor first (its rooms and doorways); the walkable
// levels take over where it returns nothing.
scenes::SceneDescription stackStoreys(const std::vector<scenes::SceneDescription>& perStorey, const Storeys& found,
                                      double eyeHeight, const FloorRoute& route = {});

}  // namespace cavewall::walls
