#pragma once
// The frame-time controller of Maciel & Shirley's (1995) clusters (hierarchy/cluster_budget.h),
// applied to the walkthrough's frames, one definition for `cavewall run --hierarchy` and the
// bench's clusters modes: before a frame, the selection's budget for FrameInput; after it, the
// controller's prediction, floor and target written into FrameResult (frames.csv,
// bench_frames.csv), then the controller updated with the frame. Here rather than in hierarchy/,
// which knows nothing of the walkthrough's frames.

#include "hierarchy/cluster_budget.h"
#include "walkthrough/frame_types.h"

namespace cavewall::walkthrough {

// FrameInput::clusterBudgetMs for the next frame: the controller's selection budget, at least
// 1e-9 ms (0 would mean "no budget given"), so that a budget of 0 draws the cheapest selection.
double clusterBudgetFor(const hierarchy::ClusterBudget& budget);

// After a frame of the walkthrough with clusters: fills r.clusterTargetMs,
// r.clusterPredictedFrameMs and r.clusterFloorMs from what the controller knew before the
// frame (0 before its first frame), then updates it with r.frameMs, r.clusterPredictedMs and
// r.clusterSelectedMs.
void controlClusters(hierarchy::ClusterBudget& budget, FrameResult& r);

}  // namespace cavewall::walkthrough
