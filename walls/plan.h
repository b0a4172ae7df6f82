#pragma once
// Zone planning for textured virtual walls (Ebbesmeyer 1997, sections 4-5), with the error
// bound proven exactly in 3D (walls/angular_error.h).
//
// For every cell and every virtual wall or portal bounding it (seen from that cell), the cell's
// floor is cut into zones, each a convex floor polygon times the scene's head height range:
//  - geometry: too close to the wall for any texture within alpha (and any zone of at least
//    minZoneSize); the cell behind the wall is drawn as geometry there;
//  - texture: one texture, baked from the zone's sampling point;
//  - blend: a strip of blendWidth around a border; it mixes every texture listed, and it lies
//    inside the region where each of them is proven within alpha (the texture's validRegion);
//    a texture->geometry blend strip (mixesGeometry) lies on the texture side of the geometry
//    border.
// Guarantee: for every eye in a zone (whole floor polygon and height range), every texture the
// zone draws with non-zero weight and every scene point behind the wall at any depth, the
// angle between the point's true direction and its texel's direction is <= alpha.
//
// Layout (per cell and wall, in the wall's floor frame: s along the wall, d away from it into
// the cell): the geometry strip d < dG with dG found by bisection; then rows of increasing
// distance, each cut into columns of maximal width by bisection (greedy; a row's depth is
// chosen among candidates to cover the most depth per texture). Zones of one cell and wall
// tile the cell's floor polygon. Sampling points: at mid head height, the centroid of the
// zone's row/column cell, or of its part nearest the wall when that proves a wider zone.
// The geometry distance is the smallest at which a zone of minZoneSize is proven, so the
// texture count trades against minZoneSize (a larger alpha shrinks the geometry strip and
// may therefore need more textures, not fewer).
// Depth walls keep the flat walls' geometry strip: their border is searched from where the
// flat bound first proves a zone of minZoneSize (the same layout with the flat bound), not from
// the wall. Their tighter bound would prove zones nearer the wall, where each needs a large
// texture: on the default plant at alpha = 10° it took the strip from 4.25 to 3.44 m for
// 3,517 textures instead of 2,980 (docs/depth-walls.md), and drew less geometry only there.
//
// Beyond a neighbour drawn as geometry (Plan::beyond): while the eye is in a cell's geometry
// zone of a wall or in that zone's texture->geometry blend strip, the cell behind the wall (the
// neighbour) is drawn as geometry, and so are its far walls' textures, from eyes outside the
// neighbour. For each such eye region and far wall the region is cut into zones exactly as a
// cell is (same layout, same guarantee, textures baked on the far wall from sampling points in
// the region), or, where no texture is proven, a geometry zone: the far wall's cell behind is
// drawn as geometry too; where that happens, the far walls of that cell are planned the same
// way for that part of the region (a second level, the last). Cells that see each other through
// an open boundary give the whole cell as eye region.

#include "display/off_axis.h"
#include "scenes/scene_description.h"
#include "walls/depth_wall.h"
#include "walls/polygon2d.h"

#include <glm/glm.hpp>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace cavewall::walls {

struct PlanOptions {
    double alphaDeg = 10.0;              // error bound, degrees, in (0, 90]
    double blendWidth = 0.2;             // metres, width of blend strips, >= 0
    double minZoneSize = 1.0;            // metres, smallest zone width/depth (at walking speed, at most
                                         // about one texture switch per second); > 2 * blendWidth
    double pixelsPerDegree = 10.0;       // texel density target at the zone's nearest distance
    int maxResolution = 4096;            // texels per texture side (cap); for depth walls also the
                                         // texel size their bound reserves, so at most the bake's cap
    WallKind wallKind = WallKind::Flat;  // flat: the flat bound (angular_error.h); depth: the depth
                                         // walls' bound (depthTextureBound: the smaller of
                                         // depth_wall.h's span form and its segment form, from each
                                         // wall's depth span PlannedWall::depthNear .. depthBehind)
};

// Throws cavewall::Error naming the option when it is out of range.
void validatePlanOptions(const PlanOptions& options);

// Which of a scene's own planning choices (scene.json "planning") a command's flags replace:
// --min-zone, and --max-res (bench: --bake-resolution).
struct PlanningFlags {
    bool minZone = false, maxRes = false;
};

