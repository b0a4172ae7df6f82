#pragma once
// Maciel & Shirley's (1995) impostors of a cluster (their sections 3 and 5.1), GL-free: the
// geometry of a cluster's box, its faces as screens for the project's off-axis projection
// (display/off_axis.h), the viewing regions of each face (the paper's Figure 3) with the eye a
// face's texture is rendered from, and the average-colour box made from the textures.
//
// A textured box has one texture per face and viewing region: the cluster's own objects seen
// from the region's sampling eye through the face (the face is the screen, so the image square
// is the face; alpha 0 where nothing is drawn). Every object lies inside the box and the
// sampling eye is on the outer side of the face, so what the face shows is exactly what that
// eye sees through it: the front faces of the box together reproduce the cluster's image at a
// sampling eye. At run time each face towards the eye shows the texture of the region the eye
// is in.
//
// Frames: world, metres. Face f: axis f / 2 (x, y, z), outward normal +axis for even f, -axis
// for odd f. A face's quad is given as seen from outside (display::ScreenQuad: lowerLeft,
// lowerRight, upperLeft; right x up = the outward normal); side faces have +Y up, the top face
// -Z up, the bottom face +Z up.

#include "display/off_axis.h"
#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace cavewall::hierarchy {

inline constexpr int kBoxFaces = 6;
// Regions per face: 0 the centre (the eye within kCentreRegionDeg of the normal), 1..4 the eye
// off the normal towards +right, -right, +up, -up (whichever lateral axis dominates).
inline constexpr int kFaceRegions = 5;
inline constexpr double kCentreRegionDeg = 20.0;
// A side region's sampling eye is tilted this far from the normal towards its side.
inline constexpr double kRegionTiltDeg = 40.0;
// Sampling eyes lie this many box diagonals from the face centre.
inline constexpr double kSamplingDistance = 2.0;

// The box an impostor is drawn on: `bounds` grown on every axis thinner than 1 % of its largest
// extent (at least 1 mm) to that size, so no face is degenerate. `bounds` must not be empty.
scenes::Bounds impostorBox(const scenes::Bounds& bounds);

// Face `face` (0..5) of `box` as a screen seen from outside.
display::ScreenQuad boxFace(const scenes::Bounds& box, int face);
glm::dvec3 faceNormal(int face);  // outward, unit

// Whether `eye` (world) is on the outer side of `face`'s plane: the face is towards the eye.
bool faceTowards(const scenes::Bounds& box, int face, glm::dvec3 eye);

// The viewing region of `face` that `eye` is in (0..kFaceRegions-1); meaningful when the face
// is towards the eye.
int viewRegion(const scenes::Bounds& box, int face, glm::dvec3 eye);

// The eye the texture of (face, region) is rendered from: kSamplingDistance box diagonals from
// the face centre, along the normal (region 0) or tilted kRegionTiltDeg towards the region's side.
// viewRegion of this eye is `region`.
glm::dvec3 samplingEye(const scenes::Bounds& box, int face, int region);

// Texels per side of a face's texture: `maxResolution` along the longer side, the other side
// in proportion (at least 4).
glm::ivec2 faceResolution(const scenes::Bounds& box, int face, int maxResolution);

// One face of an average-colour box (Maciel & Shirley 1995, section 5.1): the mean colour of
// the pixels something covers in the face's centre-region texture, and the share of the face
// they cover. Drawn as an opaque rectangle of that colour and area, centred on the face.
struct FaceAverage {
    glm::vec3 linearColour{0.0f};  // linear RGB, [0, 1]
    float coverage = 0.0f;         // [0, 1]: covered texels (alpha-weighted) over all texels
    bool operator==(const FaceAverage&) const = default;
};

// The average of `premultiplied`: 8-bit RGBA, sRGB-encoded colour premultiplied by alpha (what
// the impostor's sRGB target reads back: walls::gl::WallTextureRenderer; straight and
// premultiplied agree where alpha is 0 or 1), alpha as coverage. Colour is averaged in linear
// light, weighted by alpha: the sum of premultiplied colours over the sum of alphas.
FaceAverage faceAverage(const scenes::Image& premultiplied);

// The rectangle an average face covers: the face's quad scaled about its centre by
// sqrt(coverage) on both sides (Maciel & Shirley's "average area").
display::ScreenQuad averageFaceQuad(const display::ScreenQuad& face, float coverage);

// Directions (unit, world, from the cluster's centre towards the eye) from which a cluster's
// representations are compared with full detail to measure their accuracy: four around it at
// 25 degrees elevation, one from above and one at 60 degrees elevation between two of them.
inline constexpr int kAccuracyDirections = 6;
std::array<glm::dvec3, kAccuracyDirections> accuracyDirections();

// Index of the accuracy direction nearest to the direction from `box`'s centre to `eye`.
int nearestAccuracyDirection(const scenes::Bounds& box, glm::dvec3 eye);

// A view that sees all of `box` from `direction` (unit, from its centre towards the eye): the
// eye 2.5 box diagonals away, the screen a square through the box centre facing it, 1.5
// diagonals wide (the box's projection from there spans at most 1.25 diagonals).
struct BoxView {
    display::ScreenQuad screen;
    glm::dvec3 eye{0.0};
};
BoxView viewOfBox(const scenes::Bounds& box, glm::dvec3 direction);

// Accuracy in [0, 1] from a mean LDR-FLIP error in [0, 1] (metrics/flip.h): 1 - error.
double accuracyFromFlip(double flipMean);

}  // namespace cavewall::hierarchy
