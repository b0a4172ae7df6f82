#pragma once
// What automatic walls (walls/auto_walls.h) refuse up front and how far they search. GL-free.
//
// Models. A model is refused, with a message about the model and naming it, when it has no
// triangles; when a coordinate lies beyond scenes::kMaxSceneCoordinate of the origin (the
// proposal's cells and walls must lie within it, and single-precision positions lose
// millimetres there); when all its vertices lie within 1 mm of one point; or when it has no
// floor to cut into cells: its bounds span less than 1 cm along x or along z.
//
// Planning limit. Planning a candidate takes time in proportion to the length of its virtual
// walls: the zone planner cuts the floor on both sides of every wall into zones, about 4 to 10
// per metre of wall at the defaults. A grid of nx x nz cells over a walkable rectangle of
// width w (x) and depth d (z) has (nx - 1) walls of length d and (nz - 1) of length w. The
// grids are taken in order of that length (shortest first; ties in the order tried, nx then
// nz) while the total stays within the limit and each within kMostPerCandidate of it (one
// candidate does not take the whole limit: on a 10 km hall, one 10 km wall takes 15 s of CPU
// here); the others are not planned and are reported.
// The one-cell grid has no walls and is always planned.
//
// Walk cost eyes. Every 0.25 m along the walk path, or a 0.5 m grid over the walkable
// rectangle; on a long path or a large floor the step widens so that there are at most about
// kMaxCostEyes (each is looked up in every candidate's zones).

#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace cavewall::walls {

inline constexpr std::size_t kMaxCostEyes = 20000;
// The share of the planning limit one candidate's virtual walls may take, at most.
inline constexpr double kMostPerCandidate = 0.4;

// Throws cavewall::Error "<where>: ..." when automatic walls cannot cut `scene` (above).
void checkWallsModel(const scenes::Scene& scene, const std::string& where);

// Metres of virtual wall of an nx x nz grid over a rectangle of `size` (x, z) metres.
double gridWallMetres(int nx, int nz, glm::dvec2 size);

// Which grids of 1..maxX x 1..maxZ cells over `size` to plan within `limitMetres` of virtual
// wall, each within kMostPerCandidate of it: planned[(nx - 1) * maxZ + (nz - 1)].
std::vector<bool> gridsWithinLimit(int maxX, int maxZ, glm::dvec2 size, double limitMetres);

// The walk cost's eyes: along `walkPath` when it has two points or more, else a grid over
// [lo, hi] (x, z) at height eyeY. `step` (may be null): the metres between them.
std::vector<glm::dvec3> costEyes(const std::vector<glm::dvec3>& walkPath, glm::dvec2 lo, glm::dvec2 hi, double eyeY,
                                 double* step = nullptr);

}  // namespace cavewall::walls
