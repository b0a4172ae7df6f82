#pragma once
// The on-demand bench mode's bake cache (`cavewall bench --on-demand`): a folder of its own,
// emptied before the run so that the walk starts from a cold cache, and never the shared bake
// cache (or a folder inside it or holding it), whose other scenes' bakes must survive.
// GL-free.

#include <filesystem>

namespace cavewall::bench {

// The file that marks a folder as an earlier on-demand run's private cache.
inline constexpr const char* kPrivateCacheMarker = ".cavewall-on-demand-cache";

// Throws cavewall::Error (naming both folders) when makeEmptyPrivateCache would refuse
// `folder`; changes nothing.
void checkPrivateCache(const std::filesystem::path& folder, const std::filesystem::path& sharedCache);

// Makes `folder` an empty private cache: refuses (cavewall::Error naming both folders) when it
// is `sharedCache`, lies inside it or holds it, and when it exists, is not empty and lacks the
// marker (a folder this bench did not make is never deleted); otherwise deletes what an earlier
// run left, creates the folder and writes the marker. Paths are compared after making them
// absolute and resolving what exists of them (symbolic links, "..").
void makeEmptyPrivateCache(const std::filesystem::path& folder, const std::filesystem::path& sharedCache);

}  // namespace cavewall::bench
