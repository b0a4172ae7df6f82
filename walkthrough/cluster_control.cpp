#include "walkthrough/cluster_control.h"

#include <algorithm>

namespace cavewall::walkthrough {

double clusterBudgetFor(const hierarchy::ClusterBudget& budget) { return std::max(1e-9, budget.selectionBudgetMs()); }

void controlClusters(hierarchy::ClusterBudget& budget, FrameResult& r) {
    r.clusterTargetMs = budget.targetMs();
    r.clusterPredictedFrameMs = budget.predictedFrameMs(r.clusterPredictedMs);
    r.clusterFloorMs = budget.floorMs(r.clusterCheapestMs);
    budget.update(r.frameMs, r.clusterPredictedMs, r.clusterSelectedMs);
}

}  // namespace cavewall::walkthrough
