#pragma once
// How many pixels an error covers on a view's screen: the conversion behind every error "in
// pixels" (level-of-detail tolerances, the walls' angular error).
//
// In view space (eye at the origin, screen plane z = -h, config/conventions.h), a ray that
// meets the screen at distance r from the eye moves across the screen by at most r²/h metres
// per radian it turns (when it turns in the plane through itself and the screen normal; across
// that plane it moves by r). An angle of one radian therefore covers at most r² / (h p) pixels,
// p the pixel size in metres: least in the screen's centre, most at its far corners.
//
// A point displaced by a length e at distance D from the eye turns its ray by at most e / D
// radians, so a geometric error e of an object covers at most
//     e * maxStretch(viewFromModel) / nearestDistance(box) * maxPixelsPerRadian(screen, box)
// pixels on that screen: the bound the renderer's level-of-detail choice uses.

#include "display/off_axis.h"

#include <glm/glm.hpp>

#include <span>

namespace cavewall::display {

// The screen rectangle of a frustum in its view space.
struct ViewScreen {
    double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;  // metres, on the plane z = -distance
    double distance = 0.0;                                    // h: the eye's distance to the plane, > 0
    double pixelSize = 0.0;                                   // metres, the smaller of width and height
};

// The screen of `frustum` (from its projection) drawn into `viewportSize` pixels.
ViewScreen viewScreen(const OffAxisFrustum& frustum, glm::ivec2 viewportSize);

// The same for a screen rectangle seen from `eye` (the same frame), drawn into `pixels`; an eye
// nearer the plane than 1 mm (or behind it) counts as 1 mm away, as offAxisFrustum's guard.
ViewScreen viewScreen(const ScreenQuad& screen, glm::dvec3 eye, glm::ivec2 pixels);

// The most pixels per radian over the whole screen (at its corner farthest from the eye).
double maxPixelsPerRadian(const ViewScreen& screen);

// The fewest pixels per degree of visual angle anywhere on the screen: at the screen point
// nearest the eye, in the direction across the plane through the ray and the screen normal,
// d / p * pi / 180 for d the eye's distance to the nearest point of the screen rectangle (h when
// the eye is in front of the rectangle) and p the pixel size. This is the angular resolution to
// evaluate image metrics such as FLIP at (metrics/flip.h): a CAVE wall of 3 m and 1024 pixels seen
// from 1.5 m gives 8.9, with 1920 pixels 16.8. Nearest, not a mean over the screen, because it is
// conservative (where pixels look largest, contrast sensitivity hides the least, so a metric
// reports at least the error any other point of the screen would show) and because it is where
// the screen is seen most directly; a mean would be pulled up by the far, oblique corners (2.6 m
// away on that wall, with pixels foreshortened). Uses `pixelSize`, the smaller side of
// non-square pixels.
double minPixelsPerDegree(const ViewScreen& screen);

// The most pixels per radian over the part of the screen where points inside the box around
// `viewPoints` (view space) can appear: the screen rectangle clipped to their projections'
// bounds; the whole screen when a point is not in front of the eye. 0 when the points project
// entirely beside the screen.
double maxPixelsPerRadian(const ViewScreen& screen, std::span<const glm::dvec3> viewPoints);

// The same for the convex hull of `viewPoints` (a wall's corners, say) cut to the part in front
// of the eye (view z <= -1e-9 m): a shape that crosses the eye's plane counts where its part in
// front can appear, not on the whole screen. 0 when no part is in front or it projects beside
// the screen.
double maxPixelsPerRadianInFront(const ViewScreen& screen, std::span<const glm::dvec3> viewPoints);

// Distance from the origin (the eye) to the axis-aligned box around `points`; 0 inside it.
double nearestDistance(std::span<const glm::dvec3> points);

// The largest factor by which `m` stretches a vector (its spectral norm), for any matrix.
double maxStretch(const glm::dmat3& m);

}  // namespace cavewall::display
