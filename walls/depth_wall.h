#pragma once
// Depth walls: a wall texture that also stores, per texel, how far behind the wall plane the
// surface seen through that texel lies, so that it can be reprojected to any eye. GL-free: the
// wall frame, the depth encoding, the reference reprojection (the algorithm the depth wall pass
// runs per pixel, walls/gl/depth_wall_pass.h) and its error bound.
//
// Wall frame. For a wall quad as seen from the texture's side (bake_key.h quadSeenFrom):
// origin lowerLeft, x along lowerLeft -> lowerRight, y along lowerLeft -> upperLeft (metres),
// z the distance *behind* the plane (away from the side the texture is seen from). An eye in
// front has z < 0; its distance to the plane is D = -z.
//
// Depth encoding. Texel (i, j) (rows top to bottom, as the colour) stores d = the distance
// behind the wall plane, along the normal, of the surface the sampling point S sees through
// the texel centre, as a 32-bit float in metres; +infinity where nothing was drawn (alpha 0).
// The surface point is P = T + (d / D_S) (T - S) for T the texel centre on the wall. It comes
// from the bake's reversed-Z float depth buffer (depthFromBuffer), whose relative precision is
// 2^-24 of the view distance: |error of d| <= 1.2e-7 (D_S + d), 12 um at 100 m, far below a
// texel; storing d as float adds 6e-8 d, and the depth file's 16-bit code at most
// depthFileError(d) (walls/depth_file.h: 0.9 mm at 10 m). Precision is not the limit; texel
// spacing is.
//
// Reprojection (reproject). An eye E sees the wall point W along the ray
//   Q(s) = W + s (W - E_xy) / D_E      (lateral position at depth s behind the plane).
// S sees Q(s) through a wall point T(s) that is linear in sigma = s / (D_S + s) (sigma in
// [0, 1) for s in [0, inf)); the ray hits the stored surface at the first s with
// s >= d(T(s)). The march steps uniformly in sigma, one step per texel crossed on the ray's
// longer texture axis (at most one texel per axis a step; a texel whose corner alone the ray
// clips may be stepped over, and the bound below holds for any hit), then finds the first
// crossing within the last step exactly (texelCrossing).
//
// Error bound (reprojectionErrorBound, proof in depth_wall.cpp). The surface point S saw
// through T at depth d is seen from E at the wall point
//   W = T + k(d) v(T),   k(d) = d / (D_E + d),
//   v(T) = (E_xy - S_xy) + (D_E / D_S - 1) (T - S_xy)     (the parallax vector at T),
// so a depth step d1 -> d2 between adjacent texels exposes a wall interval S never saw, whose
// angle at E is at most |k(d2) - k(d1)| |v(T)| / D_E. With the largest adjacent-texel step this
// bounds disocclusion and sampling together, plus the reprojected texel's own size
// (h (1 + k |D_E/D_S - 1|) / D_E, half a texel either side).
// Derivation: docs/depth-walls.md.

#include "display/off_axis.h"
#include "walls/angular_error.h"
#include "walls/texture_rect.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cavewall::walls {

// The kind of texture a virtual wall is baked and drawn as (`--walls flat|depth`).
enum class WallKind : std::uint8_t { Flat, Depth };
std::string_view wallKindName(WallKind kind);
// The words `--walls` accepts, in the order its help lists them.
inline constexpr std::array<std::pair<std::string_view, WallKind>, 2> kWallKindNames{
    {{"flat", WallKind::Flat}, {"depth", WallKind::Depth}}};
// Throws cavewall::Error naming `where`, expected "flat" or "depth", for anything else.
WallKind parseWallKind(std::string_view text, const std::string& where);

inline constexpr float kNoSurface = std::numeric_limits<float>::infinity();

struct WallFrame {
    glm::dvec3 origin{0.0};             // lowerLeft
    glm::dvec3 x{1, 0, 0}, y{0, 1, 0};  // unit axes along the quad's edges
    glm::dvec3 behind{0, 0, -1};        // unit normal pointing behind the plane
    double width = 0.0, height = 0.0;   // metres

