#pragma once
// Automatic virtual walls (the future work Ebbesmeyer 1997 names): cells and virtual walls
// proposed for a model nobody prepared. GL-free.
//
// 1. Structure. An object is structure when its node name matches one of the description's
//    structure patterns or it is a large plane: its bounding box is thinner than
//    `planarThickness` of its second-largest extent and that extent is at least
//    `planarExtent` of the model's horizontal extent along the same axes. Horizontal planes
//    give the floor (the lowest; its top is floorY) and the ceiling (the highest; its bottom
//    is the walls' top); without them the model's bounds do.
// 2. Walkable floor. The (x, z) rectangle of the floor planes (or of the model), shrunk to the
//    inside of vertical structure planes that span most of it (hall walls).
// 3. Candidates. Every grid of nx x nz cells over that rectangle with cells at least
//    `minCellSize` metres wide, nx, nz <= maxCellsPerAxis (a row of nz stops at its first
//    candidate over the budget: more cells only add walls and textures). Each cut is moved, within a quarter
//    of a cell, to the position (0.05 m steps) that the fewest content objects straddle.
//    Adjacent cells are separated by one virtual wall from floorY to the ceiling.
// 4. Cost. The expected frame time of a walk that visits the floor uniformly:
//      E[ms] = sum over cells of (area share) x (msPerMillionTriangles x the cell's triangles
//              [content objects whose box meets the cell, instances counted] / 1e6)
//              + msPerWallSide x (the cell's virtual wall sides: its wall layers' fill)
//    where the textures' count and size come from the planner itself (walls/plan.h, planZones
//    with `plan`), and the candidate must fit `textureBudgetMB` (RGBA8 + MIP chain, each
//    texture's resolution capped at plan.maxResolution). The one-cell candidate (no walls,
//    the whole model as geometry) always fits, so a proposal always exists.
// 5. Rooms. Thin vertical structure boxes (at most 0.5 m thick, at least 0.3 m tall) are pieces
//    of real wall. Lines of pieces strictly inside the walkable rectangle whose pieces reaching
//    the floor cover at least half of it cut one more candidate, the rooms: a boundary on such
//    a line is a portal for every gap of at least 0.3 m between the pieces reaching the floor
//    (as high as the lowest piece above the gap: a lintel, else the ceiling), nothing where they
//    close it; a boundary on no line stays a virtual wall. Every piece becomes a real wall.
//    The rooms are scored like every grid and chosen when they cost the least.
//    Without such lines (a model whose walls are many small elements nobody named), the rooms
//    come from the storey's floor plan instead: wall elements found by their shape are sliced
//    into an occupancy grid, gaps up to a door's width close, the free floor falls into rooms
//    and the closed gaps between two rooms are doorways (walls/floor_grid.h, walls/rooms.h).
//    With two rooms or more, the candidate's cells are rectangles cut along the rooms' walls,
//    its doorways portals, its open cuts virtual walls (walls/room_cells.h); at most 48 cells,
//    halved while its textures are over the budget (down to 4).
// 6. Walk cost (walkCost). 4. counts only the viewer's cell, but the walkthrough also draws the
//    cell behind a wall as geometry while the eye is in that wall's geometry zone or its
//    texture->geometry blend strip (walls/plan.h), and a walk follows aisles, where cuts
//    straddle the fewest objects. So: eyes every 0.25 m along the input description's
//    walkPath (without one, on a 0.5 m grid over the walkable rectangle); each eye costs
//    msPerMillionTriangles x (its cell's triangles + those of every neighbour whose zone
//    holding the eye draws it as geometry, the planner's own zones) / 1e6 + msPerWallSide x its
//    cell's wall sides; E[ms] and meanCellTriangles are the means over the eyes.
//    The costs per triangle and per texture are inputs: measure them on the target machine
//    (`cavewall bench`'s full-geometry and walls rows give both); the defaults are this
//    project's llvmpipe figures at 1024 x 1024 per screen (docs/virtual-walls.md).
// 7. Storeys. walls/storeys.h finds the floors from the geometry's horizontal area. With one
//    storey, 1.-6. apply as they stand. With more, each storey is cut on its own: its floor and
//    ceiling from walls/storeys.h, its walkable rectangle the part of 2.'s within its floor's
//    (x, z) bounds, its content and wall pieces those whose boxes reach into [floor, ceiling),
//    a wall piece cut to that range, and an equal share of textureBudgetMB; the walk cost's eyes
//    are those of the storey holding them (storeyAt, at eye height above its floor). The
//    cheapest candidate of every storey is chosen, and the proposal stacks them: cells named
//    "<storey>/<cell>" with their storey's floorY (scenes::findCell picks a cell by height), one
//    walk path visiting every storey in turn, up the stairs found (walls/storeys.h,
//    stackStoreys), to and from them over the storeys' rooms and doorways (walls/room_tour.h)
//    where their cells hold that walk.
// 8. Limits (walls/auto_walls_limits.h). A model without triangles, beyond
//    scenes::kMaxSceneCoordinate, of one point or without a floor is refused up front. Grids
//    are planned shortest virtual walls first while their total length stays within
//    planLimitMetres (shared equally among storeys; the rooms count too), each candidate
//    within kMostPerCandidate of it; the others are not
//    planned, and `limit` says how many and how long. The walk cost uses at most kMaxCostEyes
//    eyes per storey: the 0.25 m path step or the 0.5 m grid widens to stay within it.
// Deterministic: the same scene and options give the same description, byte for byte.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/auto_walls_limits.h"
#include "walls/plan.h"
#include "walls/storeys.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::walls {

