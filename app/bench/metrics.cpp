#include "app/bench/metrics.h"

#include "display/timing.h"
#include "metrics/flip.h"
#include "metrics/ssim.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>

namespace cavewall::bench {

namespace {

void addPopping(metrics::PoppingSummary& s, double& squares, std::int64_t frame, double popping) {
    if (s.pairs == 0 || popping > s.peak) {
        s.peak = popping;
        s.peakFrame = frame;
    }
    ++s.pairs;
    squares += popping * popping;
}

}  // namespace

ErrorPool::ErrorPool(std::size_t screens) : _screens(screens) {}

void ErrorPool::addFrame(std::int64_t frame, const std::vector<ComparedImage>& images) {
    metrics::SquaredError all;
    std::vector<metrics::SquaredError> perScreen(_screens.size());
    std::vector<bool> shown(_screens.size(), false);
    for (const ComparedImage& c : images) {
        assert(c.screen >= 0 && c.screen < static_cast<int>(_screens.size()) && c.test && c.reference);
        const metrics::SquaredError e = metrics::squaredError(*c.test, *c.reference);
        all += e;
        perScreen[c.screen] += e;
        shown[c.screen] = true;
        const double ssim = metrics::ssim(*c.test, *c.reference);
        metrics::FlipOptions options;
        options.pixelsPerDegree = c.pixelsPerDegree;
        const metrics::FlipResult flip = metrics::flip(*c.test, *c.reference, options);
        for (Series* s : {&_all, &_screens[c.screen]}) {
            s->ssimSum += ssim;
            ++s->images;
            s->pixels += flip.errors.size();
            s->flipSum += flip.mean * static_cast<double>(flip.errors.size());
            s->flipOver += static_cast<std::uint64_t>(
                std::count_if(flip.errors.begin(), flip.errors.end(), [](float v) { return v > kFlipThreshold; }));
        }
        _images.push_back({frame, c.screen, c.image, e.psnrDb(), flip.mean});
        if (_worst.frame < 0 || flip.mean > _worst.mean) {
            _worst = {metrics::flipErrorImage(flip), frame, c.screen, c.image, flip.mean, *c.test, *c.reference};
        }
        const auto [it, added] = _meters.try_emplace({c.screen, c.image});
        if (const std::optional<double> p = it->second.addFrame(frame, *c.test, *c.reference)) {
            addPopping(_all.popping, _all.poppingSquares, frame, *p);
            addPopping(_screens[c.screen].popping, _screens[c.screen].poppingSquares, frame, *p);
        }
    }
    _all.psnr.addFrame(frame, all);
    for (std::size_t s = 0; s < _screens.size(); ++s)
        if (shown[s]) _screens[s].psnr.addFrame(frame, perScreen[s]);
}

ImageError ErrorPool::summarise(const Series& s) {
    const metrics::PooledErrorSummary p = s.psnr.summary();
    ImageError e;
    e.frames = p.frames;
    e.mse = p.mse;
    e.rmse = std::sqrt(p.mse);
    e.psnrDb = p.psnrDb;
    e.worstFramePsnrDb = p.worstFramePsnrDb;
    e.worstFrame = p.worstFrame;
    e.p5FramePsnrDb = p.p5FramePsnrDb;
    e.meanPsnrDb = p.frames > 0 ? p.cappedMeanPsnrDb : kQuantisationPsnrDb;
    e.ssim = s.images > 0 ? s.ssimSum / static_cast<double>(s.images) : 1.0;
    e.flipMean = s.pixels > 0 ? s.flipSum / static_cast<double>(s.pixels) : 0.0;
    e.flipOverThreshold = s.pixels > 0 ? static_cast<double>(s.flipOver) / static_cast<double>(s.pixels) : 0.0;
    e.poppingPeak = s.popping.peak;
    e.poppingRms = s.popping.pairs > 0 ? std::sqrt(s.poppingSquares / static_cast<double>(s.popping.pairs)) : 0.0;
    return e;
}

ImageError ErrorPool::result() const { return summarise(_all); }

ImageError ErrorPool::screenResult(std::size_t screen) const { return summarise(_screens.at(screen)); }

TimeStats timeStats(const std::vector<double>& samples) {
    TimeStats s;
    if (samples.empty()) return s;
    s.p50 = display::percentile(samples, 0.50);
    s.p95 = display::percentile(samples, 0.95);
    s.p99 = display::percentile(samples, 0.99);
    for (double v : samples) s.mean += v;
    s.mean /= static_cast<double>(samples.size());
    return s;
}

std::vector<std::size_t> paretoFront(const std::vector<TradeOff>& points) {
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < points.size(); ++i) {
        bool dominated = false;
        for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
            const TradeOff &p = points[i], &q = points[j];
            dominated = q.time <= p.time && q.error <= p.error && (q.time < p.time || q.error < p.error);
        }
        if (!dominated) front.push_back(i);
    }
    std::stable_sort(front.begin(), front.end(),
                     [&](std::size_t a, std::size_t b) { return points[a].time < points[b].time; });
    return front;
}

}  // namespace cavewall::bench
