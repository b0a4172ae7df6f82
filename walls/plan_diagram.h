#pragma once
// A top-view diagram of a plan (like Ebbesmeyer 1997, Figure 8), rasterised on the CPU: one
// panel per wall showing every cell outline, real walls (black), virtual walls (light blue; the
// panel's wall in dark blue), the zones of both sides of the panel's wall filled by kind
// (texture: greens, one shade per texture; blend: yellow; geometry: red), sampling points
// (black dots) and object footprints (grey outlines). Top view: +x to the right, +z downwards.
// The per-wall detail of `plan --png-walls` and `walls --png-walls`; the overview of `--png`,
// one panel per storey with axes and a legend, is app/bench/plan_figure.h.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/plan.h"

namespace cavewall::walls {

// `scene` may be null (no object footprints). Panels are panelSize pixels wide and as high as
// the floor plan's aspect needs (at most panelSize), laid out in a near-square grid.
scenes::Image planDiagram(const Plan& plan, const scenes::SceneDescription& description, const scenes::Scene* scene,
                          int panelSize = 320);

}  // namespace cavewall::walls
