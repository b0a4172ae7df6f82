#pragma once
// The residency core shared by walls/texture_pager.h and walls/geometry_pager.h: which items
// (texture ids, cells) are resident with how many bytes, under a byte budget, evicting the least
// recently wanted item that is not wanted now. GL-free, no thread and no lock: each pager calls
// it under its own mutex.
//
// Per frame: beginFrame(), then wantNow() for the items drawn now and touch() for every item
// wanted (now or soon). markResident(id, bytes) first evicts, least recently wanted first and
// never an item wanted now, until the new item fits; when everything resident is wanted now the
// item is made resident anyway (over budget until the view moves). Evicted ids wait in
// takeEvictions() for the caller to free them.

#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace cavewall::walls {

class ResidencyCore {
public:
    explicit ResidencyCore(std::size_t budgetBytes) : _budget(budgetBytes) {}

    void beginFrame() {
        ++_frame;
        _wantedNow.clear();
    }
    void wantNow(int id) { _wantedNow.insert(id); }
    bool wantedNow(int id) const { return _wantedNow.count(id) > 0; }
    void touch(int id) { _lastWanted[id] = _frame; }

    // Makes `id` resident with `bytes` (replacing its size if it already is), evicting first.
    void markResident(int id, std::size_t bytes);
    std::vector<int> takeEvictions();

    bool isResident(int id) const { return _resident.count(id) > 0; }
    int count() const { return static_cast<int>(_resident.size()); }
    std::size_t residentBytes() const;
    double residentMB() const;  // sum of each item's MB (bytes / 2^20)
    std::size_t budget() const { return _budget; }
    long pageIns() const { return _pageIns; }
    long evictions() const { return _evictionCount; }

private:
    void evictFor(std::size_t bytes);

    std::size_t _budget;
    std::map<int, std::size_t> _resident;  // id -> bytes
    std::map<int, long> _lastWanted;       // id -> frame number
    std::set<int> _wantedNow;
    std::vector<int> _evictions;
    long _frame = 0, _pageIns = 0, _evictionCount = 0;
};

}  // namespace cavewall::walls
