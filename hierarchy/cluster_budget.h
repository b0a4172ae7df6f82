#pragma once
// The frame-time controller of Maciel & Shirley's (1995) clusters: how many predicted
// milliseconds the next frame's selection (cluster_tree.h, cluster_frame.h) may spend so that
// frames take at most a target time, in a stated share of them, whatever the fixed part of a
// frame costs.
//
// Model: a frame takes m = P + e ms, P the predicted cost of what it drew (the selection and
// its cross-fades, costed at the display's own resolution: hierarchy/gl/cluster_costs.h) and e the
// rest: the fixed part (clearing, structure, every view's set-up), the prediction's error and
// the machine's noise. The controller keeps e of the last `window` frames. The budget that
// makes the next frame take at most the target T in a share `quantile` of frames like those is
// T - q(e), q the nearest-rank quantile of the window (display/timing.h); the budget moves
// towards it by `gain` of the difference per frame. With the costs right (m = F + P + noise)
// any gain converges; a prediction off by a factor k (m = F + k P) still converges when
// k < 2 / gain, to the budget whose frames take T. A frame whose selection could not use its
// budget (refinement is discrete) costs only what it drew, so its e is as good as any other's
// and the budget neither shrinks nor grows from it: no credit, no starvation.
//
// Cross-fades (cluster_fades.h) last several frames and are costed after the selection, so the
// selection's budget is the controlled budget minus what the last frame's fades added.
//
// The floor: the selection at a budget of 0 (ClusterFramePlan::cheapestMs) plus q(e) is the
// shortest frame the hierarchy gives; a target below it is infeasible and is reported so
// (floorMs), not silently missed.
//
// Pure and deterministic. Times in milliseconds.

#include <vector>

namespace cavewall::hierarchy {

class ClusterBudget {
public:
    // targetMs > 0; quantile in (0, 1]; window >= 1; 0 < gain <= 1. Throws nothing (asserts).
    explicit ClusterBudget(double targetMs, double quantile = 0.9, int window = 20, double gain = 0.5);

    double targetMs() const { return _target; }
    // The controlled budget of predicted ms for everything the next frame draws (selection and
    // fades); 0 before the first update, so the first frame draws the cheapest selection.
    double budgetMs() const { return _budget; }
    // budgetMs minus the last frame's fade cost, at least 0: what the selection may spend.
    double selectionBudgetMs() const;
    // The time a frame of predicted cost `predictedMs` should take: predictedMs plus the
    // window's median e. 0 before the first update.
    double predictedFrameMs(double predictedMs) const;
    // The shortest frame the hierarchy can give now: `cheapestMs` plus the window's q(e)
    // (0 before the first update); above targetMs the target is infeasible.
    double floorMs(double cheapestMs) const;
    bool feasible(double cheapestMs) const { return floorMs(cheapestMs) <= _target; }

    // After a frame: its wall-clock time, its predicted cost (selection and fades) and the
    // selection's part of it. Non-finite or non-positive frame times are ignored.
    void update(double frameMs, double predictedMs, double selectedMs);

private:
    double residualQuantile(double q) const;

    double _target, _quantile, _gain;
    int _window;
    std::vector<double> _residuals;  // e of the last frames, a ring
    int _next = 0;
    double _budget = 0.0, _fadeMs = 0.0;
};

}  // namespace cavewall::hierarchy
