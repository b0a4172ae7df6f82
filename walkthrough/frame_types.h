#pragma once
// The walkthrough's plain data: what a frame is given (FrameInput), what it reports
// (FrameResult, one WallState per wall) and the settings that are not GL. Shared by the frame
// planner (walkthrough/frame_planner.h), the GL executor (walkthrough/gl/walkthrough.h), the input side and
// cluster serialisation in tools/, none of which needs a GL context for them.
//
// Frames and units: config/conventions.h. Times in seconds, durations in milliseconds.

#include "display/display.h"
#include "display/frame_stats.h"
#include "scenes/screen_image.h"
#include "walls/geometry_pager.h"
#include "walls/texture_pager.h"

#include <glm/gtc/quaternion.hpp>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace cavewall::walkthrough {

// How structure crossing a textured wall meets the texture (walkthrough/gl/walkthrough.h).
enum class Transition { Blend, Warp };

// The hand cursor's pose (walkthrough/gl/hand_cursor.h draws it).
struct HandCursorPose {
    glm::dvec3 position{0.0};                    // cave frame, metres
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // the hand points along its -Z
    double rayLength = 2.0;                      // metres
};

// Everything about a walkthrough that is not GL (walkthrough::gl::WalkthroughOptions adds the renderer's).
struct WalkthroughSettings {
    double textureBudgetMB = 256.0;  // GPU budget of resident wall textures, MB, > 0
    double uploadMBPerFrame = 8.0;   // texture bytes uploaded per frame at most, MB
    // Wait for the pager to decode and upload every requested texture before drawing, so the
    // frames depend only on the input (tests, replays, golden images). Off: a frame never
    // waits, missing textures fall back (walkthrough/frame_planner.h).
    bool synchronousPaging = false;
    // > 0: page the model's geometry by cell under this GPU budget in MB (walls/geometry_pager.h;
    // with virtual walls only); 0: every cell stays resident.
    double geometryBudgetMB = 0.0;
    // Reads every MIP level of a baked texture file on the pager's thread; empty: the pager's
    // own (walls/texture_pager.h). Tests inject slow or failing decoders here.
    walls::TexturePager::Decoder decoder;
    Transition transition = Transition::Blend;  // Warp: structure behind textured walls warped
    double morphSeconds = 0.5;                  // Warp: duration of a warp-morph, seconds, > 0
    // Levels of detail (render.lodPixels > 0): the geometry of every frame is drawn at the
    // levels SceneRenderer::chooseLods picks for render.lodPixels, over all screens and eyes
    // at once. triangleBudget > 0 caps the triangles the scene renderer submits per frame (all
    // views; the wall, warp and cursor passes are not counted) by raising the tolerance
    // (Maciel & Shirley's (1995) frame budget); 0: no cap.
    std::size_t triangleBudget = 0;
    // The most a budget may raise the tolerance to, pixels (>= render.lodPixels): beyond it a
    // frame is drawn over budget rather than with coarser shapes (FrameResult::lodOverBudget).
    double lodMaxPixels = 8.0;
    // False: the control of the image error, "cells without textures": every frame draws the
    // geometry cells the walls' selection draws (the viewer's cell, the neighbours in geometry
    // zones and blend strips, structure) and no wall texture; none is requested or loaded
    // (walkthrough/frame_planner.h FramePlanner::drawTextures). Blend transition only.
    bool wallTextures = true;
    // True (the default): objects of other cells are drawn only where they may be seen through
    // the openings of the viewer's cell (FramePlan::portals, render/portal_cull.h).
    bool portalCulling = true;
};

struct FrameInput {
    long frame = 0;          // frame number (for the pager's recency)
    double time = 0.0;       // seconds
    display::HeadPose head;  // cave frame
    glm::dmat4 worldFromCave{1.0};
    std::optional<HandCursorPose> hand;  // drawn when given
    bool readImages = false;             // read every rendered image back into FrameResult
    // Read every view's depth back into FrameResult::depths, after the frame is timed (walls
    // redrawn depth-only: the depth a viewer sees, walkthrough::gl::Walkthrough). Not sent to cluster ranks.
    bool readDepth = false;
    // This frame's triangle budget (with levels of detail), > 0 overrides
    // WalkthroughSettings::triangleBudget: a frame-time controller (display/frame_budget.h)
    // sets it frame by frame, the same on every cluster rank.
    std::size_t triangleBudget = 0;
    // With clusters (walkthrough::gl::ClusterOptions): this frame's budget of predicted milliseconds, > 0
    // overrides ClusterOptions::budgetMs (the frame-time controller sets it).
    double clusterBudgetMs = 0.0;
};

// One wall's state in a frame (walls.csv).
struct WallState {
    int wall = 0;                                  // index into Plan::walls
    std::vector<std::pair<int, double>> textures;  // drawn (texture id, weight)
    double geometryWeight = 0.0;                   // weight of the cell behind as geometry
    bool fallback = false;                         // wanted textures missing: previous or geometry drawn
    bool beyond = false;                           // a far wall of a neighbour drawn as geometry
                                                   // (FrameSelection::beyond), planned like the others
    double errorDeg = 0.0;                         // exact worst angular error of its drawn textures
    int texturesOverAlpha = 0;                     // of its drawn textures, those whose exact error
                                                   // exceeds the plan's alpha (0 when the bound holds)
};

