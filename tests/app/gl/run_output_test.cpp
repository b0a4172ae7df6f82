// The files of a run (app/gl/run_output.h) written from hand-made frame results: the columns
// docs/commands.md and the header promise, read back by name, and poses exact to the bit. No GL
// context.
#include "app/gl/run_output.h"

#include "config/display_config.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace cavewall::app::gl {
namespace {

using walkthrough::FrameResult;
using walkthrough::WallState;

scenes::SceneDescription twoCells() {
    scenes::SceneDescription d;
    d.cells.resize(2);
    d.cells[0].name = "A";
    d.cells[1].name = "B";
    d.walls.resize(1);
    d.walls[0].name = "A|B";
    return d;
}

TEST(RunOutput, FramesAndWallsCsvHaveOneRowPerFrameAndWall) {
    const test::TempFolder folder("run_output");
    const scenes::SceneDescription d = twoCells();
    const display::Display display(config::loadDisplayConfig("cave4"));
    const glm::dvec3 head(0.1, 1.7 / 3.0, -0.2);  // 1.7 / 3 has no short decimal form
    {
        RunOutput out(folder.path(), d, display);
        FrameResult r;
        r.cell = 1;
        r.zone = 4;
        r.eyeWorld = glm::dvec3(-37.0, 1.7, -10.0);
        r.frameMs = 12.3456;
        r.stats.triangles = 5000;
        r.geometryTriangles = 4990;
        r.walls = {WallState{0, {{7, 0.25}, {8, 0.75}}, 0.0, true, false, 3.5, 1}};
        r.texturesOverAlpha = 1;
        r.clusterObjects = 12;
        r.clusterTextured = 3;
        r.clusterAverage = 2;
        r.clusterPredictedMs = 4.25;
        r.clusterBudgetMs = 16.5;
        r.clusterFades = 2;
        r.clusterSelectedMs = 3.5;
        r.clusterCheapestMs = 0.125;
        r.clusterTargetMs = 40.0;
        r.clusterPredictedFrameMs = 38.25;
        r.clusterFloorMs = 24.5;
        r.geometryFallbacks = 2;
        r.texturesBaked = 40;
        r.texturesBakedNow = 3;
        r.texturesToBake = 7;
        r.bakerBusy = true;
        out.writeFrame(0, 0.0, head, r);
        r.cell = -1;  // outside every cell
        r.walls.clear();
        out.writeFrame(1, 1.0 / 60.0, head, r, 2.5, {-1.0, 1.0, -1.0});
    }
    const test::CsvTable frames = test::readCsv(folder / "frames.csv");
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(frames[0].at("frame"), "0");
    EXPECT_EQ(frames[0].at("cell"), "B");
    EXPECT_EQ(frames[1].at("cell"), "-");
    EXPECT_EQ(frames[0].at("zone"), "4");
    EXPECT_EQ(frames[0].at("frame_ms"), "12.346");  // three decimals
    EXPECT_EQ(frames[0].at("triangles"), "5000");
    EXPECT_EQ(frames[0].at("geometry_triangles"), "4990");
    EXPECT_EQ(frames[0].at("fallbacks"), "1");  // the one wall's fallback
    EXPECT_EQ(frames[1].at("sync_ms"), "2.500");
    EXPECT_EQ(frames[0].number("view_yaw_deg"), 0.0);  // the default view, down -Z
    // (-1, 1, -1): half-way between -Z and -X (45° to the left), 35.26° up (asin(1 / sqrt 3)).
    EXPECT_NEAR(frames[1].number("view_yaw_deg"), 45.0, 1e-4);
    EXPECT_NEAR(frames[1].number("view_pitch_deg"), 35.2644, 1e-4);
    EXPECT_EQ(frames[0].at("over_alpha"), "1");
    EXPECT_EQ(frames[0].at("cluster_objects"), "12");
    EXPECT_EQ(frames[0].at("cluster_textured"), "3");
    EXPECT_EQ(frames[0].at("cluster_average"), "2");
    EXPECT_EQ(frames[0].number("cluster_predicted_ms"), 4.25);
    EXPECT_EQ(frames[0].number("cluster_budget_ms"), 16.5);
    EXPECT_EQ(frames[0].at("cluster_fades"), "2");
    EXPECT_EQ(frames[0].number("cluster_selected_ms"), 3.5);
    EXPECT_EQ(frames[0].number("cluster_cheapest_ms"), 0.125);
    EXPECT_EQ(frames[0].number("cluster_target_ms"), 40.0);
    EXPECT_EQ(frames[0].number("cluster_predicted_frame_ms"), 38.25);
    EXPECT_EQ(frames[0].number("cluster_floor_ms"), 24.5);
    EXPECT_EQ(frames[0].at("geometry_fallbacks"), "2");
    EXPECT_EQ(frames[0].at("textures_baked"), "40");
    EXPECT_EQ(frames[0].at("textures_baked_now"), "3");
    EXPECT_EQ(frames[0].at("textures_to_bake"), "7");
    EXPECT_EQ(frames[0].at("baker_busy"), "1");
    // Poses read back to the same double (replays are compared exactly).
    EXPECT_EQ(std::strtod(frames[0].at("head_y").c_str(), nullptr), head.y);
    EXPECT_EQ(std::strtod(frames[1].at("t").c_str(), nullptr), 1.0 / 60.0);
    EXPECT_EQ(frames[0].number("world_x"), -37.0);

    const test::CsvTable walls = test::readCsv(folder / "walls.csv");
    ASSERT_EQ(walls.size(), 1u);
    EXPECT_EQ(walls[0].at("wall"), "A|B");
    EXPECT_EQ(walls[0].at("textures"), "7:0.25;8:0.75");
    EXPECT_EQ(walls[0].at("fallback"), "1");
    EXPECT_EQ(walls[0].at("beyond"), "0");
    EXPECT_EQ(walls[0].number("err_deg"), 3.5);
    EXPECT_EQ(walls[0].at("over_alpha"), "1");
}

TEST(RunOutput, AnUnwritableFolderIsAClearError) {
    const test::TempFolder folder("run_output_bad");
    test::writeFile(folder / "file", "x");  // a file where the folder should go
    const scenes::SceneDescription d = twoCells();
    const display::Display display(config::loadDisplayConfig("cave4"));
    EXPECT_THROW(RunOutput(folder / "file" / "out", d, display), Error);
}

}  // namespace
}  // namespace cavewall::app::gl
