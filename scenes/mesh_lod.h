#pragma once
// Levels of detail: coarser index lists over a mesh's own vertices, each with the geometric
// error it costs, and the per-frame choice of a level for every drawn object under a pixel
// tolerance and an optional triangle budget (Maciel & Shirley's (1995) frame budget, their
// section 4: the representation of every object is chosen so that the frame's cost stays within
// the budget while the accuracy lost is as small as possible).
//
// Levels come from meshoptimizer's edge-collapse simplifier. It keeps a subset of the mesh's
// vertices (never moves one) and keeps seams (vertices split by normal or texture coordinates)
// and borders in place as far as the error allows. Its own error estimate comes from quadrics
// and runs up to 3x below the true deviation on curved parts, so each level's `error` is the
// larger of that estimate and the symmetric Hausdorff distance between the level and the full
// mesh, sampled (scenes/mesh_distance.h).
//
// Weld a mesh first (scenes/mesh_optimize.h): a triangle soup has no edges to collapse.

#include "scenes/scene.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace cavewall::scenes {

struct LodLevel {
    std::uint32_t firstIndex = 0;  // into MeshLod::indices
    std::uint32_t indexCount = 0;  // 3 per triangle
    double error = 0.0;            // model units: how far this level's surface lies from the
                                   // full mesh's at most (both ways); 0 for level 0, non-decreasing
};

struct MeshLod {
    std::vector<std::uint32_t> indices;  // every level's triangles, finest first; level 0 is
                                         // the mesh's own index list, unchanged
    std::vector<LodLevel> levels;        // at least one

    std::size_t triangles(int level) const { return levels[static_cast<std::size_t>(level)].indexCount / 3; }
};

struct LodOptions {
    double levelRatio = 0.5;         // each level aims at this share of the previous level's triangles
    int maxLevels = 8;               // levels including level 0, >= 1
    double maxRelativeError = 0.25;  // no level whose error exceeds this share of the mesh's extent
    double minReduction = 0.85;      // a level must keep at most this share of the previous level's
                                     // triangles, else the chain stops (nothing more to gain)
};

// The level chain of one mesh. Meshes with fewer than 64 triangles, or that do not simplify,
// get level 0 only. Every level's triangles are ordered for the vertex cache.
MeshLod buildMeshLod(const Mesh& mesh, const LodOptions& options = {});

// buildMeshLod for every mesh of the scene, in mesh order.
std::vector<MeshLod> buildSceneLods(const Scene& scene, const LodOptions& options = {});

// One object a frame draws, as the level choice sees it.
struct LodCandidate {
    const MeshLod* lod = nullptr;  // its mesh's levels
    // The most pixels one model unit of error can cover in any view the object is drawn in
    // (see display/pixel_scale.h); +infinity when the eye is inside its bounds (level 0 only).
    double pixelsPerUnit = 0.0;
    int views = 1;  // views that draw it: each submits the level's triangles
};

struct LodChoice {
    std::vector<int> level;     // per candidate
    double tolerancePx = 0.0;   // the pixel tolerance every level meets
    double maxErrorPx = 0.0;    // the largest error of a chosen level, pixels (<= tolerancePx)
    std::size_t triangles = 0;  // sum over candidates of views * the chosen level's triangles
    bool overBudget = false;    // even the coarsest levels exceed the budget
};

// Chooses for every candidate the coarsest level whose error in pixels (error *
// pixelsPerUnit) is at most the tolerance. The tolerance is `tolerancePx`, raised to the
// smallest value at which the frame's triangles fit `triangleBudget` (0: no budget): the
// smallest worst-case error in pixels that meets the budget, the same for every object. It
// never rises above `maxTolerancePx` (>= tolerancePx): a budget that needs more is not met
// (overBudget) and the levels within maxTolerancePx are drawn.
LodChoice chooseLevels(const std::vector<LodCandidate>& candidates, double tolerancePx, std::size_t triangleBudget = 0,
                       double maxTolerancePx = std::numeric_limits<double>::infinity());

}  // namespace cavewall::scenes
