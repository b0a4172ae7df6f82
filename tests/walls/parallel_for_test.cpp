#include "walls/parallel_for.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>
#include <vector>

namespace cavewall::walls {
namespace {

TEST(ParallelFor, CallsEveryIndexOnce) {
    std::vector<int> calls(1000, 0);
    parallelFor(int(calls.size()), [&](int i) { ++calls[i]; });  // one slot per index: no race
    for (int i = 0; i < int(calls.size()); ++i) EXPECT_EQ(calls[i], 1) << i;
}

TEST(ParallelFor, NestedCallsRunOnTheOuterCallsThread) {
    // The planner nests loops (sides in parallel, each side's row candidates in parallel); the
    // inner loop must not start threads of its own.
    constexpr int kOuter = 8, kInner = 16;
    std::vector<std::thread::id> outer(kOuter);
    std::vector<std::vector<std::thread::id>> inner(kOuter, std::vector<std::thread::id>(kInner));
    parallelFor(kOuter, [&](int i) {
        outer[i] = std::this_thread::get_id();
        parallelFor(kInner, [&](int j) { inner[i][j] = std::this_thread::get_id(); });
    });
    for (int i = 0; i < kOuter; ++i)
        for (int j = 0; j < kInner; ++j) EXPECT_EQ(inner[i][j], outer[i]) << i << ", " << j;
}

TEST(ParallelFor, RethrowsTheExceptionAndStaysUsable) {
    EXPECT_THROW(parallelFor(100,
                             [](int i) {
                                 if (i == 37) throw std::runtime_error("37");
                             }),
                 std::runtime_error);
    std::vector<int> calls(100, 0);
    parallelFor(100, [&](int i) { ++calls[i]; });
    for (int c : calls) EXPECT_EQ(c, 1);
}

}  // namespace
}  // namespace cavewall::walls
