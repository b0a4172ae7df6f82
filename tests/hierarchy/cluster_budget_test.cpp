// The clusters' frame-time controller (hierarchy/cluster_budget.h), driven by a stated model of
// frame times: m = F + k P (times a noise factor), F the fixed part, P the predicted cost drawn.
#include "hierarchy/cluster_budget.h"

#include "display/timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace cavewall::hierarchy {
namespace {

struct Walk {
    std::vector<double> frameMs, budgetMs;
};

// `frames` frames: each draws `drawn(budget)` predicted ms and takes (F + k drawn) x noise(i).
Walk drive(
    ClusterBudget& c, int frames, double fixedMs, double k, const std::function<double(int)>& noise,
    const std::function<double(double)>& drawn = [](double b) { return b; }) {
    Walk w;
    for (int i = 0; i < frames; ++i) {
        const double p = drawn(c.selectionBudgetMs());
        const double m = (fixedMs + k * p) * noise(i);
        w.frameMs.push_back(m);
        w.budgetMs.push_back(c.selectionBudgetMs());
        c.update(m, p, p);
    }
    return w;
}

double none(int) { return 1.0; }

// Multiplicative noise, log-uniform in [1 / (1 + s), 1 + s], from a fixed seed.
std::function<double(int)> noisy(double s) {
    auto rng = std::make_shared<std::mt19937>(17);
    return [rng, s](int) {
        const double u = static_cast<double>((*rng)()) / static_cast<double>(std::mt19937::max());
        return std::exp((2.0 * u - 1.0) * std::log1p(s));
    };
}

std::vector<double> after(const std::vector<double>& v, std::size_t warmUp) {
    return {v.begin() + static_cast<long>(warmUp), v.end()};
}

TEST(ClusterBudget, StartsAtTheCheapestSelectionAndPredictsNothingBeforeTheFirstFrame) {
    const ClusterBudget c(50.0);
    EXPECT_EQ(c.budgetMs(), 0.0);
    EXPECT_EQ(c.selectionBudgetMs(), 0.0);
    EXPECT_EQ(c.predictedFrameMs(10.0), 0.0);
    EXPECT_EQ(c.floorMs(1.0), 0.0);
    EXPECT_EQ(c.targetMs(), 50.0);
}

TEST(ClusterBudget, RightCostsConvergeOnTheTargetFromBelow) {
    // F = 20 ms, T = 50 ms: the budget that fills the frame is 30 ms. Every frame's rest is
    // exactly F, so the wanted budget is 30 from the first frame on, and with gain 0.5 the
    // budget is 30 (1 - 0.5^n) after n frames: never above, within 1e-6 after 25.
    ClusterBudget c(50.0);
    const Walk w = drive(c, 40, 20.0, 1.0, none);
    for (std::size_t i = 0; i < w.frameMs.size(); ++i) EXPECT_LE(w.frameMs[i], 50.0 + 1e-9) << i;
    EXPECT_NEAR(c.budgetMs(), 30.0, 1e-6);
    EXPECT_NEAR(w.frameMs.back(), 50.0, 1e-6);
    // The prediction: the drawn cost plus the median rest (20 ms); the floor: the cheapest
    // selection plus the rest's 90th percentile.
    EXPECT_NEAR(c.predictedFrameMs(30.0), 50.0, 1e-9);
    EXPECT_NEAR(c.floorMs(4.0), 24.0, 1e-9);
    EXPECT_TRUE(c.feasible(4.0));
}

TEST(ClusterBudget, CostsOffByAFactorBelowFourStillConverge) {
    // m = F + k P: the fixed point is P = (T - F) / k (gain 0.5: each step multiplies the error
    // by 1 - 0.5 k, so k < 4 converges; the window's quantile lags a moving rest, so it takes a
    // few hundred frames to come within 0.1 %).
    for (double k : {0.5, 2.0, 3.0}) {
        SCOPED_TRACE(k);
        ClusterBudget c(50.0);
        const Walk w = drive(c, 300, 20.0, k, none);
        EXPECT_NEAR(c.budgetMs(), 30.0 / k, 1e-3 * 30.0 / k);
        EXPECT_NEAR(w.frameMs.back(), 50.0, 0.05);
    }
}

TEST(ClusterBudget, NoisyFramesHoldTheP95NearTheTarget) {
    // Frame times scattered by up to 15 % either way around F + P: the controller aims the
    // 90th percentile at the target, so after a warm-up of 30 frames the p95 stays within 1.1x
    // the target and the median below it.
    for (double k : {1.0, 2.0}) {
        SCOPED_TRACE(k);
        ClusterBudget c(50.0);
        const Walk w = drive(c, 400, 20.0, k, noisy(0.15));
        const std::vector<double> warm = after(w.frameMs, 30);
        EXPECT_LE(display::percentile(warm, 0.95), 1.1 * 50.0);
        EXPECT_LT(display::median(warm), 50.0);
        EXPECT_GT(display::median(warm), 0.75 * 50.0);  // and does not starve
    }
}

TEST(ClusterBudget, ABudgetTheSelectionCannotUseNeitherShrinksNorGrows) {
    // Refinement is discrete: the selection draws the largest multiple of 7 ms within its
    // budget. The rest (m - P) is still F, so the budget stays at T - F = 30 ms (no credit
    // builds up, and it does not fall towards the root's cost either).
    ClusterBudget c(50.0);
    const Walk w = drive(c, 60, 20.0, 1.0, none, [](double b) { return 7.0 * std::floor(b / 7.0); });
    EXPECT_NEAR(c.budgetMs(), 30.0, 1e-6);
    EXPECT_NEAR(w.frameMs.back(), 20.0 + 28.0, 1e-6);
}

TEST(ClusterBudget, ATargetBelowTheFloorIsInfeasibleAndDrawsTheCheapest) {
    // F = 24 ms (the cheapest selection's frame on the plant): 16.7 ms cannot be held.
    ClusterBudget c(1000.0 / 60.0);
    drive(c, 30, 24.0, 1.0, none);
    EXPECT_EQ(c.budgetMs(), 0.0);
    EXPECT_EQ(c.selectionBudgetMs(), 0.0);
    EXPECT_NEAR(c.floorMs(0.5), 24.5, 1e-9);
    EXPECT_FALSE(c.feasible(0.5));
}

TEST(ClusterBudget, ASingleStallMovesNothing) {
    // One frame 10x too slow is the window's largest rest; its 90th percentile (nearest rank,
    // the 18th of 20) is another frame's, so the budget does not move.
    ClusterBudget c(50.0);
    drive(c, 40, 20.0, 1.0, none);
    const double before = c.budgetMs();
    c.update(500.0, before, before);
    EXPECT_NEAR(c.budgetMs(), before, 1e-9);
}

TEST(ClusterBudget, FadesAreReservedFromTheNextSelection) {
    ClusterBudget c(50.0);
    drive(c, 40, 20.0, 1.0, none);
    // A frame whose fades added 4 ms to its selection of 26 ms: the next selection gets the
    // controlled budget minus 4 ms.
    c.update(50.0, 30.0, 26.0);
    EXPECT_NEAR(c.selectionBudgetMs(), c.budgetMs() - 4.0, 1e-9);
    c.update(50.0, 30.0, 30.0);  // no fades: all of it
    EXPECT_NEAR(c.selectionBudgetMs(), c.budgetMs(), 1e-9);
}

TEST(ClusterBudget, BadTimesAreIgnored) {
    ClusterBudget c(50.0);
    drive(c, 10, 20.0, 1.0, none);
    const double before = c.budgetMs();
    for (double bad : {0.0, -3.0, std::nan(""), std::numeric_limits<double>::infinity()}) c.update(bad, 1.0, 1.0);
    c.update(40.0, std::nan(""), 1.0);
    EXPECT_EQ(c.budgetMs(), before);
}

}  // namespace
}  // namespace cavewall::hierarchy
