#pragma once
// The walkthrough's frame planner: everything a frame decides before anything is drawn, GL-free.
// The GL executor (walkthrough/gl/walkthrough.h) pages, uploads and draws what it returns.
//
// Per frame, in two steps (the executor uploads ready textures in between):
//  requests(input, views):
//   1. the cyclopean eye in the world = worldFromCave * head position; FrameSelector::select(eye)
//      gives the cell, every bounding wall's texture weights and geometryWeight, and the cells
//      drawn as geometry. One selection per frame, shared by both eyes and all screens.
//   2. walls outside every given view are neither requested nor drawn (a cluster rank pages only
//      what its own screens show); they keep a row in FramePlan::walls. The textures drawn now
//      (weight > 0) are wanted now; those the selection would draw 1.5 m away in each of 8
//      directions (the neighbouring zones) soon, then, while the eye moves, those it will draw
//      along its way (the cells' and beyond walls', in view or not: the selections at the eye's
//      position 0.125, 0.25 and 0.5 s ahead at its velocity, 1.5 to 12 m away). Geometry
//      paging's cellsSoon gains those selections' geometry cells likewise.
//  plan(resident):
//   3. a wall whose textures are not all resident keeps the textures it drew last (from the
//      same side) if they are still resident and still within the plan's alpha for this eye
//      (maxAngularError), else it is drawn as geometry (its cell behind joins the geometry
//      cells): a wall is never black or missing. Such walls are flagged `fallback`.
//   4. geometry: all structure + objects without a cell + objects of the geometry cells, each
//      neighbour's objects with the chains of openings it is seen through (FramePlan::portals).
//      Geometry paging (walls/geometry_pager.h, plan's `cellResident` given): a wall whose cell
//      behind would be drawn as geometry while that cell's geometry is not resident keeps its
//      textures instead (this frame's, renormalised without the geometry weight, or the last
//      ones drawn when still resident and within alpha), flagged `fallback` and counted in
//      FramePlan::geometryMisses; the cell is then not drawn unless another wall needs it.
//      Only when no texture within alpha exists (the wall's geometry zone) or for the viewer's
//      own cell is a non-resident cell drawn (FramePlan::geometryForced: the executor must
//      load it before drawing; prefetching the neighbours as `soon` makes this rare).
//   5. the error: textureErrorAt (walls/plan.h: maxAngularError for flat walls, the smaller
//      of depthEyeBound and depthSegmentEyeBound for depth walls) of every texture drawn
//      with non-zero weight against the true eye, in degrees and in pixels (FrameResult::maxErrorPixels:
//      each wall's error at the pixels per degree of the screens its quad appears on), and the
//      count of those over the plan's alpha (+ kErrorTolerance): 0 while the bound holds.
// Transition::Warp: every wall drawn with textures and no geometry weight gets the structure
// behind it warped into its texture's view (the texture of the largest weight when it mixes
// several). When the warp of such a wall is ill-conditioned for any given view
// (display::warpCondition > kMaxWarpCondition: the eye near the wall plane), the wall falls back
// to geometry (its cell behind drawn, no texture, flagged `fallback`), counted in warpFallbacks.
// Warp-morph (Transition::Warp, Aliaga & Lastra 1997, section 2): a wall's mix of textures and
// geometry becomes whichever weighs more (no alpha fade between texture and geometry; textures
// still cross-fade among themselves). When a wall switches between texture and geometry, for
// morphSeconds of FrameInput::time its cell behind (content and structure) is drawn by the warp
// pass through the wall as seen from p = lerp(samplingPoint, eye, s) (texture -> geometry;
// eye -> samplingPoint back), s the elapsed share: it starts as the texture's view and ends
// exact. During the morph the wall draws no quad and reports no textures and geometryWeight 1.
// A scene without virtual walls (no WallSetup) plans all geometry and requests nothing.
//
// Stateful per walkthrough (the textures each wall drew last, the morphs), deterministic given
// the inputs, FrameInput::time and the residency answers. Frames and units:
// config/conventions.h.

