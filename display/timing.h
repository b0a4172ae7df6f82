#pragma once
// Frame-time measurement and statistics, one definition for every caller (the run's and the
// demo's summaries, the bench's percentiles, the frame-time budget's median cost).
//
// Percentiles are nearest-rank: the p-th percentile of n samples is the ceil(p n)-th smallest
// (rank clamped to [1, n]). The result is always one of the samples, never an interpolation
// between two, so a percentile of frame times is a frame that happened; the median of an even
// count is the lower of the two middle samples.

#include <chrono>
#include <span>

namespace cavewall::display {

// The nearest-rank `p`-th percentile of `samples` (p in [0, 1]; p = 0 gives the smallest);
// 0 for no samples. Samples need not be sorted.
double percentile(std::span<const double> samples, double p);

// percentile(samples, 0.5).
double median(std::span<const double> samples);

// Milliseconds of the steady clock since `start`.
double msSince(std::chrono::steady_clock::time_point start);

}  // namespace cavewall::display
