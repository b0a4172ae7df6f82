#include "hierarchy/cluster_budget.h"

#include "display/timing.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace cavewall::hierarchy {

ClusterBudget::ClusterBudget(double targetMs, double quantile, int window, double gain)
    : _target(targetMs), _quantile(quantile), _gain(gain), _window(window) {
    assert(targetMs > 0.0 && quantile > 0.0 && quantile <= 1.0 && window >= 1 && gain > 0.0 && gain <= 1.0);
}

double ClusterBudget::selectionBudgetMs() const { return std::max(0.0, _budget - _fadeMs); }

double ClusterBudget::residualQuantile(double q) const {
    return _residuals.empty() ? 0.0 : display::percentile(_residuals, q);
}

double ClusterBudget::predictedFrameMs(double predictedMs) const {
    return _residuals.empty() ? 0.0 : predictedMs + residualQuantile(0.5);
}

double ClusterBudget::floorMs(double cheapestMs) const {
    return _residuals.empty() ? 0.0 : cheapestMs + residualQuantile(_quantile);
}

void ClusterBudget::update(double frameMs, double predictedMs, double selectedMs) {
    if (!(frameMs > 0.0) || !std::isfinite(frameMs) || !std::isfinite(predictedMs)) return;
    const double e = frameMs - std::max(0.0, predictedMs);
    if (static_cast<int>(_residuals.size()) < _window)
        _residuals.push_back(e);
    else
        _residuals[static_cast<std::size_t>(_next)] = e;
    _next = (_next + 1) % _window;
    const double wanted = std::max(0.0, _target - residualQuantile(_quantile));
    _budget = std::max(0.0, _budget + _gain * (wanted - _budget));
    _fadeMs = std::isfinite(selectedMs) ? std::max(0.0, predictedMs - selectedMs) : 0.0;
}

}  // namespace cavewall::hierarchy
