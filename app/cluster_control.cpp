#include "app/cluster_control.h"

#include <algorithm>

namespace cavewall::app {

double clusterBudgetFor(const render::ClusterBudget& budget) { return std::max(1e-9, budget.selectionBudgetMs()); }

void controlClusters(render::ClusterBudget& budget, walkthrough::FrameResult& r) {
    r.clusterTargetMs = budget.targetMs();
    r.clusterPredictedFrameMs = budget.predictedFrameMs(r.clusterPredictedMs);
    r.clusterFloorMs = budget.floorMs(r.clusterCheapestMs);
    budget.update(r.frameMs, r.clusterPredictedMs, r.clusterSelectedMs);
}

}  // namespace cavewall::app