    // World -> wall frame (x, y lateral in metres, z metres behind the plane) and back.
    glm::dvec3 toWall(glm::dvec3 world) const;
    glm::dvec3 toWorld(glm::dvec3 wall) const;
};

// The frame of `quad` (front side facing the viewer; conventions.h). Throws Error for a
// degenerate quad.
WallFrame wallFrame(const display::ScreenQuad& quad);

// Per-texel depth behind the wall plane (metres; kNoSurface where nothing), rows top to bottom.
struct DepthImage {
    int width = 0, height = 0;
    std::vector<float> depth;
    float at(int i, int j) const { return depth[static_cast<std::size_t>(j) * width + i]; }
};

// The smallest and largest finite depth (both 0 when there is none).
glm::dvec2 depthRange(const DepthImage& image);
// Clamps every finite depth to `range` (x <= y): decoded 16-bit depths (walls/depth_file.h)
// brought back inside the baked range, so inside the wall's depth span the bounds assume.
void clampDepths(DepthImage& image, glm::dvec2 range);

// Block minima of a depth image, for skipping empty space in the march: an image of
// floor(width / block) x floor(height / block) whose texel (bx, by) is the smallest depth over the
// texels of blocks bx - dilate ... bx + dilate, by - dilate ... by + dilate (clipped to the image;
// the last block of a row or column also takes the texels beyond it that make no whole block).
// With dilate 1, every point within block - 1 texels (per axis) of a point of block (bx, by), or
// of a point beyond the last block that clamps to it, lies over texels whose depth is at least
// the value: no sample of such a stretch of the ray can hit a surface nearer than that.
// Throws cavewall::Error unless block >= 1, dilate >= 0 and the image holds a whole block.
DepthImage depthBlockMinimum(const DepthImage& image, int block, int dilate);
// The depths the walkthrough marches (the bake writes them, walls::BakeWriter): each 2 x 2
// block of the rendered image replaced by its nearest depth, an image of half the width and
// height, when both are even; otherwise the image as it is. A depth texel then covers exactly
// 2 x 2 colour texels, so the march's texel units (the depth texture's size over the wall's)
// and the colour's normalised coordinates still agree, and a march crosses half as many texels.
// Every value is a baked depth, so it lies in the baked range and in the wall's span: the
// planner's bound (depthEyeBound, whose proof needs only that the stored and ray depths lie in
// the span and that the colour texel shown is the one at the hit) holds unchanged. Per image,
// marchErrorBound bounds what the halved march draws (depthWallErrorBound is for full depths);
// a hole narrower than a depth texel is sealed, and that bound counts the error. Measured:
// docs/depth-walls.md.
DepthImage marchDepths(DepthImage image);
// The size marchDepths gives a width x height image.
glm::ivec2 marchDepthSize(int width, int height);

// The march's block (texels a side; walls::gl::DepthTexture::skip holds depthBlockMinimum with
// dilate 1, walls::gl::uploadDepthTexture) and the most steps one skip test covers (each step
// crosses at most one texel per axis, so kSkipSteps steps stay within the 3 x 3 blocks).
inline constexpr int kSkipBlock = 8;
inline constexpr int kSkipSteps = kSkipBlock - 1;

// The smallest rectangle of whole texels holding every finite depth of `image` (empty when there
// is none). Nothing outside it can be hit by a march.
TextureRect contentRect(const DepthImage& image);

