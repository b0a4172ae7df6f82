// End to end: this process sends DTrack packets over loopback UDP while a child
// `cavewall track` listens; the child's CSV must show the sent head after calibration.
#include "input/network_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>

extern char** environ;

namespace cavewall::input {
namespace {

std::filesystem::path outputDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    std::filesystem::path p = std::filesystem::path(dir ? dir : "/tmp") / "track_udp";
    std::filesystem::create_directories(p);
    return p;
}

// Sends `packet(i)` at about 100 Hz (a tracker's rate) until the child exits, so however late
// the child starts listening on a loaded machine it gets packets for its whole run; kills it
// after `limit` (the test then fails, never hangs). Returns the exit code, -1 on timeout.
template <class Packet>
int sendUntilExit(pid_t pid, std::chrono::seconds limit, Packet packet) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    int status = 0;
    for (int i = 0; waitpid(pid, &status, WNOHANG) == 0; ++i) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            ADD_FAILURE() << "cavewall track did not finish in time";
            return -1;
        }
        packet(i);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));  // the tracker's pace
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(TrackCli, DTrackSenderDrivesTheHeadThroughCalibration) {
    const auto dir = outputDir();
    int port = 0;
    {
        UdpReceiver probe("127.0.0.1", 0);  // ask the OS for a free port, then free it for the child
        port = probe.port();
    }
    // The tracker's origin is 0.1 m above and 0.5 m in front of the cave origin.
    std::ofstream(dir / "lab.json") << R"({"screens": [{"name": "front", "lowerLeft": [-1.5, 0, -1.5],
        "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, 3, -1.5], "resolution": [64, 64]}],
        "tracking": {"caveFromTracker": [[1,0,0,0],[0,1,0,0.1],[0,0,1,-0.5],[0,0,0,1]]}})";
    const std::string spec = "dtrack:udp://127.0.0.1:" + std::to_string(port);
    const std::string csv = (dir / "head.csv").string(), display = (dir / "lab.json").string(), log = (dir / "stderr.txt").string();
    std::vector<std::string> words = {CAVEWALL_EXE, "track", "--tracker", spec, "--display", display,
                                      "--seconds", "2.5", "--rate", "100", "--csv", csv};
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, CAVEWALL_EXE, &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    // Head (body 1) at (100, 1600, -200) mm at 100 Hz while the child runs, with a garbage
    // datagram every 10th.
    ASSERT_EQ(sendUntilExit(pid, std::chrono::seconds(60), [&](int i) {
                  sendUdp("127.0.0.1", port,
                          "fr " + std::to_string(i) + "\n6d 1 [1 1.0][100 1600 -200 0 0 0][1 0 0 0 1 0 0 0 1]\n");
                  if (i % 10 == 0) sendUdp("127.0.0.1", port, "\x7f garbage");
              }),
              0);
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
    std::stringstream err;
    err << std::ifstream(log).rdbuf();
    // Garbage was counted, not fatal (some early datagrams may arrive before the child listens).
    EXPECT_THAT(err.str(), ::testing::MatchesRegex("(.|\n)*malformed [1-9][0-9]*(.|\n)*"));
}

}  // namespace
}  // namespace cavewall::input
