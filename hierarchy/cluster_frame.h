#pragma once
// One frame of Maciel & Shirley's (1995) cluster walkthrough, GL-free: from the hierarchy
// (cluster_tree.h), the measured cost and accuracy of every representation and the frame's
// views, the NodeFrame of every node (benefit, visibility, representations) and the selection
// under the frame's budget, returned as plain data the GL executor draws: objects (at full
// detail, or at the level of detail the renderer picks for them) and cluster boxes (textured or
// average colour).
//
// Frames: world (bounds, eye) and the cave frame of the views, placed by worldFromCave.
// Costs in milliseconds.

#include "display/display.h"
#include "hierarchy/cluster_impostor.h"
#include "hierarchy/cluster_tree.h"

#include <array>
#include <cstddef>
#include <vector>

namespace cavewall::hierarchy {

// Representation ids (Representation::id) of a cluster; a leaf has only Full.
enum class ClusterRep { Full = 0, Textured = 1, Average = 2 };

// Drawing costs measured on this machine and renderer at the display's resolution
// (hierarchy/gl/cluster_costs.h). A box costs its fixed part plus its fill: the views' shares it
// covers (viewShare, summed over the frame's views) times the cost of filling one whole view.
struct ClusterCosts {
    double msPerTriangle = 1e-5;  // full-detail geometry
    double msPerObject = 1e-3;    // fixed part of one object's draw
    double texturedBoxMs = 1e-2;  // one textured box (its front faces), fixed part
    double averageBoxMs = 1e-2;   // one average-colour box, fixed part
    double texturedViewMs = 0.0;  // a textured box's fill per whole view it covers
    double averageViewMs = 0.0;   // an average box's fill per whole view it covers
    bool operator==(const ClusterCosts&) const = default;
};

// The share of a view, in [0, 1], that `world` bounds cover: the rectangle around their
// corners' projections, clipped to the view (clipFromWorld: the view's clip from world), over
// the view's area; 1 when a corner lies at or behind the eye's plane and the bounds may meet
// the view (they may cover all of it), 0 outside. An upper bound of the pixels a box's faces
// fill, the same in the measurement and the prediction.
double viewShare(const scenes::Bounds& world, const glm::dmat4& clipFromWorld);

// A box's predicted cost: its fixed part plus its fill over views covering `viewShares` in all.
double boxCostMs(const ClusterCosts& costs, ClusterRep rep, double viewShares);

// A box's fixed part and fill from two draws: `boxesA` boxes covering `sharesA` views in all in
// `msA`, and one box covering `sharesB` views in `msB`. Without a non-negative solution (the
// two draws do not tell them apart, or noise), the fill is 0 and the fixed part msA / boxesA.
// The fixed part is at least 1e-6 ms.
struct BoxCost {
    double fixedMs = 0.0, viewMs = 0.0;
};
BoxCost solveBoxCost(double boxesA, double sharesA, double msA, double sharesB, double msB);

// Accuracy of a cluster's impostors from each accuracy direction (cluster_impostor.h), [0, 1],
// measured against full detail.
struct ClusterAccuracy {
    std::array<double, kAccuracyDirections> textured{}, average{};
    bool operator==(const ClusterAccuracy&) const = default;
};

// Everything about the model the frames need besides the tree: per object its triangles, per
// node (tree index) the accuracy of its impostors (leaves: unused) and whether it has them.
struct ClusterModel {
    ClusterTree tree;
    std::vector<std::size_t> objectTriangles;  // per object
    std::vector<ClusterAccuracy> accuracy;     // per node
    std::vector<bool> hasImpostors;            // per node: textures and averages were made
    ClusterCosts costs;
};

struct ClusterBoxDraw {
    int node = -1;
    ClusterRep rep = ClusterRep::Textured;  // Textured or Average
    float weight = 1.0f;                    // (0, 1]: < 1 while cross-fading (cluster_fades.h)
};

struct ClusterFramePlan {
    std::vector<int> objects;           // leaves drawn: object indices, ascending
    std::vector<ClusterBoxDraw> boxes;  // back to front from the eye
    int textured = 0, average = 0;      // boxes of each kind the selection drew
    int fades = 0, ghostObjects = 0;    // cross-fades under way, objects they kept
    double predictedMs = 0.0;           // the selection's cost, and the fades' extra
    double selectedMs = 0.0;            // the selection's cost alone (<= budgetMs, or
                                        // cheapestMs when that is above it)
    double cheapestMs = 0.0;            // the selection at a budget of 0 (the root's box):
                                        // what a frame with nothing to spend draws
                                        // (cluster_budget.h's floor)
    double budgetMs = 0.0;
    std::vector<std::array<double, 2>> boxMs;  // per node: this frame's textured and average
                                               // box cost (fill included), for the fades
};

// The frame's NodeFrame per node: a leaf's benefit is its bounding sphere's solid-angle share
// (r / d)^2 seen from `eyeWorld` (1 when the eye is inside), visible when its bounds meet some
// view's frustum (corners against the side and near planes; `views` in the cave frame). A
// leaf has one representation (Full: msPerObject + triangles x msPerTriangle, accuracy 1); a
// cluster with impostors has Textured and Average (boxCostMs over its views' shares; accuracy from the nearest
// accuracy direction, 0 when the eye is inside its impostor box) and no others (it is drawn as
// a box or refined).
std::vector<NodeFrame> clusterNodeFrames(const ClusterModel& model, const std::vector<display::ScreenView>& views,
                                         const glm::dmat4& worldFromCave, glm::dvec3 eyeWorld);

// The predicted cost of every object at full detail (all leaves' Full representation): the most
// any selection can cost, so a budget above it buys nothing.
double fullDetailCostMs(const ClusterModel& model);

// clusterNodeFrames, then selectClusters under `budgetMs`, as drawable data.
ClusterFramePlan planClusterFrame(const ClusterModel& model, const std::vector<display::ScreenView>& views,
                                  const glm::dmat4& worldFromCave, glm::dvec3 eyeWorld, double budgetMs,
                                  ClusterCoherence* coherence);

}  // namespace cavewall::hierarchy