// Where on the wall a depth layer's march can hit, seen from `eye` (the wall frame, z < 0, as
// reproject takes it; S likewise): every wall point
// whose eye ray meets, at a depth in `range` behind the plane, a ray of S through `content`
// (a TextureRect of the wall's texture, which S sees the wall through) lies in the returned
// rectangle of the wall (the same fractions), grown by `margin` metres on every side and
// clipped to the wall. Those points of content form a truncated pyramid with apex S (its eight
// corners: content's corners at both ends of the range), which is convex, and the central
// projection from an eye in front of the plane keeps it convex, so the rectangle around the
// eight corners' projections holds its whole image. Empty when content is, when the range is
// not 0 <= near <= far < infinity, or when the eye or S is not in front of the plane. The
// depth wall pass draws only this part of a wall (walls::gl::DepthWallPass): the pixels it leaves out
// are ones no march hits, which add nothing.
TextureRect depthDrawRect(const WallFrame& frame, glm::dvec3 eye, glm::dvec3 samplingPoint, const TextureRect& content,
                          glm::dvec2 range, double margin);

// A depth image as the GPU holds it (walls::gl::uploadDepthTexture): the depths and, when the image has
// a whole skip block (kSkipBlock texels on both sides), their block minima (depthBlockMinimum
// with dilate 1; empty otherwise). Made on the texture pager's thread, off the frame.
struct DepthTextureData {
    DepthImage depth, blocks;
    // What the march needs beside the texels, from the texture's manifest entry: its sampling
    // point (world) and baked depth range (the range the depths are clamped to). They arrive and
    // leave with the texels (walls::gl::TextureStore::depthLayer).
    glm::dvec3 samplingPoint{0.0};
    glm::dvec2 range{0.0};
    // contentRect of the depths: where the march can hit (depthDrawRect).
    TextureRect content;
    std::size_t gpuBytes() const;  // depthTextureBytes of its size
};
// Throws cavewall::Error unless the image holds width x height depths.
DepthTextureData depthTextureData(DepthImage image);
// GPU bytes of a width x height depth texture's GL_R32F storage: the depths, and the block
// minima (width / kSkipBlock x height / kSkipBlock) when it has a whole skip block.
std::size_t depthTextureBytes(int width, int height);

// Converts a reversed-Z depth-buffer value of a frustum whose screen is the wall (clipFromView
// of display::offAxisFrustum: z_view = -P[3][2] / (depth + P[2][2])) into the distance behind
// the wall; eyeDistance is the frustum's. Buffer value 0 (cleared, nothing drawn) -> kNoSurface.
float depthFromBuffer(float bufferValue, const glm::dmat4& clipFromView, double eyeDistance);

// The wall-frame centre of texel (i, j) of a width x height texture of `frame`.
glm::dvec2 texelCentre(const WallFrame& frame, int width, int height, int i, int j);

struct ReprojectSettings {
    int maxSteps = 64;      // linear steps at most (the pass's uniform); fewer when fewer texels are crossed
    int refine = 6;         // bisections at most before the exact crossing, while the last step
                            // spans more than one texel on an axis (only when maxSteps capped the march)
    bool cutSheets = true;  // cut rubber sheets (below); false keeps every hit, for measuring the cut
};

// The march's hit test at sigma: the stored depth d is reached at or before sigma, with a
// tolerance of 1e-5 of the distance from S (so that the first sample, at the nearest depth, hits
// the nearest surface); sigma >= hitSigma(d). The shader tests the same inequality multiplied
// out, without the division. False for kNoSurface.
bool hitsDepth(double sigma, double d, double samplingDistance);
// The smallest sigma at which hitsDepth holds for depth d: (d - 1e-5 D_S) / (D_S + d); 2 (past
// the ray's end at 1) for kNoSurface.
double hitSigma(double d, double samplingDistance);