// Where the command gave no flag for it, the scene's own zone size into `plan.minZoneSize` and
// its largest baked texture side into `maxResolution` (a command's bake resolution, or
// plan.maxResolution itself), when the scene has them. Throws, naming the scene's field, for a
// zone size too small for plan.blendWidth.
void useScenePlanning(const scenes::SceneDescription& description, PlanningFlags given, PlanOptions& plan,
                      int& maxResolution);

enum class ZoneKind { Texture, Blend, Geometry };
const char* toString(ZoneKind kind);

struct Texture {
    int id = 0;
    int cell = 0, wall = 0;
    glm::dvec3 samplingPoint{0.0};  // world
    Polygon2 validRegion;           // floor polygon (x, z) where the bound is proven
    double maxError = 0.0;          // radians, over validRegion: flat walls the exact
                                    // depth-independent maximum; depth walls depthTextureBound
    glm::ivec2 resolution{0};       // texels, from pixelsPerDegree (see texelSize)
};

struct Zone {
    int id = 0;
    int cell = 0, wall = 0;
    ZoneKind kind = ZoneKind::Geometry;
    Polygon2 floorPolygon;             // convex, (x, z), orientation of the cell's region
    glm::dvec2 heightRange{1.2, 2.0};  // absolute y
    std::vector<int> textures;         // texture ids: one for texture zones, all mixed for blends
    bool mixesGeometry = false;        // blend zones next to a geometry zone
};

struct PlannedWall {
    int id = 0;  // index into SceneDescription::walls
    std::string name;
    display::ScreenQuad quad;
    std::array<int, 2> cells{-1, -1};  // [front, back]
    // Largest distance behind the plane of geometry baked into its textures (both sides),
    // metres; infinity until known (assignDepthBehind in walls/visibility.h).
    double depthBehind = std::numeric_limits<double>::infinity();
    // Smallest distance behind the plane of geometry baked into its textures (both sides),
    // metres; 0 until known. [depthNear, depthBehind] is the depth walls' span (depth_wall.h).
    double depthNear = 0.0;
};

// One row of a side's layout in the side's floor frame (s along the wall, d into the cell).
// Column k spans s in [cuts[k-1], cuts[k]] (the first and last are open-ended); its texture is
// proven on that span widened by blendWidth / 2 at interior cuts, times `validated` in d, all
// clipped to the cell.
struct PlannedRow {
    double near = 0.0, far = 0.0;  // d range of the row (metres)
    glm::dvec2 validated{0.0};     // d range its textures are proven for (may be infinite)
    std::vector<double> cuts;      // column borders (s), increasing
    std::vector<int> textures;     // texture id per column: cuts.size() + 1 entries
};

// The zones of one cell for one wall: zones[firstZone, firstZone + zoneCount).
struct WallSide {
    int cell = 0, wall = 0, side = 0;  // side 0: the cell is in front of the wall
    int firstZone = 0, zoneCount = 0;
    int textureCount = 0;
    double geometryDistance = 0.0;  // dG, metres from the wall's footprint line (no geometry
                                    // zone when it equals the cell's nearest d)
    bool hasGeometry = false;
    // The floor frame: world (x, z) = origin + s * along + d * inward; inward points into the
    // cell. Rows are ordered by distance from the wall.
    glm::dvec2 origin{0.0}, along{1.0, 0.0}, inward{0.0, 1.0};
    std::vector<PlannedRow> rows;
};

// A far wall of a neighbour drawn as geometry, planned for the eyes of one region outside that
// neighbour (see the top of this header). side.cell is the neighbour, side.wall the far wall,
// side.side the neighbour's side of it; side's zones (in Plan::beyondZones, their cell and wall
// those of side) tile eyeRegion, and their textures (in Plan::textures, cell and wall those of
// side) are proven over their validRegion, which lies in eyeRegion.
struct BeyondSide {
    int eyeCell = 0;     // the cell holding the eye region
    int viaWall = -1;    // the wall whose geometry zone and blend strip draw the
                         // neighbour: the eye cell's own, or the parent's far wall;
                         // -1: an open boundary (whole cell)
    Polygon2 eyeRegion;  // convex floor polygon (x, z), within eyeCell, on the
                         // neighbour's side of the far wall's plane; x heightRange
    WallSide side;
    // Second level: the index in Plan::beyond of the far wall whose geometry zone (and blend
    // strip) draws this side's neighbour as geometry; -1 for a neighbour of the eye's cell.
    // The far walls of a neighbour at the second level are not planned (nor drawn).
    int parent = -1;
};

