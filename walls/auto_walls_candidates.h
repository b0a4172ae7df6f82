#pragma once
// The candidates of automatic walls (walls/auto_walls.h, 3.-6.): the grids and the rooms of
// one storey, described, scored and kept in the order tried. Internal to walls/auto_walls.cpp
// and walls/auto_walls_candidates.cpp. GL-free.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/auto_rooms.h"
#include "walls/auto_walls.h"
#include "walls/room_cells.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace cavewall::walls::detail {

// 1.'s findings over the model's objects.
struct ModelParts {
    std::vector<std::string> structure;                               // structure objects' names, in object order
    std::vector<const scenes::Object*> verticalPlanes;                // large vertical structure planes (hall walls)
    std::vector<WallPiece> pieces;                                    // thin vertical structure boxes (5.)
    std::vector<scenes::Bounds> content;                              // every other object's box
    std::vector<std::size_t> contentTriangles;                        // and its triangles
    scenes::Bounds floorBox;                                          // the floor planes'
    double floorTop = std::numeric_limits<double>::infinity();        // the lowest floor plane's top
    double ceilingBottom = -std::numeric_limits<double>::infinity();  // the highest ceiling's bottom
};

// An (x, z) rectangle.
struct Rect {
    glm::dvec2 lo, hi;
};

// What every candidate is described from and scored with.
struct CandidateInputs {
    const scenes::SceneDescription& named;  // withStructure's
    const ModelParts& parts;                // content, its triangles and the wall pieces
    const AutoWallsOptions& options;
    const std::vector<glm::dvec3>& eyes;  // the walk cost's (6.); empty: the floor cost (4.)
    double floorY = 0.0, ceilingY = 0.0, eyeHeight = 0.0;
    const StoreyRooms* rooms = nullptr;  // the storey's floor plan (5.)
};

// The candidates in the order tried, with their descriptions (index for index).
struct Proposals {
    std::vector<AutoWallsCandidate> candidates;
    std::vector<scenes::SceneDescription> descriptions;
    double limitMetres = 0.0;  // 8.: virtual wall this storey may plan
    AutoWallsLimit limit;      // what it planned and left out (eyes aside)
    int storey = 0;            // for the progress lines
};

// E[ms], triangles, textures and MiB of description `d` (AutoWallsCandidate without nx, nz).
// A cell's triangles are those of the content boxes meeting its region's bounding rectangle
// (exact for the rectangular cells proposed here). `eyes` (x, y, z): the walk cost's (6.);
// empty: the floor cost (4.).
AutoWallsCandidate evaluate(const scenes::SceneDescription& d, const std::vector<scenes::Bounds>& content,
                            const std::vector<std::size_t>& contentTriangles, const AutoWallsOptions& options,
                            const std::vector<glm::dvec3>& eyes = {});

// 3.-5. The grids and the rooms of one storey within out.limitMetres: the rooms' walls are
// counted first, the grids get the rest; the rooms are scored last.
void addCandidates(Proposals& out, const CandidateInputs& in, const Rect& walkable);

// The cheapest candidate within the budget (the first of equals; the first candidate, one cell,
// always fits), or with `preferRooms` the rooms when they are within it.
int chooseCandidate(const std::vector<AutoWallsCandidate>& candidates, bool preferRooms);

}  // namespace cavewall::walls::detail