// The first crossing of the ray with the stored depths within the march's last step [lo, hi],
// in texel units: the ray's texture point is ta + sigma (tb - ta) (x right, y down from the
// upper edge, as rows are stored; outside the image there is no surface). Requires consecutive
// samples at most one texel apart per axis and hitsDepth at hi for depthHi (the depth of hi's
// texel). Depths are constant per texel, so the ray meets at most three texels between lo and hi,
// and in each the first point that hits is the later of where it enters and hitSigma. Returns
// that sigma and the texel's depth (hi and depthHi when rounding finds none in [lo, hi]).
// `from` is the texel the ray came from when it entered the texel hit already behind its
// surface (the hit is on the side of a depth step, where a rubber sheet would stretch), with its
// depth `fromDepth`; (-1, -1) otherwise. It may lie outside the image (kNoSurface there).
struct TexelCrossing {
    double sigma = 0.0;
    float depth = kNoSurface;
    glm::ivec2 from{-1, -1};
    float fromDepth = kNoSurface;
};
TexelCrossing texelCrossing(const DepthImage& image, glm::dvec2 ta, glm::dvec2 tb, double samplingDistance, double lo,
                            double hi, float depthHi);

struct ReprojectHit {
    bool hit = false;
    glm::dvec2 texture{0.0};  // wall-frame point T of the texture seen (metres)
    double depth = 0.0;       // s at the hit, metres behind the plane (on the eye's ray)
    double surface = 0.0;     // the stored depth of the texel hit: S saw the point
                              // T + (surface / D_S)(T - S), whose colour the pixel shows
    bool filled = false;      // a cut sheet: T lies just inside the far texel the ray came from
};

// ---- Cutting rubber sheets ----
//
// Where the ray enters a march texel B already behind B's surface, coming from a texel A that it
// passed in front of (the crossing's `from`), the hit lies on the side of a depth step: a march
// that keeps it stretches B's colour over whatever lies between the two surfaces (a rubber
// sheet). If A and B can hold one surface (no depthJump), the hit stands: it is a staircase
// step of that surface. Otherwise the sheet is cut:
//  - A holds a surface: the pixel shows, at the ray's depth at the entry, the colour texel
//    under the ray's point kFillBack texels (on the ray's longer texture axis) before the entry:
//    a texel the ray passed in front of, next to B, so the far side's (its texels, stretched
//    over the gap: the surface S saw next to what it could not see);
//  - A is an empty texel inside the image: nothing is behind the sheet, and nothing is drawn;
//  - A lies outside the image: content beyond the wall's edge is unknown, and the hit stands.
// Bound: the entry's ray depth s lies behind B (s >= m_B^-), and the texel shown, a neighbour of
// B, holds d_c >= s, so a filled pixel shows a colour texel c at a ray depth s >= m_B^- of a
// neighbour B of c's march texel: the
// per-image bound (marchErrorBound) counts k(d_c) - k(m_B^-); the planner's forms need only
// that s and d_c lie in the span, which they do.

// The smallest grazing angle (radians) at which one surface is assumed to be seen: two
// neighbouring march texels whose depths differ by more than such a surface could give hold two
// surfaces. A surface seen at a shallower angle is cut as if it were two; its fill shows a
// neighbouring texel of the same surface, within the same bound.
inline constexpr double kMinGrazing = 0.5235987755982988;  // 30 degrees
// How far before a cut sheet's entry the fill is sampled, in march texels on the ray's longer
// texture axis: well inside the texel before (float rounding), within one texel of the entry.
inline constexpr double kFillBack = 0.25;

// Whether march texels at depths dNear <= dFar (metres behind the plane; dFar may be
// kNoSurface), whose colour texels' centres lie at most `pitch` metres apart on the wall and at
// most `lateral` metres from S's foot on the wall, hold two surfaces (a depth jump). One plane
// seen from S at a grazing angle of at least g through two rays delta apart (delta <=
// pitch / D_S) lies at distances along the rays whose ratio is at most sin g / sin(g - delta)
// (law of sines); distances from S's plane differ from those by at most the ratio of the rays'
// cosines, cos delta + sin delta tan beta, tan beta <= (lateral + pitch) / D_S. A jump is a ratio
// (D_S + dFar) / (D_S + dNear) beyond their product. False when delta >= g / 2 (the texels are
// too coarse to tell); true for an empty dFar.
bool depthJump(double dNear, double dFar, double samplingDistance, double pitch, double lateral);
// The ratio depthJump compares with, as (a, b): a + b lateral; (0, 0) where it never cuts. The
// depth wall pass computes it per layer and draw.
glm::dvec2 jumpRatio(double samplingDistance, double pitch);
// The `pitch` for march texels of an image of `frame` with width x height texels: 1.5 march
// texel diagonals, the farthest two colour texels of neighbouring halved march texels can be.
double jumpPitch(const WallFrame& frame, int width, int height);

