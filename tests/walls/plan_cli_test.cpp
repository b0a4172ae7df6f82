#include "scenes/image_io.h"
#include "tests/support/run_cli.h"
#include "walls/angular_error.h"
#include "walls/depth_wall.h"
#include "walls/plan.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <fstream>
#include <iterator>
#include <sys/stat.h>
#include <tuple>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::filesystem::path outputDir() {
    const char* env = std::getenv("CAVEWALL_TEST_OUTPUT");
    const std::filesystem::path dir = std::filesystem::path(env ? env : "/tmp") / "plan_cli";
    std::filesystem::create_directories(dir);
    return dir;
}

glm::dvec3 vec3(const nlohmann::json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}; }

TEST(PlanCli, PlansAGeneratedHouseAndTheJsonKeepsTheBound) {
    const auto dir = outputDir();
    const CliResult gen = runCavewall({"generate", "house", "--out", (dir / "house").string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const CliResult r =
        runCavewall({"plan", (dir / "house").string(), "--alpha", "12", "--json", (dir / "house.plan.json").string(),
                     "--png", (dir / "house.plan.png").string(), "--png-walls", (dir / "house.walls.png").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("alpha 12°"));
    EXPECT_THAT(r.out, HasSubstr("GPU"));
    // Every edge the house's cells share is covered: no cells see each other directly.
    EXPECT_THAT(r.out, Not(HasSubstr("see each other directly")));
    // The overview (gnuplot): one storey panel 760 pixels wide beside a 400-pixel legend strip.
    EXPECT_EQ(scenes::readImage(dir / "house.plan.png").width, 760 + 400);
    EXPECT_TRUE(std::filesystem::file_size(dir / "house.walls.png") > 100);  // the per-wall detail
    std::ifstream in(dir / "house.plan.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["alphaDeg"], 12.0);
    ASSERT_FALSE(j["walls"].empty());
    for (const auto& w : j["walls"]) EXPECT_TRUE(w["depthBehind"].is_number());  // the scene is loaded
    // Check the bound from the file alone, as an outside tool would: every texture a zone
    // draws, at every vertex of the zone, for scene points at any depth (the vertices give the
    // exact zone maximum in that case, angular_error.h), and at the file's depthBehind.
    int checked = 0;
    for (const auto& z : j["zones"]) {
        if (z["kind"] == "geometry") continue;
        const auto& w = j["walls"][z["wall"].get<int>()];
        const walls::ScreenQuad quad{vec3(w["lowerLeft"]), vec3(w["lowerRight"]), vec3(w["upperLeft"])};
        const nlohmann::json points =
            z["kind"] == "texture" ? nlohmann::json::array({z["samplingPoint"]}) : z["samplingPoints"];
        for (const auto& s : points)
            for (const auto& v : z["floorPolygon"])
                for (double y : {z["heightRange"][0].get<double>(), z["heightRange"][1].get<double>()}) {
                    const glm::dvec3 eye(v[0].get<double>(), y, v[1].get<double>());
                    ASSERT_LE(walls::maxAngularError(eye, vec3(s), quad), glm::radians(12.0));
                    ASSERT_LE(walls::maxAngularError(eye, vec3(s), quad, w["depthBehind"].get<double>()),
                              walls::maxAngularError(eye, vec3(s), quad));
                    ++checked;
                }
    }
    EXPECT_GT(checked, 100);
}

// Depth walls: the JSON names the kind and each wall's depth span, and every texture a zone
// draws is within alpha at every zone vertex by the depth walls' own bound, recomputed from the
// file alone (span, sampling point, resolution).
TEST(PlanCli, DepthWallsJsonKeepsTheirOwnBound) {
    const auto dir = outputDir();
    const CliResult gen = runCavewall({"generate", "house", "--out", (dir / "house").string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const CliResult r = runCavewall({"plan", (dir / "house").string(), "--alpha", "12", "--walls", "depth", "--json",
                                     (dir / "house.depth.json").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("depth walls: largest texture error bound"));
    std::ifstream in(dir / "house.depth.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["wallKind"], "depth");
    std::map<std::tuple<int, int, double, double, double>, nlohmann::json> textures;
    for (const auto& t : j["textures"]) {
        EXPECT_LE(t["maxError"].get<double>(), glm::radians(12.0));
        const glm::dvec3 s = vec3(t["samplingPoint"]);
        textures[{t["cell"].get<int>(), t["wall"].get<int>(), s.x, s.y, s.z}] = t;
    }
    int checked = 0;
    for (const auto& z : j["zones"]) {
        if (z["kind"] == "geometry") continue;
        const auto& w = j["walls"][z["wall"].get<int>()];
        const walls::ScreenQuad quad{vec3(w["lowerLeft"]), vec3(w["lowerRight"]), vec3(w["upperLeft"])};
        const glm::dvec2 span(w["depthNear"].get<double>(), w["depthBehind"].get<double>());
        const nlohmann::json points =
            z["kind"] == "texture" ? nlohmann::json::array({z["samplingPoint"]}) : z["samplingPoints"];
        for (const auto& p : points) {
            const glm::dvec3 s = vec3(p);
            const nlohmann::json& t = textures.at({z["cell"].get<int>(), z["wall"].get<int>(), s.x, s.y, s.z});
            const glm::ivec2 resolution(t["resolution"][0].get<int>(), t["resolution"][1].get<int>());
            for (const auto& v : z["floorPolygon"])
                for (double y : {z["heightRange"][0].get<double>(), z["heightRange"][1].get<double>()}) {
                    const glm::dvec3 eye(v[0].get<double>(), y, v[1].get<double>());
                    // The per-eye bound the frame planner checks (walls::textureErrorAt): the
                    // smaller of the span and segment forms.
                    const double h = walls::texelDiagonal(quad, resolution);
                    const double bound = std::min(walls::depthEyeBound(eye, s, quad, span, h),
                                                  walls::depthSegmentEyeBound(eye, s, quad, span, h));
                    ASSERT_LE(bound, t["maxError"].get<double>() + 1e-12);
                    ++checked;
                }
        }
    }
    EXPECT_GT(checked, 100);
}

// Without gnuplot on PATH, --png stops before planning with what to install and where it
// looked, and writes nothing.
TEST(PlanCli, PngWithoutGnuplotSaysWhatToInstall) {
    const auto dir = outputDir() / "no-gnuplot";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "empty-bin");
    const CliResult gen = runCavewall({"generate", "house", "--out", (dir / "house").string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const char* oldPath = std::getenv("PATH");
    const std::string saved = oldPath ? oldPath : "";
    ::setenv("PATH", (dir / "empty-bin").c_str(), 1);  // the child inherits it
    const CliResult r = runCavewall({"plan", (dir / "house").string(), "--png", (dir / "plan.png").string()});
    ::setenv("PATH", saved.c_str(), 1);
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_THAT(
        r.err,
        HasSubstr("gnuplot not found: install gnuplot-nox (searched PATH: " + (dir / "empty-bin").string() + ")"));
    EXPECT_FALSE(std::filesystem::exists(dir / "plan.png"));
}

TEST(PlanCli, BadArgumentsFailClearly) {
    const struct {
        std::vector<std::string> args;
        const char* message;
    } cases[] = {
        {{"plan"}, "SCENE"},
        {{"plan", "/nonexistent/scene.json"}, "/nonexistent/scene.json"},
        {{"plan", "x", "--alpha", "0"}, "--alpha"},
        {{"plan", "x", "--alhpa", "10"}, "alhpa"},
        {{"plan", "x", "--walls", "deep"}, "--walls: expected a wall kind, flat or depth, got \"deep\""},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.message);
        const CliResult r = runCavewall(c.args);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

// `cavewall walls`: proposes cells and walls for the generated house (its own cells and walls
// replaced), writes a scene.json that `plan` accepts and a diagram.
TEST(WallsCli, ProposesWallsThatPlanAccepts) {
    const auto dir = outputDir();
    const CliResult gen =
        runCavewall({"generate", "house", "--out", (dir / "auto-house").string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    std::filesystem::create_directories(dir / "auto-proposal");
    const auto scene = dir / "auto-proposal" / "scene.json";
    const CliResult r = runCavewall({"walls", (dir / "auto-house").string(), "--out", scene.string(), "--png",
                                     (dir / "auto-proposal" / "top.png").string(), "--max-cells", "3", "--max-res",
                                     "64", "--min-cell", "2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("<- chosen"));
    EXPECT_THAT(r.out, HasSubstr("(the input's own cells and walls)"));
    EXPECT_THAT(r.err, HasSubstr("are replaced"));
    EXPECT_GT(std::filesystem::file_size(dir / "auto-proposal" / "top.png"), 100u);
    // The proposal names the model relative to its own folder and plans.
    const CliResult plan = runCavewall({"plan", scene.string()});
    EXPECT_EQ(plan.exitCode, 0) << plan.err;
    // --keep-paths keeps the house's own walk path (checked inside the proposed cells); a bare
    // model has none to keep.
    const auto kept = dir / "auto-proposal" / "kept.json";
    const CliResult k = runCavewall({"walls", (dir / "auto-house").string(), "--out", kept.string(), "--max-cells", "3",
                                     "--max-res", "64", "--min-cell", "2", "--keep-paths"});
    ASSERT_EQ(k.exitCode, 0) << k.err;
    auto walkPath = [](const std::filesystem::path& file) {
        std::ifstream in(file);
        return nlohmann::json::parse(in).at("walkPath");
    };
    EXPECT_FALSE(walkPath(dir / "auto-house" / "scene.json").empty());
    EXPECT_EQ(walkPath(kept), walkPath(dir / "auto-house" / "scene.json"));
    EXPECT_NE(walkPath(scene), walkPath(kept));  // without the flag: the proposal's own loop
    const CliResult bare = runCavewall({"walls", (dir / "auto-house" / "house.glb").string(), "--out",
                                        (dir / "auto-proposal" / "bare.json").string(), "--max-cells", "2", "--max-res",
                                        "32", "--keep-paths"});
    EXPECT_NE(bare.exitCode, 0);
    EXPECT_THAT(bare.err, HasSubstr("--keep-paths: expected a walkPath in"));
    EXPECT_FALSE(std::filesystem::exists(dir / "auto-proposal" / "bare.json"));
}

// `walls` writes what it planned the proposal with ("planning": --min-zone and --max-res), so
// that `plan` without the flags plans the same zones and textures, and a flag still wins; a
// proposal made from that scene keeps them.
TEST(WallsCli, ThePlanningOptionsAreWrittenToTheProposalAndPlannedWith) {
    const auto dir = outputDir();
    const CliResult gen =
        runCavewall({"generate", "house", "--out", (dir / "zone-house").string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const auto scene = dir / "zone-house" / "proposal.json";
    const CliResult r = runCavewall({"walls", (dir / "zone-house").string(), "--out", scene.string(), "--max-cells",
                                     "3", "--max-res", "64", "--min-cell", "2", "--min-zone", "3"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto planning = [](const std::filesystem::path& file) {
        std::ifstream in(file);
        return nlohmann::json::parse(in).value("planning", nlohmann::json());
    };
    EXPECT_EQ(planning(scene), nlohmann::json({{"minZone", 3.0}, {"maxRes", 64}}));
    EXPECT_THAT(r.out, HasSubstr("planned with zones of at least 3 m and textures of at most 64 texels"));
    // The house's own cells and walls with a zone size of their own.
    nlohmann::json house;
    std::ifstream(dir / "zone-house" / "scene.json") >> house;
    house["planning"] = {{"minZone", 3.0}, {"maxRes", 64}};
    const auto zoned = dir / "zone-house" / "zoned.json";
    std::ofstream(zoned) << house.dump();
    const CliResult own = runCavewall({"plan", zoned.string()});
    const CliResult given = runCavewall({"plan", zoned.string(), "--min-zone", "3"});
    const CliResult smaller = runCavewall({"plan", zoned.string(), "--min-zone", "1"});
    ASSERT_EQ(own.exitCode, 0) << own.err;
    ASSERT_EQ(smaller.exitCode, 0) << smaller.err;
    EXPECT_THAT(own.out, HasSubstr("capped at 64 texels per side"));
    EXPECT_EQ(own.out, given.out);
    EXPECT_NE(own.out, smaller.out);
    // A zone size the blend strips do not fit is named where it comes from.
    house["planning"] = {{"minZone", 0.3}};
    std::ofstream(zoned) << house.dump();
    const CliResult narrow = runCavewall({"plan", zoned.string()});
    EXPECT_NE(narrow.exitCode, 0);
    EXPECT_THAT(narrow.err, HasSubstr("planning.minZone: expected more than twice the blend width (0.4 m), got 0.3 m "
                                      "(or give --min-zone)"));
    const auto again = dir / "zone-house" / "again.json";
    const CliResult k =
        runCavewall({"walls", scene.string(), "--out", again.string(), "--max-cells", "3", "--min-cell", "2"});
    ASSERT_EQ(k.exitCode, 0) << k.err;
    EXPECT_EQ(planning(again), nlohmann::json({{"minZone", 3.0}, {"maxRes", 64}}));
    // A scene not written by `walls` has none: the commands' own defaults.
    EXPECT_TRUE(planning(dir / "zone-house" / "scene.json").is_null());
}

// A real model exported as one mesh (SponzaLOD4: 187 k triangles, one object) has nothing a
// cell could leave out until it is cut into chunks: `walls` cuts it, proposes more than one
// cell and writes "splitMetres" so that loading the proposal cuts it the same way.
TEST(WallsCli, CutsAOneMeshRealModelIntoChunksAndProposesCells) {
    const auto dir = outputDir();
    const std::filesystem::path model =
        std::filesystem::path(CAVEWALL_REAL_SCENES) / "SponzaLOD4" / "sponza_s_lod4.glb";
    ASSERT_TRUE(std::filesystem::exists(model)) << model;
    std::filesystem::create_directories(dir / "auto-sponza");
    const auto scene = dir / "auto-sponza" / "scene.json";
    const CliResult r =
        runCavewall({"walls", model.string(), "--out", scene.string(), "--max-cells", "3", "--max-res", "32"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("split: 1 content object(s) wider than 8.0 m hold 100 % of the content triangles; "
                                 "models cut into chunks of 2.00 m: 1 objects -> "));
    std::ifstream in(scene);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["models"][0]["splitMetres"].get<double>(), 2.0);
    EXPECT_GT(j["cells"].size(), 1u);
    const CliResult plan = runCavewall({"plan", scene.string()});
    EXPECT_EQ(plan.exitCode, 0) << plan.err;
    // --split 0 leaves the one mesh whole: one cell is all a proposal can be.
    const CliResult whole =
        runCavewall({"walls", model.string(), "--out", (dir / "auto-sponza" / "whole.json").string(), "--max-cells",
                     "3", "--max-res", "32", "--split", "0"});
    ASSERT_EQ(whole.exitCode, 0) << whole.err;
    EXPECT_THAT(whole.out, Not(HasSubstr("split:")));
    EXPECT_THAT(whole.out, HasSubstr("(1 cells, 0 virtual walls, 0 portals)"));
}

TEST(WallsCli, BadInputSaysWhatIsWrong) {
    const auto dir = outputDir();
    const CliResult noOut = runCavewall({"walls", (dir / "nowhere.glb").string()});
    EXPECT_NE(noOut.exitCode, 0);
    EXPECT_THAT(noOut.err, HasSubstr("--out"));
    const CliResult badBudget = runCavewall(
        {"walls", (dir / "nowhere.glb").string(), "--out", (dir / "x.json").string(), "--texture-budget", "-3"});
    EXPECT_NE(badBudget.exitCode, 0);
    EXPECT_THAT(badBudget.err, HasSubstr("--texture-budget"));
    EXPECT_FALSE(std::filesystem::exists(dir / "x.json"));
}

std::string bytesOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Writing replaces the path, so `walls` and `plan` refuse an output that exists and is not a
// regular file (a device such as /dev/null or /dev/full would become a regular file, exit 0)
// and an output that is one of their inputs (the model or the scene.json would be lost); each
// refusal says which, before any work, and leaves the path as it was.
TEST(WritersCli, OutputsThatAreNotRegularFilesOrInputsAreRefused) {
    const auto dir = outputDir() / "writers";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "folder");
    const auto house = dir / "house";
    const CliResult gen = runCavewall({"generate", "house", "--out", house.string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const auto fifo = dir / "fifo", link = dir / "link-to-folder", glb = house / "house.glb",
               json = house / "scene.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    std::filesystem::create_directory_symlink(dir / "folder", link);
    const std::string model = bytesOf(glb), scene = bytesOf(json);
    const std::string notRegular = ": expected a regular file or a new name, got ";
    const std::string anInput = ": expected a file apart from the command's inputs, got the input ";
    const struct {
        const char* name;
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {"walls --out /dev/null",
         {"walls", house.string(), "--out", "/dev/null"},
         "--out /dev/null" + notRegular + "a character device"},
        {"walls --png fifo",
         {"walls", house.string(), "--out", (dir / "w.json").string(), "--png", fifo.string()},
         "--png " + fifo.string() + notRegular + "a fifo"},
        {"walls --out MODEL",
         {"walls", glb.string(), "--out", glb.string()},
         "--out " + glb.string() + anInput + glb.string()},
        {"walls --out its scene.json",
         {"walls", house.string(), "--out", json.string()},
         "--out " + json.string() + anInput + json.string()},
        {"walls --png MODEL",
         {"walls", json.string(), "--out", (dir / "w.json").string(), "--png", glb.string()},
         "--png " + glb.string() + anInput + glb.string()},
        {"plan --json /dev/null",
         {"plan", house.string(), "--json", "/dev/null"},
         "--json /dev/null" + notRegular + "a character device"},
        {"plan --png /dev/full",
         {"plan", house.string(), "--png", "/dev/full"},
         "--png /dev/full" + notRegular + "a character device"},
        {"plan --png link to a folder",
         {"plan", house.string(), "--png", link.string()},
         "--png " + link.string() + notRegular + "a directory"},
        {"plan --png-walls link to a folder",
         {"plan", house.string(), "--png-walls", link.string()},
         "--png-walls " + link.string() + notRegular + "a directory"},
        {"walls --png-walls MODEL",
         {"walls", json.string(), "--out", (dir / "w.json").string(), "--png-walls", glb.string()},
         "--png-walls " + glb.string() + anInput + glb.string()},
        {"plan --json its scene.json",
         {"plan", house.string(), "--json", json.string()},
         "--json " + json.string() + anInput + json.string()},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const CliResult r = runCavewall(c.args);
        EXPECT_EQ(r.exitCode, 1) << r.out;
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
    EXPECT_EQ(std::filesystem::status("/dev/null").type(), std::filesystem::file_type::character);
    EXPECT_EQ(std::filesystem::status("/dev/full").type(), std::filesystem::file_type::character);
    EXPECT_EQ(std::filesystem::status(fifo).type(), std::filesystem::file_type::fifo);
    EXPECT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_TRUE(std::filesystem::is_empty(dir / "folder"));
    EXPECT_EQ(bytesOf(glb), model);
    EXPECT_EQ(bytesOf(json), scene);
    EXPECT_FALSE(std::filesystem::exists(dir / "w.json"));  // refused before the work
}

// --min-cell 0.1, the smallest documented value, is accepted: the default --split (half of it)
// is held to its smallest chunk, 0.1 m; only a --split given below that is refused, by name.
TEST(WallsCli, TheSmallestMinCellIsAcceptedAndASmallSplitIsNamed) {
    const auto dir = outputDir() / "min-cell";
    std::filesystem::remove_all(dir);
    const CliResult gen = runCavewall({"generate", "house", "--out", (dir / "house").string(), "--triangles", "2000"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const CliResult r = runCavewall({"walls", (dir / "house").string(), "--out", (dir / "scene.json").string(),
                                     "--min-cell", "0.1", "--max-cells", "2", "--max-res", "32"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, Not(HasSubstr("--split")));
    EXPECT_TRUE(std::filesystem::exists(dir / "scene.json"));
    const CliResult small = runCavewall({"walls", (dir / "house").string(), "--out", (dir / "small.json").string(),
                                         "--min-cell", "0.1", "--split", "0.05"});
    EXPECT_EQ(small.exitCode, 1);
    EXPECT_THAT(small.err, HasSubstr("--split: expected 0 (no cutting) or at least 0.1 metres, got 0.05"));
}

}  // namespace
}  // namespace cavewall::test
