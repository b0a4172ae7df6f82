// The upload pacer (walls/upload_pacer.h) against simulated decoders: a steady stream, bursts at
// zone changes, and a hard limit. The store uploads whole textures up to the allowance.
#include "walls/upload_pacer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <numeric>
#include <vector>

namespace cavewall::walls {
namespace {

// Drives the pacer as walls::gl::TextureStore does: each frame `arrivals[f]` textures of `size` bytes
// become ready, and the store uploads what waits in bands of `band` bytes up to the allowance
// (at least one band). Returns bytes per frame.
std::vector<std::size_t> drive(UploadPacer& pacer, const std::vector<int>& arrivals, std::size_t size,
                               std::size_t band = 1000) {
    std::size_t waiting = 0;
    std::vector<std::size_t> out;
    for (int n : arrivals) {
        waiting += static_cast<std::size_t>(n) * size;
        const std::size_t allowed = pacer.allowance(waiting);
        std::size_t bytes = 0;
        while (bytes < waiting && (bytes == 0 || bytes + band <= allowed)) bytes += std::min(band, waiting - bytes);
        waiting -= bytes;
        pacer.uploaded(bytes);
        out.push_back(bytes);
    }
    return out;
}

double ratioP99P50(std::vector<std::size_t> v) {
    std::sort(v.begin(), v.end());
    const double p50 = static_cast<double>(v[(v.size() - 1) / 2]);
    const double p99 = static_cast<double>(v[static_cast<std::size_t>(0.99 * static_cast<double>(v.size() - 1) + 0.5)]);
    return p99 / p50;
}

TEST(UploadPacer, ASteadyStreamIsUploadedAsItArrives) {
    UploadPacer pacer(8u << 20);
    // Once the rate is learnt (a few times its window) and the start's backlog drained.
    const std::vector<std::size_t> bytes = drive(pacer, std::vector<int>(400, 4), 100000);
    for (std::size_t f = 360; f < bytes.size(); ++f) EXPECT_EQ(bytes[f], 400000u) << f;
    EXPECT_NEAR(pacer.inflowBytesPerFrame(), 400000.0, 1000.0);
}

TEST(UploadPacer, BurstsAreSpreadOverFramesAndAllArrive) {
    // 2 textures a frame, and 24 more every 12th frame (a zone change): uploading on arrival
    // spikes to 26 textures; paced, the per-frame work stays within 1.3x its median.
    std::vector<int> arrivals(480, 2);
    for (std::size_t f = 0; f < arrivals.size(); f += 12) arrivals[f] += 24;
    UploadPacer pacer(8u << 20);
    const std::vector<std::size_t> paced = drive(pacer, arrivals, 100000);
    const std::vector<std::size_t> tail(paced.begin() + 120, paced.end());
    EXPECT_LE(ratioP99P50(tail), 1.3);
    // Nothing is held back for good: what arrived was uploaded within a few frames.
    const std::size_t in = 100000u * static_cast<std::size_t>(std::accumulate(arrivals.begin(), arrivals.end(), 0));
    const std::size_t out = std::accumulate(paced.begin(), paced.end(), std::size_t{0});
    EXPECT_LE(in - out, 100000u * 26);
    // Uploading on arrival (the hard limit only) would not be.
    std::vector<std::size_t> unpaced;
    for (int n : arrivals) unpaced.push_back(100000u * static_cast<std::size_t>(n));
    EXPECT_GT(ratioP99P50(std::vector<std::size_t>(unpaced.begin() + 120, unpaced.end())), 10.0);
}

TEST(UploadPacer, TheHardLimitHoldsAndALargeTextureStillGoes) {
    UploadPacer pacer(1000000);
    const std::vector<std::size_t> bytes = drive(pacer, std::vector<int>(20, 30), 100000);
    for (std::size_t b : bytes) EXPECT_LE(b, 1000000u);
    // A texture larger than the limit still goes up, a band a frame at least.
    UploadPacer small(1000);
    EXPECT_EQ(drive(small, {1, 0, 0, 0, 0, 0}, 5000), (std::vector<std::size_t>{1000, 1000, 1000, 1000, 1000, 0}));
}

TEST(UploadPacer, BandsFollowTheAllowanceWhereWholeTexturesCannot) {
    // 175 kB textures (a 512^2 BC1 chain) arriving 1, 1, 2, 1, 1, 2, ...: whole, a frame
    // uploads one or two of them (p99/p50 2); in 1 kB bands about the mean every frame.
    std::vector<int> arrivals(480, 1);
    for (std::size_t f = 2; f < arrivals.size(); f += 3) arrivals[f] = 2;
    UploadPacer whole(8u << 20), banded(8u << 20);
    const std::vector<std::size_t> a = drive(whole, arrivals, 175000, 175000);
    const std::vector<std::size_t> b = drive(banded, arrivals, 175000);
    EXPECT_GE(ratioP99P50(std::vector<std::size_t>(a.begin() + 240, a.end())), 1.9);
    EXPECT_LE(ratioP99P50(std::vector<std::size_t>(b.begin() + 240, b.end())), 1.1);
}

}  // namespace
}  // namespace cavewall::walls
