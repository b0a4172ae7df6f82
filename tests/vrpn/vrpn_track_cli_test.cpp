// End to end: the scripted VRPN server (the real VRPN server code) streams a head pose while a
// child `cavewall track --tracker vrpn:...` reads it; the child's CSV must show the pose.
#include "tests/support/run_cli.h"
#include "tests/vrpn/server_process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

namespace cavewall::input {
namespace {

std::filesystem::path outputDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    std::filesystem::path p = std::filesystem::path(dir ? dir : "/tmp") / "track_vrpn";
    std::filesystem::create_directories(p);
    return p;
}

TEST(TrackVrpnCli, TheServersHeadReachesTheCsv) {
    const int port = test::freeTcpPort();
    test::VrpnServerProcess server(VRPN_TEST_SERVER, port, "Tracker0", 2);
    ASSERT_TRUE(server.ready()) << server.firstLine();
    const std::string csv = (outputDir() / "head.csv").string();
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
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!child.exited() && std::chrono::steady_clock::now() < deadline) {
        ASSERT_EQ(server.command("pose 0 0.1 1.6 -0.2 0 0.70710678118654757 0 0.70710678118654757"), "ok");
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const test::CliResult r = child.finish(std::chrono::seconds(5));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(csv);
    std::string line, lastTracked;
    std::getline(in, line);
    EXPECT_EQ(line, "t,head_x,head_y,head_z,qx,qy,qz,qw,dropped");
    while (std::getline(in, line))
        if (line.size() > 2 && line.substr(line.size() - 2) == ",0") lastTracked = line;
    ASSERT_FALSE(lastTracked.empty()) << "no tracked head in " << csv << "\n" << r.err;
    std::istringstream row(lastTracked);
    double v[8];
    char comma;
    for (double& x : v) row >> x >> comma;
    EXPECT_NEAR(v[1], 0.1, 1e-6);
    EXPECT_NEAR(v[2], 1.6, 1e-6);
    EXPECT_NEAR(v[3], -0.2, 1e-6);
    EXPECT_NEAR(v[5], std::sqrt(0.5), 1e-6);  // qy
    EXPECT_NEAR(v[7], std::sqrt(0.5), 1e-6);  // qw
    EXPECT_THAT(r.err, ::testing::HasSubstr("dropped 0 "));
    EXPECT_TRUE(server.quit());
}

}  // namespace
}  // namespace cavewall::input
