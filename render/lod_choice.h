#pragma once
// Levels of detail for a frame: one level per object for all views together, so that
// neighbouring screens and both eyes draw the same shape.

#include "display/display.h"
#include "display/pixel_scale.h"
#include "render/draw_filter.h"
#include "render/render_scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <limits>
#include <vector>

namespace cavewall::render {

// The frame's levels of detail (chooseLods).
struct FrameLod {
    std::vector<int> levels;    // per object index (DrawFilter::lodLevels); 0 where not drawn
    double tolerancePx = 0.0;   // the pixel tolerance every drawn object meets
    double maxErrorPx = 0.0;    // the largest geometric error drawn, in pixels on its screen
    std::size_t triangles = 0;  // triangles the views will submit at these levels
    bool overBudget = false;    // the coarsest levels still exceed the triangle budget
};

// The most pixels one model unit of an object's geometric error covers on `screen`
// (display/pixel_scale.h): the screen's largest pixels per radian over the object's bounds,
// times `modelStretch` (maxStretch of its worldFromModel) and `viewStretch` (maxStretch of
// viewFromWorld), over the nearest distance of its bounds from the eye. `worldBounds` in the
// world; +infinity when the eye is inside them.
double pixelsPerUnit(const scenes::Bounds& worldBounds, double modelStretch, const display::ViewScreen& screen,
                     const glm::dmat4& viewFromWorld, double viewStretch);

// Levels of detail for one frame of `views` (Display::views; worldFromCave places the CAVE in
// the world): per object drawn by some view (after `filter` and culling, as render lists
// select), the coarsest level whose error covers at most `tolerancePx` pixels on every screen
// it is drawn on. With `triangleBudget` > 0 the tolerance rises to the least that fits the
// views' triangles into the budget, never above `maxTolerancePx` (scenes::chooseLevels).
// Without level chains (RenderScene::hasLods false) everything is level 0.
FrameLod chooseLods(const RenderScene& scene, const std::vector<display::ScreenView>& views,
                    const glm::dmat4& worldFromCave, const DrawFilter& filter, double tolerancePx,
                    std::size_t triangleBudget = 0, double maxTolerancePx = std::numeric_limits<double>::infinity());

// Levels of detail for one frustum drawn into `pixels` (a wall texture: screen = the wall quad,
// eye = the sampling point, frame = the world, pixels = texels): chooseLods for that single view,
// so every object `filter` selects and the frustum does not cull gets the coarsest level whose
// sampled geometric error covers at most `tolerancePx` pixels of the image.
FrameLod chooseFrustumLods(const RenderScene& scene, const display::OffAxisFrustum& frustum, glm::ivec2 pixels,
                           const DrawFilter& filter, double tolerancePx);

}  // namespace cavewall::render