// One view's depth (FrameInput::readDepth): the distance in metres from the view's eye to
// what each pixel of its viewport shows (display/eye_distance.h), virtual walls included.
struct ViewDepth {
    int screen = 0;
    int image = 0;  // RenderTargets image index (separate stereo: 0 left, 1 right)
    display::Eye eye = display::Eye::Center;
    int width = 0, height = 0;  // the view's viewport, pixels
    std::vector<float> metres;  // rows top to bottom; +inf: nothing drawn; NaN: invalid
};

struct FrameResult {
    glm::dvec3 eyeWorld{0.0};   // cyclopean eye in the world
    int cell = -1, zone = -1;   // viewer's cell (also without walls); zone of the
                                // first wall with one (-1 without walls)
    double frameMs = 0.0;       // renderFrame wall-clock time, until the GPU finished
    double cpuMs = 0.0;         // CPU time until every command was submitted
    double gpuMs = 0.0;         // GL_TIME_ELAPSED of the frame's commands
    display::FrameStats stats;  // triangles and draw calls, all views
    walls::PagerStats pager;
    // Textures refused this frame (walls::TexturePager::takeWarnings: a failed content check or
    // decode), one line each, naming the file; each texture is reported once per run.
    std::vector<std::string> warnings;
    std::size_t uploadedBytes = 0;       // wall texture bytes (all MIP levels) uploaded this
                                         // frame, at most WalkthroughSettings::uploadMBPerFrame
                                         // unless one texture alone is larger
    walls::GeometryPagerStats geometry;  // geometry paging by cell (zeros when off)
    int geometryMisses = 0;              // walls kept as textures: cell behind not resident
    int geometryForced = 0;              // cells drawn though not resident (loaded at once: a stall)
    // Walls drawn as geometry this frame because neither their wanted textures nor the previous
    // ones (within alpha) were resident (FramePlan::geometryFallbacks).
    int geometryFallbacks = 0;
    // Baking on demand (WalkthroughSettings via walkthrough::gl::WalkthroughOptions::baker): textures baked
    // by this run and handed to the pager, so far and this frame; textures still to bake.
    int texturesBaked = 0, texturesBakedNow = 0, texturesToBake = 0;
    bool bakerBusy = false;     // a background bake ran during some of the frame
    double maxErrorDeg = 0.0;   // max over drawn textures (0 without textures)
    int texturesOverAlpha = 0;  // sum of WallState::texturesOverAlpha (must be 0)
    // The walls' error in pixels as the viewer sees them, on the screens this instance renders:
    // over the walls, a wall's error (degrees) times the pixels per degree of visual angle of the
    // screens its quad appears on (display::minPixelsPerDegree of each view's screen, the scale
    // the image metrics use; the most of them; 0 where it appears on none). cave4's walls seen
    // from the centre, 1.5 m away, have 8.9 pixels per degree: 10 degrees are 89 pixels. Not the
    // length on the screen's surface, which at a screen's oblique far corner is several times
    // more pixels (3.3 times at cave4's front corners, the head at 1.7 m), each looking that
    // much smaller from the eye (display/pixel_scale.h).
    double maxErrorPixels = 0.0;
    // Levels of detail (WalkthroughSettings): the pixel tolerance used this frame (raised above
    // render.lodPixels when the triangle budget needed it), the largest geometric error drawn
    // in pixels, and whether even the coarsest levels exceeded the budget. 0 without levels.
    double lodTolerancePx = 0.0, lodErrorPx = 0.0;
    bool lodOverBudget = false;
    std::size_t geometryTriangles = 0;  // of stats.triangles, what the scene renderer submitted
                                        // (what triangleBudget caps)
    int warpFallbacks = 0;              // Transition::Warp: walls drawn as geometry because
                                        // their warp was ill-conditioned (eye near the plane)
    std::vector<WallState> walls;
    // Clusters (walkthrough::gl::ClusterOptions): nodes drawn by kind, the selection's predicted cost and
    // the budget it was held to, milliseconds. Zeros without clusters.
    int clusterObjects = 0, clusterTextured = 0, clusterAverage = 0;
    int clusterFades = 0;  // cross-fades under way (hierarchy/cluster_fades.h)
    double clusterPredictedMs = 0.0, clusterBudgetMs = 0.0;
    double clusterSelectedMs = 0.0;  // of clusterPredictedMs, the selection's (no fades)
    double clusterCheapestMs = 0.0;  // the selection at a budget of 0 (the floor's part)
    // Filled by the caller's frame-time controller (hierarchy/cluster_budget.h), zeros without one:
    // its target, the frame time it predicted for this frame (clusterPredictedMs plus the
    // median of the earlier frames' rest) and the floor (the cheapest selection's frame time).
    double clusterTargetMs = 0.0, clusterPredictedFrameMs = 0.0, clusterFloorMs = 0.0;
    // Per display screen (index = screen), summed over its eyes: wall-clock CPU ms of its views
    // (geometry, walls, cursor), triangles and draw calls. Screens this instance does not
    // render stay zero.
    std::vector<display::ViewStats> perScreen;
    std::vector<scenes::ScreenImage> images;  // when FrameInput::readImages
    // When FrameInput::readImages: the projector-corrected screens' images after their warp and
    // blend pass (display/gl/projector_pass.h), stems ending in "-warped"; empty without any.
    std::vector<scenes::ScreenImage> warpedImages;
    std::vector<ViewDepth> depths;  // when FrameInput::readDepth, views in drawing order
};

}  // namespace cavewall::walkthrough
