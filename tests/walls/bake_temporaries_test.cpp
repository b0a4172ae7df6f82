#include "walls/bake_cache.h"

#include <gtest/gtest.h>

#include <fstream>

namespace cavewall::walls {
namespace {

TEST(BakeTemporaries, OnlyOurOwnNamesAreTemporaries) {
    const struct {
        const char* name;
        bool temporary;
    } cases[] = {
        {".tex_0003_0123456789abcdef.tmp-4242-0.bct", true},  // scenes::writeAtomically
        {".manifest.tmp-17-305.json", true},
        {".tex_0001_0123456789abcdef.depth.tmp-9-1.tif", true},
        {".tex_0003_0123456789abcdef.bct.link-4242", true},  // linkCachedTexture
        {"tex_0003_0123456789abcdef.bct", false},            // a texture
        {"manifest.json", false},
        {".manifest.tmp-x-1.json", false},  // not a pid
        {".manifest.tmp-12.json", false},   // no counter
        {".notes.tmp-1-2-3", false},        // more than ours
        {"a.tmp-1-2.json", false},          // not hidden
        {".tex.bct.link-", false},
        {".my-own.link-12a", false},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(isBakeTemporary(c.name), c.temporary);
    }
}

TEST(BakeTemporaries, OnlyOldOnesAreRemoved) {
    const auto dir = std::filesystem::temp_directory_path() / "cavewall_bake_temporaries";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const char* names[] = {".tex_0001_0123456789abcdef.tmp-77-0.bct", ".manifest.tmp-77-1.json",
                           ".tex_0002_0123456789abcdef.bct.link-77", "tex_0001_0123456789abcdef.bct",
                           ".someone-elses.tmp"};
    for (const char* n : names) std::ofstream(dir / n) << "x";
    // A killed bake's files, an hour old, beside a live bake's (just written) and other files.
    const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
    for (const char* n : names) std::filesystem::last_write_time(dir / n, old);
    std::ofstream(dir / ".tex_0003_0123456789abcdef.tmp-78-0.bct") << "being written";
    EXPECT_EQ(removeStaleTemporaries(dir, kStaleTemporaryAge), 3);
    EXPECT_FALSE(std::filesystem::exists(dir / names[0]));
    EXPECT_FALSE(std::filesystem::exists(dir / names[1]));
    EXPECT_FALSE(std::filesystem::exists(dir / names[2]));
    EXPECT_TRUE(std::filesystem::exists(dir / names[3]));
    EXPECT_TRUE(std::filesystem::exists(dir / names[4]));
    EXPECT_TRUE(std::filesystem::exists(dir / ".tex_0003_0123456789abcdef.tmp-78-0.bct"));
    EXPECT_EQ(removeStaleTemporaries(dir / "none", kStaleTemporaryAge), 0);
}

}  // namespace
}  // namespace cavewall::walls
