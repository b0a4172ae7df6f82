#include "display/frame_budget.h"

#include "display/timing.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace cavewall::display {

FrameTimeBudget::FrameTimeBudget(double targetMs, double gain) : _target(targetMs), _gain(gain) {
    assert(targetMs > 0.0 && gain > 0.0 && gain <= 1.0);
}

void FrameTimeBudget::update(double frameMs, std::size_t triangles) {
    if (!(frameMs > 0.0) || !std::isfinite(frameMs) || triangles == 0) return;
    const double g = static_cast<double>(triangles);
    // Over its budget (1 % slack for what the budget does not cap): the target is infeasible here.
    const bool infeasible = _budget > 0 && g > 1.01 * static_cast<double>(_budget);
    _floor = infeasible ? std::max(_floor * kFloorDecay, g) : _floor * kFloorDecay;
    _costs[_next] = frameMs / g;
    _next = (_next + 1) % kWindow;
    _count = std::min(_count + 1, kWindow);
    const double cost = median(std::span<const double>(_costs, static_cast<std::size_t>(_count)));
    const double next = std::pow(g, 1.0 - _gain) * std::pow(_target / cost, _gain);
    const double bounded = std::clamp(next, std::max(1.0, 0.5 * g), std::min(2.0 * g, 1e15));
    _budget = static_cast<std::size_t>(std::max(bounded, std::min(_floor, 1e15)));
}

}  // namespace cavewall::display
