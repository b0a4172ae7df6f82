#include "walls/residency.h"

#include <climits>
#include <utility>

namespace cavewall::walls {

void ResidencyCore::evictFor(std::size_t bytes) {
    std::size_t used = residentBytes();
    while (used + bytes > _budget) {
        int victim = -1;
        long oldest = LONG_MAX;
        for (const auto& [id, b] : _resident)
            if (!_wantedNow.count(id) && _lastWanted[id] < oldest) {
                oldest = _lastWanted[id];
                victim = id;
            }
        if (victim < 0) return;  // everything resident is wanted now: over budget until the view moves
        used -= _resident[victim];
        _resident.erase(victim);
        _evictions.push_back(victim);
        ++_evictionCount;
    }
}

void ResidencyCore::markResident(int id, std::size_t bytes) {
    evictFor(bytes);
    _resident[id] = bytes;
    ++_pageIns;
}

std::vector<int> ResidencyCore::takeEvictions() { return std::exchange(_evictions, {}); }

std::size_t ResidencyCore::residentBytes() const {
    std::size_t used = 0;
    for (const auto& [id, b] : _resident) used += b;
    return used;
}

double ResidencyCore::residentMB() const {
    double mb = 0.0;
    for (const auto& [id, b] : _resident) mb += static_cast<double>(b) / (1024.0 * 1024.0);
    return mb;
}

}  // namespace cavewall::walls