// The reference reprojection of one pixel: eye E and sampling point S in the wall frame (z < 0),
// W the wall point (x, y) of the pixel. Exactly the shader's algorithm, in double, with rubber
// sheets cut (above).
ReprojectHit reproject(const DepthImage& image, const WallFrame& frame, glm::dvec3 eye, glm::dvec3 samplingPoint,
                       glm::dvec2 wallPoint, glm::dvec2 range, const ReprojectSettings& settings = {});

// The parallax vector v(T) above (wall frame; eye and sampling point with z < 0).
glm::dvec2 parallaxVector(glm::dvec3 eye, glm::dvec3 samplingPoint, glm::dvec2 wallPoint);

// Where E sees the surface point that S saw through T at depth d: W = T + k(d) v(T).
glm::dvec2 reprojectedPoint(glm::dvec3 eye, glm::dvec3 samplingPoint, glm::dvec2 wallPoint, double depth);

// The angle at E of the wall interval exposed by a depth step d1 -> d2 at T (the disocclusion
// width): |k(d2) - k(d1)| |v(T)| / D_E, an upper bound of the exact angle.
double stepAngle(glm::dvec3 eye, glm::dvec3 samplingPoint, glm::dvec2 wallPoint, double d1, double d2);

// The bound of the error of reprojecting a wall from eye E with content between depths
// [d1, d2] behind the plane, for any texel of the wall (v(T) is affine in T, so |v| is largest
// at a corner): (k(d2) - k(d1)) max|v| / D_E. With d1 = 0 and d2 the content's far depth it is
// the flat wall's error scale; with the largest depth step it is the depth wall's.
double reprojectionErrorBound(const WallFrame& frame, glm::dvec3 eye, glm::dvec3 samplingPoint, double d1, double d2);

// The depth wall's bound for one baked depth image, in parts (radians):
//  - steps: over every pair of adjacent texels with finite depths d1 < d2, the angle of the
//    interval the step opens across its edge, (k(d2) - k(d1)) max(0, v . n) / D_E with n the
//    unit vector from the d1 texel to the d2 one (the far side moves by k(d2) v, the near by
//    k(d1) v: the gap opens only when v points from near to far; stepAngle is the same without
//    the direction, an upper bound of it); v at both texels; the largest (a
//    step to or from kNoSurface is no disocclusion: nothing is behind either side, and the
//    march never hits an empty texel, so a silhouette against emptiness reprojects exactly);
//  - border: what E sees through the wall near its edges that S saw outside the wall
//    (borderAngle: content beyond the edge may lie at any depth, so k < 1 and the band is at
//    most v . n_in wide, n_in the edge's inward normal); it does not depend on the depths;
//  - texel: the reprojected texel's own size, 0.5 h max(1, D_E / D_S) / D_E, h the texel diagonal.
// The angle of the widest band along the wall's edges where E may see content S saw outside
// the wall: max over the edges' ends of max(0, v . n_in) / D_E.
double borderAngle(const WallFrame& frame, glm::dvec3 eye, glm::dvec3 samplingPoint);

struct DepthWallBound {
    double steps = 0.0, border = 0.0, texel = 0.0;
    double interior() const { return steps + texel; }  // away from the wall's edges
    double total() const { return std::max(steps, border) + texel; }
};
DepthWallBound depthWallErrorBound(const DepthImage& image, const WallFrame& frame, glm::dvec3 eye,
                                   glm::dvec3 samplingPoint);

