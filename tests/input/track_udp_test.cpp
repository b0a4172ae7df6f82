// End to end: this process sends DTrack packets over loopback UDP while a child
// `cavewall track` listens; the child's CSV must show the sent head after calibration.
#include "input/network_source.h"
#include "tests/support/run_cli.h"

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
    std::filesystem::path p = std::filesystem::path(dir ? dir : "/tmp") / "track_udp";
    std::filesystem::create_directories(p);
    return p;
}

// Sends `packet(i)` at about 100 Hz (a tracker's rate) until the child exits; kills it after
// `limit` (the test then fails, never hangs). Returns the child's result.
template <class Packet>
test::CliResult sendUntilExit(test::CliProcess& child, std::chrono::seconds limit, Packet packet) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    for (int i = 0; !child.exited() && std::chrono::steady_clock::now() < deadline; ++i) {
        packet(i);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));  // the tracker's pace
    }
    return child.finish(std::chrono::seconds(5));
}

TEST(TrackCli, DTrackSenderDrivesTheHeadThroughCalibration) {
    const auto dir = outputDir();
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
    const test::CliResult r = sendUntilExit(child, std::chrono::seconds(60), [&](int i) {
        sendUdp("127.0.0.1", port,
                "fr " + std::to_string(i) + "\n6d 1 [1 1.0][100 1600 -200 0 0 0][1 0 0 0 1 0 0 0 1]\n");
        if (i % 10 == 0) sendUdp("127.0.0.1", port, "\x7f garbage");
    });
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(csv);
    std::string line, lastTracked;
    std::getline(in, line);
    EXPECT_EQ(line, "t,head_x,head_y,head_z,qx,qy,qz,qw,dropped");
    while (std::getline(in, line))
        if (line.size() > 2 && line.substr(line.size() - 2) == ",0") lastTracked = line;
    ASSERT_FALSE(lastTracked.empty()) << "no tracked head in " << csv;
    std::istringstream row(lastTracked);
    double v[4];
    char comma;
    row >> v[0] >> comma >> v[1] >> comma >> v[2] >> comma >> v[3];
    // (0.1, 1.6, -0.2) m plus the calibration's (0, 0.1, -0.5): (0.1, 1.7, -0.7) in the cave.
    EXPECT_NEAR(v[1], 0.1, 1e-3);
    EXPECT_NEAR(v[2], 1.7, 1e-3);
    EXPECT_NEAR(v[3], -0.7, 1e-3);
    // Garbage was counted, not fatal.
    EXPECT_THAT(r.err, ::testing::MatchesRegex("(.|\n)*malformed [1-9][0-9]*(.|\n)*"));
}

}  // namespace
}  // namespace cavewall::input
