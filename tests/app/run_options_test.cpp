// The run's options (app/run_options.h): the rules tying options together, one table row per
// rule with its message, and the enums' words.
#include "app/run_options.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

namespace cavewall::app {
namespace {

using ::testing::HasSubstr;

TEST(RunOptions, DefaultsAreValid) { EXPECT_NO_THROW(validate(RunOptions{})); }

TEST(RunOptions, EachRuleNamesItsFlags) {
    struct Case {
        const char* name;
        std::function<void(RunOptions&)> change;
        const char* message;
    };
    const Case cases[] = {
        {"negative frames", [](RunOptions& o) { o.frames = -1; },
         "--frames: expected at least 0 (0: until stopped), got -1"},
        {"until stopped on several PCs",
         [](RunOptions& o) {
             o.frames = 0;
             o.cluster = true;
         },
         "--frames 0 and --cluster: expected a frame count with --cluster"},
        {"saved frames without a folder", [](RunOptions& o) { o.saveEvery = 1; }, "--save-frames: needs --out DIR"},
        {"window images without windows",
         [](RunOptions& o) {
             o.out = "x";
             o.saveEvery = 1;
             o.saveWindow = true;
         },
         "--save-window: needs --save-frames and windows"},
        {"budget without lod", [](RunOptions& o) { o.triangleBudget = 1000; },
         "--triangle-budget: needs levels of detail (--lod PX with PX > 0), got --lod 0"},
        {"frame budget without lod", [](RunOptions& o) { o.frameBudgetMs = 16.7; },
         "--frame-budget-ms: needs levels of detail (--lod PX with PX > 0) or --clusters, got --lod 0"},
        {"both budgets",
         [](RunOptions& o) {
             o.lodPixels = 1.0;
             o.frameBudgetMs = 16.7;
             o.triangleBudget = 1000;
         },
         "--frame-budget-ms and --triangle-budget: expected one of them, got both"},
        {"clusters with a triangle budget",
         [](RunOptions& o) {
             o.clusters = true;
             o.lodPixels = 1.0;
             o.triangleBudget = 1000;
         },
         "--clusters and --triangle-budget: expected --frame-budget-ms with --clusters"},
        {"cache budget without baking on demand", [](RunOptions& o) { o.cacheBudgetMB = 100.0; },
         "--cache-budget: needs --bake-on-demand"},
        {"negative cache budget",
         [](RunOptions& o) {
             o.bakeOnDemand = true;
             o.cacheBudgetMB = -1.0;
         },
         "--cache-budget: expected a disk budget in MB in (0, 1e9], got -1"},
        {"interleave without baking on demand", [](RunOptions& o) { o.bakeInterleave = 30; },
         "--bake-interleave: needs --bake-on-demand"},
        {"baking on demand with synchronous paging",
         [](RunOptions& o) {
             o.bakeOnDemand = true;
             o.synchronousPaging = true;
         },
         "--bake-on-demand and --sync-paging: expected one of them, got both"},
        {"baking on demand in a cluster",
         [](RunOptions& o) {
             o.bakeOnDemand = true;
             o.cluster = true;
         },
         "--bake-on-demand and --cluster: expected one of them, got both"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        RunOptions o;
        c.change(o);
        EXPECT_THAT([&] { validate(o); }, ::testing::ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    RunOptions budgeted;  // each budget alone with levels of detail is fine
    budgeted.lodPixels = 1.0;
    budgeted.triangleBudget = 1000;
    EXPECT_NO_THROW(validate(budgeted));
    budgeted.triangleBudget = 0;
    budgeted.frameBudgetMs = 16.7;
    EXPECT_NO_THROW(validate(budgeted));
    RunOptions onDemand;  // baking on demand with a disk budget
    onDemand.bakeOnDemand = true;
    onDemand.cacheBudgetMB = 500.0;
    EXPECT_NO_THROW(validate(onDemand));
    RunOptions clusters;  // clusters hold a time budget without levels of detail
    clusters.clusters = true;
    clusters.frameBudgetMs = 16.7;
    EXPECT_NO_THROW(validate(clusters));
}

TEST(RunOptions, EveryEnumValueHasOneWord) {
    EXPECT_EQ(toString(Transition::Blend), "blend");
    EXPECT_EQ(toString(Transition::Warp), "warp");
    // --nav's help lists guided, fly, walk, none; Auto has no word (the flag left out).
    std::vector<std::string_view> words;
    for (const auto& [word, value] : kNavigationNames) {
        words.push_back(word);
        EXPECT_NE(value, Navigation::Auto);
    }
    EXPECT_EQ(words, (std::vector<std::string_view>{"guided", "fly", "walk", "none"}));
}

TEST(RunOptions, RouteWallFollowsTheWallPathAndNeedsOne) {
    scenes::SceneDescription d;
    d.walkPath = {{0, 1.7, 0}, {10, 1.7, 0}};
    d.wallPath = {{0, 1.7, 5}, {10, 1.7, 5}, {10, 1.7, -5}};
    scenes::SceneDescription walk = d;
    useRoute(walk, Route::Walk, "plant.json");
    EXPECT_EQ(walk.walkPath, d.walkPath);
    scenes::SceneDescription wall = d;
    useRoute(wall, Route::Wall, "plant.json");
    EXPECT_EQ(wall.walkPath, d.wallPath);
    d.wallPath.resize(1);
    EXPECT_THAT([&] { useRoute(d, Route::Wall, "plant.json"); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr(
                    "plant.json: --route wall: the scene has no wallPath (expected at least 2 points, got 1)")));
    EXPECT_EQ(kRouteNames[0].first, "walk");
    EXPECT_EQ(kRouteNames[1].first, "wall");
}

}  // namespace
}  // namespace cavewall::app
