#include "metrics/popping.h"

#include "metrics/image_filter.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace cavewall::metrics {

namespace {

struct TileSums {
    std::int64_t errorChange = 0, pictureChange = 0;  // sums of squared byte differences
    std::int64_t samples = 0;
};

}  // namespace

double framePairPopping(const scenes::Image& previousTest, const scenes::Image& previousReference,
                        const scenes::Image& test, const scenes::Image& reference, const PoppingOptions& options) {
    assert(options.tileSize >= 1 && options.floor > 0.0);
    expectComparableImages("popping", test, reference);
    expectComparableImages("popping", previousTest, test);
    expectComparableImages("popping", previousReference, reference);
    const int ts = options.tileSize, tilesX = (test.width + ts - 1) / ts, tilesY = (test.height + ts - 1) / ts;
    std::vector<TileSums> tiles(static_cast<std::size_t>(tilesX) * tilesY);
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
            TileSums& tile = tiles[static_cast<std::size_t>(y / ts) * tilesX + x / ts];
            const std::size_t i = (static_cast<std::size_t>(y) * test.width + x) * 4;
            for (std::size_t c = i; c < i + 3; ++c) {
                // (T - R) - (T' - R'), R - R', in bytes: exact in integers.
                const int errorChange =
                    (test.rgba[c] - reference.rgba[c]) - (previousTest.rgba[c] - previousReference.rgba[c]);
                const int pictureChange = reference.rgba[c] - previousReference.rgba[c];
                tile.errorChange += errorChange * errorChange;
                tile.pictureChange += pictureChange * pictureChange;
            }
            tile.samples += 3;
        }
    double worst = 0.0;
    for (const TileSums& t : tiles) {
        const auto n = static_cast<double>(t.samples);
        const double dE = std::sqrt(static_cast<double>(t.errorChange) / n) / 255.0;
        const double dR = std::sqrt(static_cast<double>(t.pictureChange) / n) / 255.0;
        worst = std::max(worst, dE / std::max(dR, options.floor));
    }
    return worst;
}

PoppingMeter::PoppingMeter(PoppingOptions options) : _options(options) {}

std::optional<double> PoppingMeter::addFrame(std::int64_t frameId, const scenes::Image& test,
                                             const scenes::Image& reference) {
    expectComparableImages("popping", test, reference);
    std::optional<double> popping;
    if (_previousTest) {
        popping = framePairPopping(*_previousTest, *_previousReference, test, reference, _options);
        if (*popping > _summary.peak || _summary.peakFrame < 0) {
            _summary.peak = *popping;
            _summary.peakFrame = frameId;
        }
        _sumSquares += *popping * *popping;
        ++_summary.pairs;
        _summary.rms = std::sqrt(_sumSquares / static_cast<double>(_summary.pairs));
    }
    _previousTest = test;
    _previousReference = reference;
    return popping;
}

void PoppingMeter::restart() {
    _previousTest.reset();
    _previousReference.reset();
}

PoppingSummary PoppingMeter::summary() const { return _summary; }

}  // namespace cavewall::metrics
