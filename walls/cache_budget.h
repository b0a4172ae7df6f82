#pragma once
// The disk budget of baking on demand (`cavewall run --cache-budget MB`), GL-free: which baked
// texture files of the scene's bake folder to delete so that the folder's texture files stay
// within a byte budget, least recently used first (walls/residency.h's core, counted in file
// bytes instead of GPU bytes).
//
// Per frame: frame(now, soon) with the textures the walkthrough wants now and soon; "used" means
// wanted in a frame, so files no frame of this run has wanted count as the oldest. add(id, bytes)
// registers a file (one found in the cache, or one just baked) and returns the ids whose files
// must go to make room: never one wanted now; when everything else is wanted now nothing is
// evicted and the folder stays over budget until the view moves. The caller first drops the
// evicted entries from the manifest (written atomically), then deletes their files.

#include "walls/residency.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::walls {

// MB as given on the command line -> bytes (rounded to the nearest). Throws cavewall::Error
// naming `flag` unless 0 < megabytes <= 1e9 (a petabyte), finite, and at least one byte once
// rounded (a budget of 0 bytes would mean none).
std::uint64_t cacheBudgetBytes(double megabytes, const std::string& flag = "--cache-budget");

class CacheBudget {
public:
    explicit CacheBudget(std::uint64_t budgetBytes) : _core(static_cast<std::size_t>(budgetBytes)) {}

    void frame(const std::vector<int>& now, const std::vector<int>& soon);
    // Registers `id`'s file of `bytes`; returns the ids evicted to make room (see above).
    std::vector<int> add(int id, std::uint64_t bytes);
    bool holds(int id) const { return _core.isResident(id); }
    // True when a further file of `bytes` would not fit without evicting.
    bool full(std::uint64_t bytes) const { return _core.residentBytes() + bytes > _core.budget(); }
    std::uint64_t bytes() const { return _core.residentBytes(); }
    std::uint64_t budget() const { return _core.budget(); }
    int files() const { return _core.count(); }
    long evictions() const { return _core.evictions(); }

private:
    ResidencyCore _core;
};

}  // namespace cavewall::walls
