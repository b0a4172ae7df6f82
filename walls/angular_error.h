#pragma once
// The angular error of a textured virtual wall, computed exactly in 3D.
//
// A texture baked from sampling point S shows a scene point P (behind the wall plane) at Q, the
// intersection of the line S-P with the wall. An eye E sees that texel in direction Q - E
// instead of P - E. The error is angle(P - E, Q - E) (radians).
//
// Facts used here (proofs in angular_error.cpp):
//  - For P on the ray from S through Q, the error grows monotonically with P's depth behind
//    the plane. At depth D it equals the angle subtended at Q by the segment [E, M] with
//    M = (E + k S) / (1 + k), k = D / dist(S, plane); as D -> infinity, M -> S and the error
//    tends to the parallax angle at Q between S and E, angle(Q - S, Q - E).
//  - For an acute angle t, the wall points Q where [A, B] subtends at least t are exactly the
//    points within R = |AB| / (2 sin t) of the circle of radius |AB| / (2 tan t) around the
//    midpoint of AB, perpendicular to AB. "Does any point of the wall rectangle exceed t?"
//    is therefore a one-dimensional distance minimisation along that circle, which is solved
//    rigorously (branch and bound with a convexity lower bound along the circle).
//  - For a fixed Q, the eyes E with angle(Q - S, Q - E) <= t (t <= 90°) form a convex cone, so
//    over a convex zone (floor polygon x height range) the depth-independent error is largest
//    at one of the zone's vertices.
//
// All functions return upper bounds that are within kErrorTolerance of the true maximum (or
// exactly it); they never under-estimate, never return NaN, and always terminate.

#include "display/off_axis.h"
#include "walls/polygon2d.h"

#include <glm/glm.hpp>

#include <limits>

namespace cavewall::walls {

using display::ScreenQuad;  // a wall rectangle: lowerLeft, lowerRight, upperLeft (conventions.h)

inline constexpr double kInfiniteDepth = std::numeric_limits<double>::infinity();
inline constexpr double kErrorTolerance = 1e-9;  // radians; bound - true maximum <= this

// The error of one scene point P (world) seen by `eye` on the texture baked from
// `samplingPoint`: angle(P - E, Q - E), Q = the intersection of line S-P with the wall's plane
// (not limited to the rectangle). Returns 0 when S-P is parallel to the plane.
double pointError(glm::dvec3 eye, glm::dvec3 samplingPoint, glm::dvec3 scenePoint, const ScreenQuad& wall);

// The exact maximum error for one eye over every texel of `wall` and every scene point up to
// `depthBehind` metres behind the wall plane (kInfiniteDepth for no limit). This is what the
// runtime calls per frame for the actual eye. Cost: about 10 µs (bench/walls_bench.cpp).
double maxAngularError(glm::dvec3 eye, glm::dvec3 samplingPoint, const ScreenQuad& wall,
                       double depthBehind = kInfiniteDepth);

// True when maxAngularError(eye, ...) <= `alpha` is proven (alpha in (0, 90°]). One
// one-dimensional search; the planner's predicate. False when the bound cannot be proven.
bool errorWithin(glm::dvec3 eye, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind, double alpha);

// A zone: a convex floor polygon (x, z) times an absolute head height range [y0, y1].
struct ZoneVolume {
    Polygon2 floor;
    glm::dvec2 heightRange{1.2, 2.0};
};

// The maximum error over every eye in `zone` (and every texel and scene point up to
// depthBehind). For kInfiniteDepth this is exact: the maximum over the zone's vertices (see
// above). For a finite depth the eyes no longer form convex sets, so a branch and bound over
// the zone refines it: the per-eye maximum is Lipschitz in the eye with constant
// k |Q - S|max / (h (h + depth)), h the eye's distance to the wall plane, k = depth / dist(S,
// plane), because every texel and scene point is on or behind the plane. It stops within `tolerance` radians of the true maximum or after `budget` eyes, and
// always returns a proven upper bound (never above the depth-independent one). Zones reaching
// the wall plane or errors of 90° and more get the depth-independent bound (pi above 90°).
double zoneMaxError(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall,
                    double depthBehind = kInfiniteDepth, double tolerance = 1e-4, int budget = 20000);

// True when every eye of `zone` is proven within `alpha` for every depth behind the wall.
bool zoneWithin(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double alpha);

// A finite depth over a zone, rigorously and at the cost of one eye per zone vertex (zoneMaxError's
// branch and bound needs boxes of millimetres near a bound, since an eye's error changes by about
// 1 / h radians per metre). Let x = E - Q, y = S - Q and k = depthBehind / dist(S, plane). The
// error at depth D is angle(x, x + k y) (the fact above), so for t < 90° it is within t exactly
// when
//   g(E) = tan t (x . y + |x|^2 / k) - |x × y| >= 0.
// In E, tan t (x . y) - |x × y| is concave and (tan t / k) |x|^2 is a convex quadratic. For E a
// convex combination sum w_i V_i of the zone's vertices, concavity and the quadratic's identity
// sum w_i |V_i - Q|^2 = |E - Q|^2 + sum w_i |V_i - E|^2 give
//   g(E) >= min_i g(V_i) - (tan t / k) r^2,   r^2 >= sum w_i |V_i - E|^2,
// and for the prism (floor polygon x height range, product weights) r^2 = R^2 + (y1 - y0)^2 / 4
// with R the largest distance of a floor vertex from the floor vertices' mean. Since |V_i - Q|
// >= h_i (V_i's distance to the plane), (tan t / k) r^2 <= (tan t / k) eta_i |V_i - Q|^2 with
// eta_i = r^2 / h_i^2, so g(V_i) >= (tan t / k) r^2 holds when V_i's error at the larger depth
// depthBehind / (1 - eta_i) (the same form with k / (1 - eta_i)) is within t. So:
//   every eye of the zone is within the largest of the vertices' errors at those depths,
// or the depth-independent bound (zoneMaxError at kInfiniteDepth) where eta_i >= 1; the
// smaller of the two. Exact for a zone of one point; the depths grow by 1 / (1 - eta), 1.2x for
// a 1 m square zone 2 m from the wall.
double zoneDepthBound(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind);
// zoneDepthBound(...) <= alpha, decided one vertex at a time (errorWithin), or zoneWithin where a
// vertex's eta >= 1. Rigorous like the bound.
bool zoneWithinDepth(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind,
                     double alpha);

// Ebbesmeyer's (1997) 2D rule (his eq. 2-4): eye at the sampling height, moving parallel to the
// wall by halfWidth at distance x from the wall point: error atan(halfWidth / x); minimum zone
// distance x_Tmin = halfWidth / tan(alpha); a wall (or scene) of width z_G needs
// n_T = z_G / (2 halfWidth) textures.
double seedError2D(double halfWidth, double distance);
double seedMinDistance(double halfWidth, double alpha);
int seedTextureCount(double sceneWidth, double minDistance, double alpha);

}  // namespace cavewall::walls
