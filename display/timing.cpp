#include "display/timing.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace cavewall::display {

double percentile(std::span<const double> samples, double p) {
    assert(p >= 0.0 && p <= 1.0);
    if (samples.empty()) return 0.0;
    const double n = static_cast<double>(samples.size());
    const auto rank = static_cast<std::size_t>(std::clamp(std::ceil(p * n), 1.0, n));
    std::vector<double> sorted(samples.begin(), samples.end());
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(rank - 1), sorted.end());
    return sorted[rank - 1];
}

double median(std::span<const double> samples) { return percentile(samples, 0.5); }

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cavewall::display
