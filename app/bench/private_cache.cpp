#include "app/bench/private_cache.h"

#include "config/error.h"

#include <fstream>

namespace cavewall::bench {

namespace fs = std::filesystem;

namespace {

// Absolute, what exists of it resolved, without a trailing separator.
fs::path resolved(const fs::path& p) {
    fs::path r = fs::weakly_canonical(fs::absolute(p)).lexically_normal();
    if (!r.has_filename() && r.has_parent_path() && r != r.root_path()) r = r.parent_path();
    return r;
}

// True when `inner` is `outer` or lies inside it (both resolved).
bool within(const fs::path& inner, const fs::path& outer) {
    auto i = inner.begin();
    for (auto o = outer.begin(); o != outer.end(); ++o, ++i)
        if (i == inner.end() || *i != *o) return false;
    return true;
}

}  // namespace

void checkPrivateCache(const fs::path& folder, const fs::path& sharedCache) {
    const fs::path mine = resolved(folder);
    const fs::path shared = resolved(sharedCache);
    // The folder comes from --out (DIR/on-demand-cache), the shared cache from --cache (or its
    // default): the messages name both flags, so that the user knows which one to change.
    const std::string where = "on-demand cache " + folder.string() + " (--out DIR/on-demand-cache)";
    if (within(mine, shared) || within(shared, mine))
        throw Error(where + ": expected a folder apart from the shared bake cache --cache " + sharedCache.string() +
                    " (default $CAVEWALL_CACHE or ~/.cache/cavewall), got " +
                    (within(mine, shared) ? "the cache or a folder inside it" : "a folder that holds it") +
                    "; give another --out or --cache");
    if (fs::exists(mine)) {
        if (!fs::is_directory(mine)) throw Error(where + ": expected a folder, got a file; give another --out");
        if (!fs::is_empty(mine) && !fs::exists(mine / kPrivateCacheMarker))
            throw Error(where + ": expected an empty folder or an earlier on-demand cache (with " +
                        kPrivateCacheMarker + "), got a folder with other files; not deleting it (give another --out)");
    }
}

void makeEmptyPrivateCache(const fs::path& folder, const fs::path& sharedCache) {
    checkPrivateCache(folder, sharedCache);
    const fs::path mine = resolved(folder);
    fs::remove_all(mine);
    fs::create_directories(mine);
    std::ofstream marker(mine / kPrivateCacheMarker);
    marker << "cavewall bench --on-demand: a private bake cache, emptied before each run\n";
    if (!marker) throw Error("on-demand cache " + folder.string() + ": could not write " + kPrivateCacheMarker);
}

}  // namespace cavewall::bench