// The per-image form of the planner's bound below, for the depths the walkthrough marches
// (marchDepths of `full`, the depth image as baked; `range` the march's, depthRange of `full`).
// It bounds what a drawn pixel shows, as the planner's claim does: the angle at E between the
// pixel's direction and the true direction of the scene point whose colour it shows.
// Claim. Let a march texel B hold m_B, the nearest of the full depths d_c of its colour texels c
// (one texel, or 2 x 2 when marchDepths halves), and let s_B be the largest of m_B and its eight
// neighbours' values (range.y for a neighbour outside the image or empty). A pixel the march
// draws from B, showing colour texel c of B with d_c finite, is within
//   depth + texel,  depth = max over such (B, c) of  dk |v(T_c)| / D_E,
//   dk = max(k(s_B) - k(d_c), k(d_c) - k(m_B^-)),  m_B^- = (m_B - 1e-5 D_S) / (1 + 1e-5),
//   texel = 0.5 h max(1, D_E / D_S) / D_E, h the colour texel's diagonal.
// A cut sheet's fill (reproject) shows a colour texel c at a ray depth of at least m_N^- of a
// neighbour N of c's march texel, and d_c >= s: so the below term takes the nearest of m_B and
// its eight neighbours' finite values in place of m_B.
// Rigorous for marches whose last step crosses at most a texel per axis (maxSteps not
// reached, or the bisections end within a texel); otherwise the planner's span bound still
// holds. Pixels showing an empty colour texel (alpha 0) draw nothing and are not in the claim.
// Derivation: docs/depth-walls.md.
// It is the planner's bound with the span replaced by each texel's own neighbourhood, so at
// most depthEyeBound for a span holding the image. With halved depths a block straddling a
// step counts the step within it (k(d_c) - k(m_B)): a step the planner's span covers anyway.
struct MarchBound {
    double depth = 0.0, texel = 0.0;
    double total() const { return depth + texel; }
};
MarchBound marchErrorBound(const DepthImage& full, const WallFrame& frame, glm::dvec3 eye, glm::dvec3 samplingPoint,
                           glm::dvec2 range);

// ---- The planner's bound: depth walls planned with the reprojection's own error ----
//
// The bound above needs the baked depth image; the planner runs before any bake. It needs only
// the depth span [dNear, dFar] of everything a wall's textures can show: the nearest and the
// farthest corner behind the plane of the boxes of the objects baked into them
// (walls/visibility.h WallContents::depthNear, depthBehind). Every stored depth lies in it.
//
// Claim. For an eye E in front of the wall (distance D_E) and every pixel the depth wall pass
// draws with texture T_S (sampling point S, distance D_S, texel diagonal h), the pixel shows
// the colour of a scene point P that S saw, and the angle at E between P's true direction and
// the pixel's direction is at most
//   B(E) = [ (k(dFar) - k(dNear)) max_T |v(T)| + 0.5 h max(1, D_E / D_S) ] / D_E,
//   k(d) = d / (D_E + d), max over the wall's corners (v is affine in T).
// The bound does not depend on the march's step count: a march that skips a thin surface draws
// another stored point, still within B.
// Not in the bound: what is not drawn, and the colour filter. (1) Near the wall's edges E may
// see, through the wall, content S saw outside the rectangle (no texel holds it): a band at
// most k(dFar) max(0, v . n_in) / D_E wide (borderAngle with k(dFar) < 1) where the march finds
// nothing (discarded: the structure behind shows) or a nearer stored surface (drawn, within
// B); it can be wider than B when dNear > 0. (2) The colour filter (bilinear, mipmaps) mixes
// neighbouring texels, as on flat walls, whose bound ignores it too.
// Precision: the span is widened by 1e-6 (D_S + d) either side, far above the stored depths'
// error (top of this header), so float rounding cannot leave it.
// Over a zone (convex floor polygon x height range) the bound is refined, still rigorously, by
// a best-first subdivision of the wall into boxes of texel centres (at most 64 splits, stopping
// within 2 % of an estimate at box centres), each bounded over the zone's vertices: the largest
// box bound plus the texel term, an upper bound whatever the budget. dFar may be infinite.
// Derivation: docs/depth-walls.md.

