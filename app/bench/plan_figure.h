#pragma once
// The top view of a plan (`cavewall plan --png`, `cavewall walls --png`) as one overview
// figure (app/bench/plot.h), drawn by gnuplot: one panel per storey (cells grouped by floor
// height), each with the cells' outlines, the real walls, the virtual walls and the zones of
// every wall side filled by kind (texture, blend, geometry; half-transparent, so where the
// zones of several walls overlap the colours mix), axes x and z in metres at one scale, +z
// downwards (looking down from +y), and one legend. The per-wall detail, one panel per wall
// with its sampling points and object footprints, is walls/plan_diagram.h.

#include "app/bench/plot.h"
#include "scenes/scene_description.h"
#include "walls/plan.h"

#include <vector>

namespace cavewall::bench {

// Storeys of `description`: floor heights (y, metres, ascending) of its cells, heights less
// than `gap` metres apart counted as one storey (the lowest of them). At least one entry
// (0 without cells).
std::vector<double> storeyFloors(const scenes::SceneDescription& description, double gap = 1.0);

// The overview figure; `title` leads every panel's title ("clinic: storey 2 of 2, floor y 3.98
// m, 16 cells, 17 virtual walls").
Figure planFigure(const walls::Plan& plan, const scenes::SceneDescription& description, const std::string& title);

}  // namespace cavewall::bench
