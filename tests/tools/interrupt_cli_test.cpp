// Ctrl+C ends `cavewall run` within a frame, with complete files and the summary (app/interrupt.h).
#include "tests/tools/run_cli_support.h"
#include "tests/support/csv_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iterator>
#include <regex>
#include <thread>

namespace cavewall::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Complete lines (ended by '\n') in `file` so far; 0 while it does not exist.
long completeLines(const fs::path& file) {
    const std::string text = readText(file);
    return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

// Polls `file` until it holds `lines` complete lines, the run ends, or a minute passes.
bool waitForLines(CliProcess& run, const fs::path& file, long lines) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (completeLines(file) < lines) {
        if (run.exited() || std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a polling interval, not a wait for a state
    }
    return true;
}

TEST(RunInterrupt, CtrlCEndsTheRunWithCompleteFilesAndTheSummary) {
    const fs::path out = outputDir("interrupt");
    std::vector<std::string> args = wallRun(out, "sim:walk?seed=3", 100000);
    args.insert(args.end(), {"--resolution", "64x64"});
    CliProcess run(args);
    // The header and 10 frames' rows (the files are flushed after every frame).
    ASSERT_TRUE(waitForLines(run, out / "frames.csv", 11)) << run.finish(std::chrono::seconds(10)).err;
    run.signal(SIGINT);
    const CliResult r = run.finish(std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.err;
    // The summary, with the frames drawn, and how the run ended.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex("run: ([0-9]+) frames on "))) << r.out;
    EXPECT_THAT(r.out, HasSubstr("run: stopped after " + m[1].str() + " frames: interrupted"));
    // Every row complete (parseCsv refuses a row with fewer cells than the header) and ended
    // by a line break; one row per frame drawn, numbered 0, 1, ...
    const std::string frames = readText(out / "frames.csv");
    ASSERT_FALSE(frames.empty());
    EXPECT_EQ(frames.back(), '\n');
    const CsvTable rows = parseCsv(frames, "frames.csv");
    ASSERT_EQ(rows.size(), std::stoul(m[1]));
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i].at("frame"), std::to_string(i));
    // walls.csv: complete too, and it has the rows of the frames drawn (the plant has walls).
    const std::string walls = readText(out / "walls.csv");
    EXPECT_EQ(walls.back(), '\n');
    const CsvTable wallRows = parseCsv(walls, "walls.csv");
    EXPECT_FALSE(wallRows.empty());
    EXPECT_EQ(wallRows.back().at("frame"), rows.back().at("frame"));
}

// Texture files written so far under `folder` (a bake cache).
int textureFiles(const fs::path& folder) {
    int n = 0;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".bct" || it->path().extension() == ".tx") ++n;
    return n;
}

TEST(RunInterrupt, CtrlCWhileBakingStopsTheBakeKeepingWhatWasFinished) {
    const fs::path out = outputDir("interrupt-bake");
    const fs::path cache = out / "cache";  // empty: the run must bake before its first frame
    // A fine plan (many small zones) bakes for much longer than the test waits.
    std::vector<std::string> args = wallRun(out / "run", "sim:walk?seed=3", 100);
    for (std::size_t i = 0; i + 1 < args.size(); ++i) {
        if (args[i] == "--alpha") args[i + 1] = "2";
        if (args[i] == "--min-zone") args[i + 1] = "0.5";
        if (args[i] == "--cache") args[i + 1] = cache.string();
    }
    args.insert(args.end(), {"--resolution", "64x64"});
    CliProcess run(args);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (textureFiles(cache) < 2) {  // baking has begun
        ASSERT_FALSE(run.exited()) << run.finish(std::chrono::seconds(5)).err;
        ASSERT_LT(std::chrono::steady_clock::now(), deadline);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a polling interval, not a wait for a state
    }
    run.signal(SIGINT);
    const CliResult r = run.finish(std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.err;
    EXPECT_THAT(r.out, HasSubstr("; stopped before the rest)"));
    EXPECT_THAT(r.out, HasSubstr("run: stopped before the first frame: interrupted"));
    // The output files are complete: each a header line and no row.
    for (const char* file : {"frames.csv", "walls.csv"}) {
        SCOPED_TRACE(file);
        const std::string text = readText(out / "run" / file);
        ASSERT_FALSE(text.empty());
        EXPECT_EQ(text.back(), '\n');
        EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
        EXPECT_TRUE(parseCsv(text, file).empty());
    }
    // What was finished is listed for the next run: a manifest naming fewer textures than the plan.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex("walls: ([0-9]+) textures in .* \\(([0-9]+) baked now")))
        << r.out;
    EXPECT_GT(std::stoi(m[2]), 0);
    EXPECT_LT(std::stoi(m[2]), std::stoi(m[1]));
    int manifests = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(cache))
        manifests += e.path().filename() == "manifest.json";
    EXPECT_EQ(manifests, 1);
}

}  // namespace
}  // namespace cavewall::test