struct Plan {
    double alphaDeg = 10.0;
    PlanOptions options;
    std::vector<PlannedWall> walls;
    std::vector<WallSide> sides;
    std::vector<Texture> textures;  // of sides and beyond sides
    std::vector<Zone> zones;        // of sides
    std::vector<BeyondSide> beyond;
    std::vector<Zone> beyondZones;  // of beyond sides (ids index this vector)
};

// Plans every cell/wall pair of a validated description. Walls must not be horizontal.
// depthSpans: per wall of the description, (depthNear, depthBehind) metres (wallDepthSpans in
// walls/visibility.h), copied into PlannedWall; empty: (0, infinity) for every wall. Depth walls
// are planned with them (the flat bound does not use them). Throws Error for a size other than
// 0 or the wall count, or a span that is not 0 <= near <= far.
Plan planZones(const scenes::SceneDescription& description, const PlanOptions& options = {},
               const std::vector<glm::dvec2>& depthSpans = {});

// `texels` (at least one per side) scaled down, if its longer side is over maxResolution, so that
// side is maxResolution: the aspect is kept, so texels stay as square as the wall asks for. The
// plan and the bake (bakeResolution) cap alike, so a depth plan capped at the bake's size
// proves its bound for the texels the bake renders.
glm::ivec2 capResolution(glm::dvec2 texels, int maxResolution);

// The resolution a texture is baked at (gl::WallBaker): the plan's, capped by capResolution.
// Depth walls round each odd side up to even (down when it is an odd maxResolution), so that
// every texture's march reads halved depths (marchDepths); texels only get finer, which the
// planner's bound allows.
glm::ivec2 bakeResolution(glm::ivec2 planned, int maxResolution, WallKind kind = WallKind::Flat);

// The texels of a texture whose valid region's nearest point is `nearestDistance` metres from
// `wall`: pixelsPerDegree at that distance (texelSize), capped by capResolution.
glm::ivec2 textureResolution(double nearestDistance, const display::ScreenQuad& wall, const PlanOptions& options);

// The diagonal of one texel of `resolution` on `wall`, metres.
double texelDiagonal(const display::ScreenQuad& wall, glm::ivec2 resolution);

// The depth walls' planned bound of a texture proven over `volume`: the smaller of
// depthZoneBound (the span form) and depthSegmentZoneBound (the segment form; both rigorous,
// walls/depth_wall.h), with the texel of the resolution textureResolution gives for the
// volume's nearest distance at the sampling point's height: what the planner proves <= alpha
// and stores as Texture::maxError for depth walls. Radians.
double depthTextureBound(const ZoneVolume& volume, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                         glm::dvec2 span, const PlanOptions& options);

// depthTextureBound(...) <= alpha, proven (the planner's test): the segment form decided first
// (a decision per zone vertex), then the span form, whose search stops once its answer is known.
bool depthTextureWithin(const ZoneVolume& volume, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                        glm::dvec2 span, const PlanOptions& options, double alpha);

// The bound of `texture`'s error for one eye (world), radians, for the plan's wall kind: flat,
// maxAngularError up to the wall's depthBehind; depth, the smaller of depthEyeBound and
// depthSegmentEyeBound over the wall's span, with the texture's resolution. What the frame planner
// checks and reports every frame.
double textureErrorAt(const Plan& plan, const Texture& texture, glm::dvec3 eye);

// The zone of (cell, wall) containing floor point p (x, z), or -1. Zones of a side are
// searched linearly (a side has tens of zones).
int findZone(const Plan& plan, int cell, int wall, glm::dvec2 p);

// Texel edge length (metres) for a texture whose valid region's nearest point is `distance`
// metres from the wall: one texel spans 1/pixelsPerDegree degrees there.
double texelSize(double distance, double pixelsPerDegree);

// The wall quad as seen from `side` (0: front, 1: back): for side 1 the quad is mirrored so its
// normal points to the back side and the image is not mirrored for a viewer there. Textures
// seen from the back are baked and drawn on this quad.
display::ScreenQuad quadSeenFrom(const display::ScreenQuad& wall, int side);

}  // namespace cavewall::walls
