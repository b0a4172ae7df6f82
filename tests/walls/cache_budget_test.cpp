// The disk budget of baking on demand (walls/cache_budget.h): least recently wanted files go
// first, never one wanted now, and a bad budget is refused with its flag and value.
#include "walls/cache_budget.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

constexpr std::uint64_t kFile = 1000;  // bytes per file in these tests

TEST(CacheBudget, EvictsTheLeastRecentlyWantedFirst) {
    CacheBudget budget(3 * kFile);  // room for three files
    budget.frame({}, {1, 2, 3});
    EXPECT_TRUE(budget.add(1, kFile).empty());
    EXPECT_TRUE(budget.add(2, kFile).empty());
    EXPECT_TRUE(budget.add(3, kFile).empty());
    budget.frame({}, {1, 3});  // 2 was last wanted a frame earlier than 1 and 3
    EXPECT_EQ(budget.add(4, kFile), std::vector<int>{2});
    EXPECT_EQ(budget.files(), 3);
    EXPECT_EQ(budget.bytes(), 3 * kFile);
    EXPECT_FALSE(budget.holds(2));
    EXPECT_EQ(budget.evictions(), 1);
}

TEST(CacheBudget, FilesNoFrameWantedAreTheOldest) {
    CacheBudget budget(2 * kFile);
    EXPECT_TRUE(budget.add(10, kFile).empty());  // found in the cache before any frame
    budget.frame({}, {1});
    EXPECT_TRUE(budget.add(1, kFile).empty());
    EXPECT_EQ(budget.add(2, kFile), std::vector<int>{10});
}

TEST(CacheBudget, NeverEvictsAFileWantedNow) {
    CacheBudget budget(2 * kFile);
    budget.frame({1, 2}, {});
    budget.add(1, kFile);
    budget.add(2, kFile);
    budget.frame({1, 2, 3}, {});
    // Everything resident is wanted now: nothing goes, the folder is over budget.
    EXPECT_TRUE(budget.add(3, kFile).empty());
    EXPECT_EQ(budget.bytes(), 3 * kFile);
    // The view moves on: 1 and 2 are not wanted now any more, the next file evicts both (oldest
    // by the frame they were last wanted in, then id) to fit 2 files in the budget.
    budget.frame({3, 4}, {});
    EXPECT_EQ(budget.add(4, kFile), (std::vector<int>{1, 2}));
}

TEST(CacheBudget, FullSaysWhetherAFileFits) {
    CacheBudget budget(2 * kFile);
    budget.add(1, kFile);
    EXPECT_FALSE(budget.full(kFile));  // 1000 + 1000 <= 2000
    EXPECT_TRUE(budget.full(kFile + 1));
}

TEST(CacheBudget, BadBudgetsNameTheFlagAndValue) {
    struct Case {
        const char* name;
        double megabytes;
        const char* message;
    };
    const Case cases[] = {
        {"zero", 0.0, "--cache-budget: expected a disk budget in MB in (0, 1e9], got 0"},
        {"negative", -5.0, "--cache-budget: expected a disk budget in MB in (0, 1e9], got -5"},
        {"not a number", std::numeric_limits<double>::quiet_NaN(), "got nan"},
        {"infinite", std::numeric_limits<double>::infinity(), "got inf"},
        {"too large", 2e9, "got 2e+09"},
        // 1e-9 MB is about 0.001 bytes: it would round to 0, which means "no budget".
        {"rounds to zero bytes", 1e-9,
         "--cache-budget: expected a disk budget of at least one byte, got 1e-09 MB (0 bytes once rounded)"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { cacheBudgetBytes(c.megabytes); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    EXPECT_EQ(cacheBudgetBytes(1.5), 1572864u);  // 1.5 * 2^20
    EXPECT_EQ(cacheBudgetBytes(1e-6), 1u);       // 1.05 bytes rounds to one byte: kept
}

}  // namespace
}  // namespace cavewall::walls