#include "display/display.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/frame_select.h"
#include "walls/cell_openings.h"
#include "walkthrough/frame_types.h"
#include "walls/wall_setup.h"
#include "walls/warp_wall.h"

#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace cavewall::walkthrough {

// Prefetching (requests()): the neighbouring zones are those kNeighbourMetres away; when the eye
// moves faster than kMovingMetresPerSecond, also what it will draw kLookaheadSeconds ahead at its
// current velocity (from kNeighbourMetres to kLookaheadMetres away).
inline constexpr double kNeighbourMetres = 1.5;
inline constexpr double kMovingMetresPerSecond = 0.1;
inline constexpr double kLookaheadSeconds[] = {0.125, 0.25, 0.5};
inline constexpr double kLookaheadMetres = 12.0;

// True when texture `id` is resident on the GPU (the executor's texture store; a set in tests).
using Residency = std::function<bool(int id)>;

struct TextureRequests {
    std::vector<int> now;   // drawn this frame (weight > 0), the cell's and beyond walls'
    std::vector<int> soon;  // of the neighbouring zones (may repeat ids of `now`)
    // Geometry paging by cell (walls/geometry_pager.h): the cells the selection draws as
    // geometry now; soon, those it draws as geometry 1.5 m away in each of 8 directions and
    // those behind every wall it selects, in view or not (a turn of the head shows them).
    std::vector<int> cellsNow, cellsSoon;
};

// One wall quad to draw with its textures (walls/gl/wall_pass.h).
struct WallDrawPlan {
    int wall = 0;              // index into Plan::walls
    display::ScreenQuad quad;  // world, as seen from the viewer's side (quadSeenFrom)
    // (texture id, weight), largest weight first, at most kMaxWallTextures (more are never
    // planned: the kept ones would take the dropped weight); sum = 1 - geometryWeight.
    std::vector<std::pair<int, double>> textures;
};

// Where a wall's warp-morph is (Transition::Warp).
enum class MorphPhase { Idle, ToGeometry, ToTexture };

struct WallMorph {
    int wall = 0;
    MorphPhase phase = MorphPhase::Idle;
    double share = 0.0;  // elapsed share s in [0, 1)
};

struct FramePlan {
    glm::dvec3 eyeWorld{0.0};         // cyclopean eye in the world
    int cell = -1, zone = -1;         // as FrameResult
    std::vector<bool> geometryCells;  // per description cell: drawn as geometry
    std::vector<int> objects;         // Scene::objects drawn by the scene renderer
    // Portal culling (walls/cell_openings.h), when the planner's portalCulling is on: the
    // viewer cell's openings and which objects are tested; empty (no test) otherwise.
    walls::PortalSets portals;
    std::vector<WallDrawPlan> wallDraws;
    std::vector<walls::WarpWall> warpWalls;  // Transition::Warp: walls drawn warped
    std::vector<WallMorph> morphs;           // walls in a warp-morph this frame
    std::vector<WallState> walls;            // every wall row (walls.csv), errors set
    double maxErrorDeg = 0.0, maxErrorPixels = 0.0;
    int texturesOverAlpha = 0;  // as FrameResult
    int warpFallbacks = 0;
    int geometryMisses = 0;           // walls kept as textures: their cell behind was not resident
    int geometryFallbacks = 0;        // walls drawn as geometry for want of a resident texture (step 3)
    std::vector<int> geometryForced;  // cells drawn as geometry though not resident (step 4)
};

// The objects drawn as geometry when `cells` (per cell index, true = drawn) are: all structure,
// objects without a cell, and the objects of those cells. Indices into scene.objects, ascending.
std::vector<int> objectsOfCells(const scenes::Scene& scene, const std::vector<bool>& cells);

