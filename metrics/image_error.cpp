#include "metrics/image_error.h"

#include "metrics/image_filter.h"

#include <algorithm>
#include <cmath>

namespace cavewall::metrics {

double psnrFromMse(double mse) { return mse > 0.0 ? -10.0 * std::log10(mse) : std::numeric_limits<double>::infinity(); }

SquaredError squaredError(const scenes::Image& test, const scenes::Image& reference) {
    expectComparableImages("squared error", test, reference);
    // Integer sums are exact; one conversion at the end.
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < test.rgba.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = test.rgba[i + c] - reference.rgba[i + c];
            sum += static_cast<std::uint64_t>(d * d);
        }
    return {static_cast<double>(sum) / (255.0 * 255.0), test.rgba.size() / 4 * 3};
}

void PooledError::addFrame(std::int64_t frameId, const SquaredError& error) {
    _total += error;
    _frames.push_back({frameId, error.psnrDb()});
}

PooledErrorSummary PooledError::summary() const {
    PooledErrorSummary s;
    s.frames = _frames.size();
    s.mse = _total.mse();
    s.psnrDb = _total.psnrDb();
    if (_frames.empty()) return s;
    std::vector<double> psnr;
    double cappedSum = 0.0;
    for (const Frame& f : _frames) {
        if (f.psnrDb < s.worstFramePsnrDb || s.worstFrame < 0) {
            s.worstFramePsnrDb = f.psnrDb;
            s.worstFrame = f.id;
        }
        psnr.push_back(f.psnrDb);
        cappedSum += std::min(f.psnrDb, kQuantisationPsnrDb);
    }
    s.p5FramePsnrDb = percentile(std::move(psnr), 0.05);
    s.cappedMeanPsnrDb = cappedSum / static_cast<double>(_frames.size());
    return s;
}

}  // namespace cavewall::metrics