struct AutoWallsOptions {
    PlanOptions plan;                      // alpha, texel density, resolution cap
    double textureBudgetMB = 4096.0;       // MiB of wall textures (RGBA8 + MIP chain), > 0
    double msPerMillionTriangles = 150.0;  // frame ms per million triangles drawn, >= 0
    double msPerWallSide = 5.0;            // frame ms per wall side the viewer's cell shows, >= 0
    double minCellSize = 4.0;              // metres, smallest cell width, > 0
    int maxCellsPerAxis = 8;               // 1 to 26
    double planarThickness = 0.05;         // a plane's thickness / its second extent
    double planarExtent = 0.5;             // a plane's extent / the model's, per axis
    bool preferRooms = false;              // choose the rooms (5.) whatever the cost model says,
                                           // when there are rooms within the budget (the model
                                           // does not count what real walls hide)
    // The walk cost (6.) instead of 4.'s floor cost: eyes along the input's walk path, each
    // also drawing the neighbours whose geometry zones hold it (`cavewall walls --walk-cost`).
    bool walkCost = false;
    // Metres of virtual wall planned over all candidates, at most (8.; `--plan-limit`), > 0.
    double planLimitMetres = 25000.0;
    // Called with one line per candidate planned (its grid, walls, textures and seconds), as
    // it is planned; may be empty.
    std::function<void(const std::string&)> progress;
};

// What 8.'s limits left out, over all storeys.
struct AutoWallsLimit {
    int planned = 0;             // grids and rooms planned
    int skipped = 0;             // grids and rooms over the limit, not planned
    double plannedMetres = 0.0;  // virtual wall planned
    double skippedMetres = 0.0;  // the shortest candidate not planned: its virtual wall
    std::size_t eyes = 0;        // the walk cost's eyes, over all storeys
    double eyeStep = 0.0;        // metres between them (largest over the storeys; 0: no walk cost)
    bool eyesWidened = false;    // kMaxCostEyes widened the step
};

// Throws cavewall::Error naming the option when it is out of range.
void validateAutoWallsOptions(const AutoWallsOptions& options);

struct AutoWallsCandidate {
    int nx = 1, nz = 1;              // cells along x and z
    double expectedMs = 0.0;         // E[ms] above
    double meanCellTriangles = 0.0;  // area-weighted triangles drawn as geometry
    int textures = 0;                // planned textures (own and beyond walls)
    double textureMB = 0.0;          // their MiB (RGBA8 + MIP chain)
    bool withinBudget = true;
    bool rooms = false;                 // cut along real walls (5. below), not a grid
    bool floorPlan = false;             // rooms of the floor plan (5.): nx cells, nz = 1
    int portals = 0, virtualWalls = 0;  // rooms: its portals and virtual walls
    int storey = 0;                     // the storey it cuts (AutoWallsResult::storeys)
};

// One storey of the proposal: its floor and ceiling, its walkable rectangle (x, z), the
// candidate chosen for it and that candidate's cells.
struct AutoWallsStorey {
    Storey storey;
    glm::dvec2 floorMin{0.0}, floorMax{0.0};
    int chosen = 0;  // index into AutoWallsResult::candidates
    int cells = 0;
    // Its floor plan (5., walls/rooms.h): wall elements sliced, rooms, their m², doorways
    // between two rooms and exits (openings to the outside).
    int wallElements = 0, rooms = 0, doorways = 0, exits = 0;
    double roomArea = 0.0;
};

struct AutoWallsResult {
    scenes::SceneDescription description;  // the proposal: the input's models, with structure
                                           // patterns added, and new cells, walls and walk path
    double floorY = 0.0, ceilingY = 0.0;
    glm::dvec2 floorMin{0.0}, floorMax{0.0};     // walkable rectangle (x, z)
    std::vector<std::string> structure;          // names of the objects found to be structure
    std::vector<AutoWallsCandidate> candidates;  // in the order tried (nx, then nz; a row of nz
                                                 // stops at its first candidate over the budget)
    int chosen = 0;                              // index into candidates
    // The storeys (7.), bottom to top, at least one; floorY, ceilingY, floorMin, floorMax and
    // chosen above are the lowest storey's.
    std::vector<AutoWallsStorey> storeys;
    std::vector<Stair> stairs;  // between the storeys (walls/storeys.h)
    // Virtual walls under a void raised to the ceiling of the storey above (walls/void_walls.h).
    int wallsRaised = 0;
    // The same figures for the input's own cells and walls (hand-placed), when it has walls;
    // nx = nz = 0. A cell's triangles are counted over its region's bounding rectangle.
    std::optional<AutoWallsCandidate> given;
    AutoWallsLimit limit;
};

// Proposes cells and virtual walls for `scene`, loaded from `base` (whose cells, walls, real
// walls and paths are replaced: real walls and portals are not proposed yet, and a warning in
// `warnings` says so when `base` had any). Throws cavewall::Error for bad options or a model
// checkWallsModel refuses (walls/auto_walls_limits.h; named "scene '<name>'").
AutoWallsResult proposeWalls(const scenes::Scene& scene, const scenes::SceneDescription& base,
                             const AutoWallsOptions& options, std::vector<std::string>* warnings = nullptr);

}  // namespace cavewall::walls
