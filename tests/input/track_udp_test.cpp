// End to end: this process sends DTrack packets over loopback UDP while a child
// `cavewall track` listens; the child's CSV must show the sent head after calibration.
#include "input/network_source.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"
#include "tests/support/run_cli.h"
#include "tests/tools/track_run.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <string>

namespace cavewall::input {
namespace {

TEST(TrackCli, DTrackSenderDrivesTheHeadThroughCalibration) {
    const test::TempFolder dir("track_udp");
    // The tracker's origin is 0.1 m above and 0.5 m in front of the cave origin.
    std::ofstream(dir / "lab.json") << R"({"screens": [{"name": "front", "lowerLeft": [-1.5, 0, -1.5],
        "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, 3, -1.5], "resolution": [64, 64]}],
        "tracking": {"caveFromTracker": [[1,0,0,0],[0,1,0,0.1],[0,0,1,-0.5],[0,0,0,1]]}})";
    const std::string csv = (dir / "head.csv").string(), display = (dir / "lab.json").string();
    // Port 0: the child binds a free port and names it on stderr before it starts polling.
    test::CliProcess child({"track", "--tracker", "dtrack:udp://127.0.0.1:0", "--display", display, "--seconds", "2.5",
                            "--rate", "100", "--csv", csv});
    const auto listening =
        child.waitForLine(std::regex("listening on 127\\.0\\.0\\.1:([0-9]+)"), std::chrono::seconds(60));
    ASSERT_TRUE(listening) << child.finish(std::chrono::seconds(1)).err;
    const int port = std::stoi((*listening)[1]);
    // Head (body 1) at (100, 1600, -200) mm at 100 Hz while the child runs, with a garbage
    // datagram every 10th.
    const test::CliResult r = test::sendUntilExit(child, std::chrono::seconds(60), [&](int i) {
        sendUdp("127.0.0.1", port,
                "fr " + std::to_string(i) + "\n6d 1 [1 1.0][100 1600 -200 0 0 0][1 0 0 0 1 0 0 0 1]\n");
        if (i % 10 == 0) sendUdp("127.0.0.1", port, "\x7f garbage");
    });
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::CsvTable table = test::readCsv(csv);
    EXPECT_EQ(table.columns, test::kTrackColumns);
    const std::optional<test::CsvRow> head = test::lastTrackedHead(table);
    ASSERT_TRUE(head) << "no tracked head in " << csv;
    // (0.1, 1.6, -0.2) m plus the calibration's (0, 0.1, -0.5): (0.1, 1.7, -0.7) in the cave.
    EXPECT_NEAR(head->number("head_x"), 0.1, 1e-3);
    EXPECT_NEAR(head->number("head_y"), 1.7, 1e-3);
    EXPECT_NEAR(head->number("head_z"), -0.7, 1e-3);
    // Garbage was counted, not fatal.
    EXPECT_THAT(r.err, ::testing::MatchesRegex("(.|\n)*malformed [1-9][0-9]*(.|\n)*"));
}

}  // namespace
}  // namespace cavewall::input
