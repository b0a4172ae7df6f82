// End to end: the scripted VRPN server (the real VRPN server code) streams a head pose while a
// child `cavewall track --tracker vrpn:...` reads it; the child's CSV must show the pose.
#include "tests/support/csv_table.h"
#include "tests/support/files.h"
#include "tests/support/run_cli.h"
#include "tests/tools/track_run.h"
#include "tests/vrpn/server_process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <regex>
#include <string>

namespace cavewall::input {
namespace {

TEST(TrackVrpnCli, TheServersHeadReachesTheCsv) {
    const int port = test::freeTcpPort();
    test::VrpnServerProcess server(VRPN_TEST_SERVER, port, "Tracker0", 2);
    ASSERT_TRUE(server.ready()) << server.firstLine();
    const test::TempFolder dir("track_vrpn");
    const std::string csv = (dir / "head.csv").string();
    const std::string spec = "vrpn:Tracker0@127.0.0.1:" + std::to_string(port) + "?retry=0.05";
    test::CliProcess child(
        {"track", "--tracker", spec, "--seconds", "1.5", "--rate", "100", "--no-filter", "--csv", csv});
    // The child names its source before it starts polling; the server then sees it connect.
    ASSERT_TRUE(child.waitForLine(std::regex("track: vrpn Tracker0@127\\.0\\.0\\.1"), std::chrono::seconds(60)))
        << child.finish(std::chrono::seconds(1)).err;
    server.send("wait-client");
    ASSERT_EQ(server.answer(std::chrono::seconds(30)), "ok");
    // The head at (0.1, 1.6, -0.2) m, turned 90° about +Y, at about 100 Hz (a tracker's pace)
    // until the child ends.
    const test::CliResult r = test::sendUntilExit(child, std::chrono::seconds(60), [&](int) {
        ASSERT_EQ(server.command("pose 0 0.1 1.6 -0.2 0 0.70710678118654757 0 0.70710678118654757"), "ok");
    });
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::CsvTable table = test::readCsv(csv);
    EXPECT_EQ(table.columns, test::kTrackColumns);
    const std::optional<test::CsvRow> head = test::lastTrackedHead(table);
    ASSERT_TRUE(head) << "no tracked head in " << csv << "\n" << r.err;
    EXPECT_NEAR(head->number("head_x"), 0.1, 1e-6);
    EXPECT_NEAR(head->number("head_y"), 1.6, 1e-6);
    EXPECT_NEAR(head->number("head_z"), -0.2, 1e-6);
    EXPECT_NEAR(head->number("qy"), std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(head->number("qw"), std::sqrt(0.5), 1e-6);
    EXPECT_THAT(r.err, ::testing::HasSubstr("dropped 0 "));
    EXPECT_TRUE(server.quit());
}

}  // namespace
}  // namespace cavewall::input