class FramePlanner {
public:
    // Keeps references to scene, description, display and `walls` (null or without planned
    // walls: geometry only), which must outlive it. `screens`: the display screens whose
    // views are given and whose pixels count for the error (empty: all).
    FramePlanner(const scenes::Scene& scene, const scenes::SceneDescription& description,
                 const display::Display& display, const walls::WallSetup* walls, Transition transition,
                 double morphSeconds, std::vector<int> screens = {});
    ~FramePlanner();

    // Steps 1-2 of the header for this frame; `views` are the views the executor draws.
    TextureRequests requests(const FrameInput& input, const std::vector<display::ScreenView>& views);
    // Geometry paging by cell: requests() also fills cellsNow and cellsSoon (eight more cell
    // selections per frame). Off by default: frames without paging skip that work.
    void requestCells(bool on) { _requestCells = on; }
    // Off: the control (WalkthroughSettings::wallTextures): requests() asks for no texture and
    // plan() draws none; every wall keeps the selection's geometry weight, its cell behind is
    // drawn as geometry where that weight is non-zero, and no texture's error is counted. On by
    // default. Blend transition only (the warp draws textures).
    void drawTextures(bool on) { _drawTextures = on; }
    // On: plan() fills FramePlan::portals (WalkthroughSettings::portalCulling, on by default).
    // Off until called: the sets cost a pass over the objects a frame.
    void portalCulling(bool on) { _portalCulling = on; }
    // Steps 3-5 for the frame of the last requests() call, against `resident` textures and
    // `cellResident` cells (empty: every cell's geometry is resident).
    FramePlan plan(const Residency& resident, const Residency& cellResident = {});

    bool hasWalls() const { return _selector.has_value(); }
    const std::vector<int>& screens() const { return _screens; }

private:
    bool _requestCells = false;
    bool _drawTextures = true;
    bool _portalCulling = false;
    struct Memory;
    struct WarpOutcome;
    struct ViewScale;
    WallState chooseWall(const walls::WallBlend& blend, const Residency& resident, FramePlan& plan);
    void keepTexturesFor(const walls::WallBlend& blend, const Residency& resident, WallState& state, FramePlan& plan);
    WarpOutcome warpWall(const walls::WallBlend& blend, const WallState& state);
    void applyWarp(const walls::WallBlend& blend, const WarpOutcome& outcome, WallState& state, FramePlan& plan);
    bool withinBound(const std::vector<std::pair<int, double>>& set, const walls::PlannedWall& wall) const;
    bool warpConditioned(const walls::WarpWall& warp) const;
    bool wallInView(int wall) const;
    void measureError(FramePlan& plan) const;
    std::vector<ViewScale> viewScales() const;
    double wallPixelsPerDegree(int wall, const std::vector<ViewScale>& views) const;
    void addDraw(const walls::WallBlend& blend, const WallState& state, FramePlan& plan) const;

    const scenes::Scene& _scene;
    const scenes::SceneDescription& _description;
    const display::Display& _display;
    const walls::WallSetup* _walls;
    Transition _transition;
    double _morphSeconds;
    std::vector<int> _screens;
    std::optional<walls::FrameSelector> _selector;
    std::optional<walls::CellOpenings> _portals;
    std::map<int, const walls::Texture*> _textures;  // by id
    std::vector<Memory> _memory;                     // per wall
    // The frame between requests() and plan().
    FrameInput _input;
    std::vector<display::ScreenView> _views;
    glm::dmat4 _caveFromWorld{1.0};  // inverse(_input.worldFromCave), once per frame
    glm::dvec3 _eye{0.0};
    glm::dvec3 _lastEye{0.0};  // the last requests()' eye and time: the velocity
    double _lastTime = 0.0;
    bool _hasLast = false;
    walls::FrameSelection _selection, _seen;  // all, and those in view
    std::vector<WallState> _outOfView;
    bool _planned = true;           // plan() was called for this frame
    Residency _cellResident;        // during plan(): geometry paging, or empty
    std::vector<bool> _cellNeeded;  // during plan(): cells some wall draws as geometry
};

}  // namespace cavewall::walkthrough
