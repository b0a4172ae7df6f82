#include "walls/cache_budget.h"

#include "config/error.h"

#include <cmath>
#include <sstream>

namespace cavewall::walls {

std::uint64_t cacheBudgetBytes(double megabytes, const std::string& flag) {
    if (!(std::isfinite(megabytes) && megabytes > 0.0 && megabytes <= 1e9)) {
        std::ostringstream got;
        got << megabytes;
        throw Error(flag + ": expected a disk budget in MB in (0, 1e9], got " + got.str());
    }
    const auto bytes = static_cast<std::uint64_t>(std::llround(megabytes * 1024.0 * 1024.0));
    if (bytes == 0) {
        std::ostringstream got;
        got << megabytes;
        // Zero bytes would read as "no budget": refused rather than rounded away.
        throw Error(flag + ": expected a disk budget of at least one byte, got " + got.str() +
                    " MB (0 bytes once rounded)");
    }
    return bytes;
}

void CacheBudget::frame(const std::vector<int>& now, const std::vector<int>& soon) {
    _core.beginFrame();
    for (int id : now) _core.wantNow(id), _core.touch(id);
    for (int id : soon) _core.touch(id);
}

std::vector<int> CacheBudget::add(int id, std::uint64_t bytes) {
    _core.markResident(id, static_cast<std::size_t>(bytes));
    return _core.takeEvictions();
}

}  // namespace cavewall::walls