// B(E) above for one eye (world), a texture baked from `samplingPoint` (world) on `wall` (either
// side: the bound is symmetric), content depths in `span` = (dNear, dFar) metres behind the
// plane, texels of diagonal `texelDiagonal` metres. Radians; pi when the eye or the sampling
// point is on the plane or they are on different sides of it.
double depthEyeBound(glm::dvec3 eye, glm::dvec3 samplingPoint, const display::ScreenQuad& wall, glm::dvec2 span,
                     double texelDiagonal);

// The zone form above: every eye of `zone`. Radians, at least every depthEyeBound in the zone
// (depthEyeBound is this for a zone of one point).
double depthZoneBound(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                      glm::dvec2 span, double texelDiagonal);
// depthZoneBound(...) <= alpha, the planner's predicate: the same answer, but the search stops
// as soon as it is known (most of the planner's probes are decided by the first boxes).
bool depthZoneWithin(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall, glm::dvec2 span,
                     double texelDiagonal, double alpha);

// ---- The segment form of the planner's bound ----
//
// Claim. Under the same conditions, every pixel the pass draws is also within
//   G(E) = seg(E) + 0.5 h max(1, D_E / D_S) / D_E,
// seg(E) = the largest angle at E subtended by the part [dNear, dFar] of S's ray through any
// point T of the wall, P(d) = T + (d / D_S)(T - S) for d in the span:
//   seg(E) = maxAngularError(E, S, wall', dFar - dNear)   (angular_error.h),
// wall' = nearWall(wall, S, dNear), the wall projected from S onto the parallel plane dNear
// behind it: P(dNear) is wall''s point on the ray, P(dFar) lies dFar - dNear behind wall'.
// It is the exact angle where the span form bounds the displacement along the segment
// linearly, so it is at most the span form's step term over the whole span; with dNear = 0 it
// is the flat texture's own exact error up to dFar, and every dNear > 0 makes it smaller.
// Over a zone it is zoneDepthBound on wall' for that depth (angular_error.h): the zone's vertices'
// errors at depths grown by 1 / (1 - eta), eta = r^2 / h^2 (r the zone's spread, h a vertex's
// distance to wall''s plane), rigorous for every eye of the zone at one eye per vertex; or, where
// eta >= 1, the depth-independent error of wall', largest at a zone vertex.
// Derivation: docs/depth-walls.md.

// The wall projected from `samplingPoint` onto the plane parallel to it `depth` metres behind
// it (on the side away from the sampling point): corners c + (depth / D_S)(c - S). Throws
// Error when the sampling point is on the plane.
display::ScreenQuad nearWall(const display::ScreenQuad& wall, glm::dvec3 samplingPoint, double depth);

// G(E) above for the span (dNear, dFar) (dFar may be infinite). Radians; pi when the eye or the
// sampling point is on the plane or they are on different sides of it.
double depthSegmentEyeBound(glm::dvec3 eye, glm::dvec3 samplingPoint, const display::ScreenQuad& wall, glm::dvec2 span,
                            double texelDiagonal);
// Over a zone: zoneDepthBound of nearWall at dNear for dFar - dNear, plus the texel term at the
// zone's nearest distance. At least every eye's form.
double depthSegmentZoneBound(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                             glm::dvec2 span, double texelDiagonal);
// The zone form proven within alpha: zoneWithinDepth on nearWall at alpha less the texel term
// (one decision per zone vertex, stopping at the first that fails), not the bound's bisection to
// 1e-9 rad. Rigorous like the bound; it can accept where the bound exceeds alpha by its
// tolerance.
bool depthSegmentZoneWithin(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                            glm::dvec2 span, double texelDiagonal, double alpha);

}  // namespace cavewall::walls
