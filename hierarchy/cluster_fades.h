#pragma once
// Cross-faded transitions between a cluster's representations (Maciel & Shirley (1995),
// section 4.6), GL-free.
//
// The selection (cluster_frame.h) switches a cluster from its box to its children (refine), from
// its children back to its box (coarsen), or from one box to the other (textured <-> average) in
// one frame, which pops. ClusterFades spreads each switch over `frames` frames by drawing both
// sides, the box over what it replaces, with a weight that ramps:
// - refine: the children are drawn as selected; the old box is drawn over them with weight
//   1 - k/frames (k = 1, 2, ... frames since the switch), fading out;
// - coarsen: the box is drawn with weight k/frames over what the frame before the switch drew
//   below it (its objects and boxes, kept as they were: "ghosts"), fading in;
// - swap: the old box is drawn opaque, the new one over it with weight k/frames.
// A box encloses everything below it, so its faces lie in front of its children's and a
// weighted box drawn after them blends over them: ClusterBoxDraw::weight scales the box's
// premultiplied colour and coverage (the wall pass's blend), and every weighted box is drawn
// after every box below it. A switch that is undone before its fade ends ends the fade (the
// frame draws the selection as it is); a new switch of the same cluster replaces its fade.
//
// The fades cost frame time: plan.predictedMs grows by what the extra items cost (objects at
// full detail, boxes at their measured cost), so the frame-time controller sees it.

#include "hierarchy/cluster_frame.h"

#include <optional>
#include <vector>

namespace cavewall::hierarchy {

class ClusterFades {
public:
    // frames <= 1: no fades (apply leaves the plan as selected).
    explicit ClusterFades(int frames = 8);
    int frames() const { return _frames; }

    // Adds this frame's fading items to `plan` (planClusterFrame's result for `model`, seen from
    // `eyeWorld`) and remembers the selection for the next frame. Call once per frame, in order.
    void apply(const ClusterModel& model, glm::dvec3 eyeWorld, ClusterFramePlan& plan);

    int active() const { return static_cast<int>(_fades.size()); }

private:
    enum class Kind { Refine, Coarsen, Swap };
    struct Fade {
        Kind kind = Kind::Refine;
        int node = -1;
        ClusterRep rep = ClusterRep::Textured;     // refine: the old box; coarsen: the new one
        ClusterRep oldRep = ClusterRep::Textured;  // swap: the old box
        int age = 0;                               // frames since the switch, 1 in its frame
        std::vector<int> ghostObjects;             // coarsen: drawn below the node before
        std::vector<ClusterBoxDraw> ghostBoxes;
    };
    // One frame's selection per node: the rep of the box drawn (-1: none) and whether anything
    // below the node is drawn.
    struct Selection {
        std::vector<int> box;
        std::vector<char> refined;
    };

    // The steps of apply, in its order.
    void restart(const ClusterTree& tree);
    Selection selectionOf(const ClusterFramePlan& plan) const;
    std::vector<Fade> continuedFades(const Selection& now);
    std::optional<Fade> switchOf(const ClusterTree& tree, const Selection& now, std::size_t node) const;
    void addSwitches(const ClusterTree& tree, const Selection& now, std::vector<Fade>& fades) const;
    double addFadeItems(const ClusterModel& model, const std::vector<Fade>& fades, ClusterFramePlan& plan) const;
    void orderBoxes(const ClusterTree& tree, glm::dvec3 eyeWorld, std::vector<ClusterBoxDraw>& boxes) const;
    bool below(int m, int n) const;  // node m strictly below node n

    int _frames;
    std::vector<int> _parent;                // per node, -1 for the root
    std::vector<int> _prevBox;               // per node: rep drawn last frame, -1 none
    std::vector<char> _prevRefined;          // per node: something below it drawn
    std::vector<int> _prevObjects;           // last frame's selected objects
    std::vector<ClusterBoxDraw> _prevBoxes;  // last frame's selected boxes
    std::vector<Fade> _fades;
    bool _first = true;
};

}  // namespace cavewall::hierarchy
