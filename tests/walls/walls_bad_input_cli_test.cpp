// `cavewall walls` on models that once hung it or failed on its own proposal: a 10 km hall and
// 200 boxes scattered over 2 km (bounded by the planning limit, progress on stderr), and
// degenerate models refused up front with a message about the model, naming its file.
#include "tests/support/run_cli.h"
#include "tests/walls/walls_bad_models.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;

std::filesystem::path outputDir() {
    const std::filesystem::path dir = scenes::testing::testOutput("walls_bad_input");
    return dir;
}

struct Timed {
    CliResult result;
    double seconds = 0.0;
};

Timed timedRun(const std::vector<std::string>& args) {
    const auto start = std::chrono::steady_clock::now();
    Timed t{runCavewall(args)};
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return t;
}

// The hall's grids along x have walls 20 m long, those across it 10 km: within 2 km of wall
// the eight grids along x are planned (560 m in all) and the 32 others are listed as not.
TEST(WallsBadInput, ATenKilometreHallIsPlannedWithinTheLimit) {
    const auto hall = longHall(10000).write("hall-10km.gltf");
    const auto out = outputDir() / "hall.json";
    const Timed t =
        timedRun({"walls", hall.string(), "--out", out.string(), "--plan-limit", "2000", "--max-res", "32"});
    ASSERT_EQ(t.result.exitCode, 0) << t.result.err;
    EXPECT_LT(t.seconds, 60.0);  // seconds here; it ran for more than 240 s before the limit
    EXPECT_THAT(t.result.out, HasSubstr("planning limit: 8 candidates planned (560 m of virtual wall); 32 not planned, "
                                        "each with at least 10000 m of virtual wall, over --plan-limit 2000 m (in all, "
                                        "and 800 m per candidate): raise --plan-limit"));
    EXPECT_THAT(t.result.err, HasSubstr("walls: planned storey 0: grid 8 x 1 (8 cells, 140 m of virtual wall): "));
    EXPECT_TRUE(std::filesystem::exists(out));
    // The walk cost's 0.5 m grid over 10 km x 20 m would be 800,000 eyes: it widens.
    const Timed w = timedRun(
        {"walls", hall.string(), "--out", out.string(), "--plan-limit", "2000", "--max-res", "32", "--walk-cost"});
    ASSERT_EQ(w.result.exitCode, 0) << w.result.err;
    EXPECT_LT(w.seconds, 60.0);
    EXPECT_THAT(w.result.out, HasSubstr("walk cost: 18972 eyes 3.16 m apart (widened to keep to 20000 per storey)"));
}

// 200 boxes scattered over 2 km x 200 m x 2 km printed nothing for 30 minutes: it now prints
// every candidate as it is planned and finishes.
TEST(WallsBadInput, ScatteredBoxesFinishWithProgress) {
    const auto boxes = scatteredBoxes(200).write("scattered-200.gltf");
    const auto out = outputDir() / "scattered.json";
    const Timed t =
        timedRun({"walls", boxes.string(), "--out", out.string(), "--plan-limit", "2000", "--max-res", "32"});
    ASSERT_EQ(t.result.exitCode, 0) << t.result.err;
    EXPECT_LT(t.seconds, 60.0);
    EXPECT_THAT(t.result.err, HasSubstr("walls: planned storey 0: grid 1 x 1 (1 cells, 0 m of virtual wall)"));
    EXPECT_THAT(t.result.out, HasSubstr("planning limit: "));
    EXPECT_TRUE(std::filesystem::exists(out));
}

// Degenerate models are refused before any work, by what is wrong with the model.
TEST(WallsBadInput, DegenerateModelsAreRefusedByWhatIsWrongWithTheModel) {
    const struct {
        const char* name;
        std::filesystem::path file;
        std::string message;
    } cases[] = {
        {"one point", pointFile(1, 2, 3, 5e-4f).write("one-point.gltf"),
         "one-point.gltf: all 3 vertices lie within 1 mm of (1.00025, 2.00025, 3)"},
        {"a vertical plane", verticalPlaneFile().write("vertical-plane.gltf"),
         "vertical-plane.gltf: the model has no floor: it spans 10 m along x, 3 m along y (up) and 0 m along z"},
        {"far from the origin", roomAt(9e5f).write("far.gltf"),
         "far.gltf: coordinates reach 900010 m (the model spans (900000, -0.1, 900000) to (900010, 1, 900010)): "
         "beyond the ±100000 m limit of scene coordinates, where single-precision positions are 0.0625 m apart; "
         "recentre the model near the origin"},
        {"empty", emptyFile().write("empty.gltf"),
         "empty.gltf: the model has no triangles (0 objects with geometry; expected at least one triangle"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const auto out = outputDir() / "degenerate.json";
        std::filesystem::remove(out);
        const CliResult r = runCavewall({"walls", c.file.string(), "--out", out.string()});
        EXPECT_EQ(r.exitCode, 1) << r.out;
        EXPECT_THAT(r.err, HasSubstr(c.message));
        EXPECT_THAT(r.err, ::testing::Not(HasSubstr("cells[0]")));
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

// --rooms on a floor with one wall across it that closes no room: the storey is cut by the cost
// model's grid, and the warning says so and why.
TEST(WallsBadInput, RoomsThatCannotBeFoundAreReported) {
    const std::filesystem::path model =
        boxesFile({{-4, -0.1f, -4, 4, 0, 4}, {-0.1f, 0, -4, 0.1f, 3, 4}}).write("rooms-none.gltf");
    const auto out = outputDir() / "rooms-none.json";
    const CliResult r = runCavewall({"walls", model.string(), "--out", out.string(), "--rooms"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("floor plan: 1 wall elements, 0 rooms"));
    EXPECT_THAT(r.err, HasSubstr("warning: --rooms: storey 0 is cut by grid "));
    EXPECT_THAT(r.err, HasSubstr(" instead: no rooms were found (its floor plan: 1 wall elements, 0 rooms)"));
    EXPECT_TRUE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace cavewall::test
