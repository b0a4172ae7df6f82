// The on-demand bench mode's private bake cache (app/bench/private_cache.h): emptied before a
// run, never the shared cache, never a folder it did not make.
#include "app/bench/private_cache.h"

#include "config/error.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace cavewall::bench {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

void touch(const fs::path& file) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << "x";
}

TEST(PrivateCache, IsEmptiedAndMarked) {
    const test::TempFolder root("private_cache_empty");
    const fs::path mine = root / "out" / "on-demand-cache";
    makeEmptyPrivateCache(mine, root / "shared");
    EXPECT_TRUE(fs::exists(mine / kPrivateCacheMarker));
    touch(mine / "0123_abcdef" / "manifest.json");  // an earlier run's bake
    makeEmptyPrivateCache(mine, root / "shared");
    EXPECT_FALSE(fs::exists(mine / "0123_abcdef"));
    EXPECT_TRUE(fs::exists(mine / kPrivateCacheMarker));
    // An empty folder without the marker is fine too.
    fs::create_directories(root / "empty");
    makeEmptyPrivateCache(root / "empty", root / "shared");
    EXPECT_TRUE(fs::exists(root / "empty" / kPrivateCacheMarker));
}

TEST(PrivateCache, RefusesTheSharedCacheAndFoldersItDidNotMake) {
    const test::TempFolder root("private_cache_refuse");
    const fs::path shared = root / "shared";
    touch(shared / "scene_0123456789abcdef" / "t0.tif");  // another scene's bake: must survive
    touch(root / "user" / "notes.txt");
    touch(root / "file");
    struct Case {
        fs::path folder;
        std::string message;
    };
    const Case cases[] = {
        {shared, "expected a folder apart from the shared bake cache --cache " + shared.string() +
                     " (default $CAVEWALL_CACHE or ~/.cache/cavewall), got the cache or a folder inside it; give "
                     "another --out or --cache"},
        {shared / "sub" / "..", "the cache or a folder inside it"},
        {shared / "private", "the cache or a folder inside it"},
        {root.path(), "a folder that holds it"},
        {root / "user", "got a folder with other files; not deleting it"},
        {root / "file", "expected a folder, got a file; give another --out"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.folder.string());
        EXPECT_THROW(
            {
                try {
                    makeEmptyPrivateCache(c.folder, shared);
                } catch (const Error& e) {
                    EXPECT_THAT(e.what(), HasSubstr(c.message));
                    EXPECT_THAT(e.what(),
                                HasSubstr("on-demand cache " + c.folder.string() + " (--out DIR/on-demand-cache): "));
                    throw;
                }
            },
            Error);
    }
    EXPECT_TRUE(fs::exists(shared / "scene_0123456789abcdef" / "t0.tif"));
    EXPECT_TRUE(fs::exists(root / "user" / "notes.txt"));
}

}  // namespace
}  // namespace cavewall::bench
