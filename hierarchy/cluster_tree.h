#pragma once
// Maciel & Shirley (1995): the model hierarchy of textured clusters and the per-frame selection
// of one representation per root-to-leaf path under a frame-time budget. GL-free: the hierarchy
// is built from object bounds, the selection from numbers the caller measures (cost per
// representation on this machine, accuracy per representation and view direction) and from the
// frame's benefit and visibility per object. Drawing the chosen representations (objects at a
// level of detail, textured or average-colour boxes) is the renderer's.
//
// Units: bounds in the world (metres); costs in milliseconds.

#include "scenes/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace cavewall::hierarchy {

// One node of the model hierarchy. Leaves hold one object; clusters hold two or more children
// and stand for every object below them.
struct ClusterNode {
    scenes::Bounds bounds;      // of the objects below, world
    std::vector<int> children;  // node indices; empty for a leaf
    std::vector<int> objects;   // the objects below, ascending (a leaf: its one object)
    int object = -1;            // a leaf's object index; -1 for a cluster
    int level = 0;              // 0: leaves; clusters: the grid level that made them (1 = finest)
    bool leaf() const { return children.empty(); }
};

struct ClusterTree {
    std::vector<ClusterNode> nodes;  // leaves first (node i = object i), clusters after their children
    int root = -1;                   // -1 only for a model without objects
    glm::ivec3 divisions{1};         // the finest grid's cells per axis
};

// Builds the hierarchy bottom up, as Maciel & Shirley's section 4.4 does: the leaves are the
// objects (`objectBounds[i]` in the world; empty bounds are left out of every cluster); the
// finest grid splits the model's bounds into `divisions` cells per axis (each >= 1), and every
// coarser level merges 2 x 2 x 2 cells until one cell covers the model. At each level, a cell
// whose bounds entirely contain two or more entries of the current child list becomes a cluster
// of them (those entries leave the list, the cluster joins it); a cell holding one entry or
// none makes nothing, so objects on cell borders are clustered higher up. The top level's
// single cell takes whatever is left, so every non-empty object ends under the root.
// Deterministic: the same input gives the same tree.
ClusterTree buildClusterTree(const std::vector<scenes::Bounds>& objectBounds, glm::ivec3 divisions);

// One drawable representation of a node (Maciel & Shirley 1995, section 4.1): its measured cost
// and its accuracy in [0, 1] (1: the full-detail image) from the current view.
struct Representation {
    int id = 0;             // the caller's (e.g. level of detail, or textured/average box)
    double costMs = 0.0;    // >= 0
    double accuracy = 0.0;  // [0, 1]
};

// What the caller knows about node n in this frame.
struct NodeFrame {
    double benefit = 0.0;                         // leaves: e.g. projected size times intrinsic factors; >= 0
                                                  // (clusters: ignored, their benefit is the largest below)
    bool visible = false;                         // leaves: in some view's frustum (clusters: any child visible)
    std::vector<Representation> representations;  // every node: at least one for a visible node
};

// The frame's choice: the node and representation of every drawn item, in the order chosen.
struct ClusterChoice {
    int node = -1;
    int representation = 0;  // index into NodeFrame::representations
};

struct ClusterSelection {
    std::vector<ClusterChoice> drawn;
    double costMs = 0.0;           // sum of the drawn representations' costs
    int clusters = 0, leaves = 0;  // drawn items of each kind
};

// Temporal coherence (Maciel & Shirley 1995, section 4.6): a cluster is replaced by its
// children only after the traversal has wanted to in more than `threshold` consecutive frames;
// refined in one frame, it may stay refined in the next without waiting again. Going back from
// children to the cluster is never delayed (as in the paper: the frame time is spent by then).
// One per walkthrough, kept across frames; selectClusters calls beginFrame.
class ClusterCoherence {
public:
    explicit ClusterCoherence(int threshold = 3) : _threshold(threshold) {}
    void beginFrame() { ++_frame; }
    // Whether node `n` may be refined this frame, given that the traversal wants to.
    bool allowRefine(int n);
    int threshold() const { return _threshold; }

private:
    int _threshold;
    long _frame = 0;
    std::vector<int> _counter;   // per node: consecutive frames refinement was wanted,
    std::vector<long> _wanted;   // ending in this frame
    std::vector<long> _refined;  // per node: the last frame it was refined in
};

// The two passes of Maciel & Shirley 1995, section 4.5. Pass 1 (depth first): each node's
// benefit is its own (a leaf) or its children's largest, it is visible when any child is, its
// initial representation is the one with the highest accuracy per cost, and the children's cost
// is the sum of their initial representations'. Pass 2 (best first, from the root, visiting
// nodes in decreasing benefit): invisible nodes are dropped with their cost; a cluster is
// replaced by its visible children when the frame's total minus its own cost plus theirs stays
// within `budgetMs` (and `coherence`, when given, allows it; a cluster whose initial
// representation has accuracy 0 or that has none is refined without asking it, and also over
// the budget when its visible children cost no more than it does), else drawn; a leaf moves up
// to the most accurate representation whose extra cost still fits. Throws nothing; nodes
// without a representation are drawn as nothing. `frame` has one entry per node of `tree`.
ClusterSelection selectClusters(const ClusterTree& tree, const std::vector<NodeFrame>& frame, double budgetMs,
                                ClusterCoherence* coherence = nullptr);

}  // namespace cavewall::hierarchy
