// cavewall's VRPN client (input/vrpn_client.h) against the real VRPN server code: a scripted
// vrpn_Tracker_Server and vrpn_Button_Server (vrpn_test_server.cpp) on loopback TCP. Poses and
// buttons must arrive as sent, a server that stops and comes back must be used again, and the
// client's latency is measured and printed.
#include "input/vrpn_client.h"
#include "tests/vrpn/server_process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <sys/time.h>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;
using Clock = std::chrono::steady_clock;

constexpr double kPositionTolerance = 1e-6;  // metres: 1 µm
constexpr double kAngleTolerance = 1e-6;     // radians

double seconds(Clock::time_point t) { return std::chrono::duration<double>(t.time_since_epoch()).count(); }

double wallClock() {
    timeval t{};
    ::gettimeofday(&t, nullptr);
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

// The angle of the rotation from a to b, radians (accurate near zero, unlike acos).
double angleBetween(const glm::dquat& a, const glm::dquat& b) {
    const glm::dquat d = glm::inverse(a) * b;
    return 2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::fabs(d.w));
}

struct Fixture {
    int port = test::freeTcpPort();
    std::unique_ptr<test::VrpnServerProcess> server;
    std::unique_ptr<VrpnSource> client;

    void startServer() {
        server = std::make_unique<test::VrpnServerProcess>(VRPN_TEST_SERVER, port, "Tracker0", 2);
        ASSERT_TRUE(server->ready()) << "server: " << server->firstLine();
    }
    void makeClient(bool udp = false) {
        VrpnConfig c;
        c.udp = udp;
        c.host = "127.0.0.1";
        c.port = port;
        c.retrySeconds = 0.05;
        c.staleSeconds = 60.0;  // the test waits on messages, not on a frame rate
        client = std::make_unique<VrpnSource>(c);
    }
    Sample poll() { return client->poll(seconds(Clock::now())); }
    // Polls, waiting on the client between polls, until `done` holds; at most 5 s.
    template <class Done>
    Sample pollUntil(Done done) {
        const auto deadline = Clock::now() + std::chrono::seconds(5);
        Sample s = poll();
        while (!done(s) && Clock::now() < deadline) {
            client->wait(seconds(Clock::now()), 0.05);
            s = poll();
        }
        EXPECT_TRUE(done(s)) << "timed out; client: " << client->problem();
        return s;
    }
    // Connects the client, and waits until the server has the connection too (a server drops
    // what it sends before that).
    void connect() {
        pollUntil([&](const Sample&) { return client->connected(); });
        ASSERT_EQ(server->command("wait-client"), "ok");
    }
    // Sends a pose and returns the client's sample once the pose was accepted.
    Sample sendPose(int sensor, glm::dvec3 p, glm::dquat q) {
        char line[512];
        std::snprintf(line, sizeof line, "pose %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g", sensor, p.x, p.y, p.z,
                      q.x, q.y, q.z, q.w);
        const std::uint64_t before = client->stats().accepted;
        server->send(line);
        const Sample s = pollUntil([&](const Sample&) { return client->stats().accepted > before; });
        EXPECT_EQ(server->answer(), "ok");
        return s;
    }
};

// Poses spread over a CAVE-sized volume, in every orientation.
std::vector<std::pair<glm::dvec3, glm::dquat>> scriptedPoses(int n) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(-1.5, 1.5), angle(-3.1, 3.1), unit(-1.0, 1.0);
    std::vector<std::pair<glm::dvec3, glm::dquat>> poses;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)) + glm::dvec3(1e-3));
        poses.emplace_back(glm::dvec3(coord(rng), 1.0 + coord(rng) / 3.0, coord(rng)),
                           glm::angleAxis(angle(rng), axis));
    }
    return poses;
}

// Over TCP only (udp=0), and with the tracker reports as UDP datagrams (udp=1).
class VrpnLoopbackChannel : public ::testing::TestWithParam<bool> {};

TEST_P(VrpnLoopbackChannel, PosesAndButtonsArriveAsTheServerSentThem) {
    const bool udp = GetParam();
    Fixture f;
    ASSERT_NO_FATAL_FAILURE(f.startServer());
    f.makeClient(udp);
    ASSERT_NO_FATAL_FAILURE(f.connect());
    const auto poses = scriptedPoses(20);
    for (std::size_t i = 0; i < poses.size(); ++i) {
        SCOPED_TRACE(i);
        const int sensor = static_cast<int>(i % 2);  // 0 = head, 1 = hand (the spec's defaults)
        const Sample s = f.sendPose(sensor, poses[i].first, poses[i].second);
        const Pose& got = sensor == 0 ? s.head : s.hand;
        EXPECT_TRUE(sensor == 0 ? s.headValid : s.handValid);
        EXPECT_LE(glm::length(got.position - poses[i].first), kPositionTolerance);
        EXPECT_LE(angleBetween(got.orientation, poses[i].second), kAngleTolerance);
    }
    // Buttons: press 0, press 2, release 0 (the wand's trigger is button 0).
    const std::pair<const char*, std::uint32_t> steps[] = {
        {"button 0 1", 0b001u}, {"button 2 1", 0b101u}, {"button 0 0", 0b100u}};
    for (const auto& [command, mask] : steps) {
        SCOPED_TRACE(command);
        f.server->send(command);
        const Sample s = f.pollUntil([&](const Sample& s) { return s.wand.buttons == mask; });
        EXPECT_EQ(s.wand.buttons, mask);
        EXPECT_EQ(f.server->answer(), "ok");
    }
    const SourceStats stats = f.client->stats();
    EXPECT_EQ(stats.dropped(), 0u);
    // With udp=1 the server switches to UDP once it has read the client's UDP description, a
    // moment after the connection: all but the first poses or so come that way.
    if (udp)
        EXPECT_GE(f.client->udpMessages(), 15u);
    else
        EXPECT_EQ(f.client->udpMessages(), 0u);
    EXPECT_EQ(f.client->problem(), "");
    EXPECT_TRUE(f.server->quit());
}

TEST_P(VrpnLoopbackChannel, AServerThatStopsAndComesBackIsUsedAgain) {
    Fixture f;
    ASSERT_NO_FATAL_FAILURE(f.startServer());
    f.makeClient(GetParam());
    ASSERT_NO_FATAL_FAILURE(f.connect());
    Sample s = f.sendPose(0, {0.1, 1.6, 0.2}, glm::dquat(1.0, 0.0, 0.0, 0.0));
    EXPECT_TRUE(s.headValid);
    f.server->send("button 0 1");
    f.pollUntil([](const Sample& s) { return s.wand.pressed(0); });
    EXPECT_EQ(f.server->answer(), "ok");

    ASSERT_TRUE(f.server->quit());
    s = f.pollUntil([&](const Sample&) { return !f.client->problem().empty(); });
    EXPECT_FALSE(s.headValid);      // no server, no head: the drop-out policy takes over
    EXPECT_EQ(s.wand.buttons, 0u);  // and no button stays held
    EXPECT_THAT(f.client->problem(), HasSubstr("the server closed the connection; trying again every 0.05 s"));

    ASSERT_NO_FATAL_FAILURE(f.startServer());  // the same port
    ASSERT_NO_FATAL_FAILURE(f.connect());
    EXPECT_EQ(f.client->connections(), 2u);
    EXPECT_EQ(f.client->problem(), "");
    const glm::dquat turned = glm::angleAxis(0.5, glm::dvec3(0.0, 1.0, 0.0));
    s = f.sendPose(0, {-0.3, 1.7, 0.4}, turned);
    EXPECT_TRUE(s.headValid);
    EXPECT_LE(glm::length(s.head.position - glm::dvec3(-0.3, 1.7, 0.4)), kPositionTolerance);
    EXPECT_LE(angleBetween(s.head.orientation, turned), kAngleTolerance);
    EXPECT_TRUE(f.server->quit());
}

// 300 poses in a row, each one seen before the next is sent, with the latency printed (the
// figure is recorded in bench/results; like every timing in this project it is printed, not
// asserted, so a loaded machine cannot fail the test). Latency is measured two ways:
//  - client: from the moment the socket is readable (the bytes have arrived) to poll() returning
//    the pose; what the client adds;
//  - end to end: from the server's time stamp (taken just before it packs the message) to the
//    pose being available; adds the server's send and the loopback.
TEST_P(VrpnLoopbackChannel, ThreeHundredPosesInARowAndTheirLatency) {
    Fixture f;
    ASSERT_NO_FATAL_FAILURE(f.startServer());
    f.makeClient(GetParam());
    ASSERT_NO_FATAL_FAILURE(f.connect());
    std::vector<double> client, endToEnd;
    for (int i = 0; i < 300; ++i) {
        char line[128];
        std::snprintf(line, sizeof line, "pose 0 %.6f 1.7 0 0 0 0 1", 0.001 * i);
        const std::uint64_t before = f.client->stats().accepted;
        f.server->send(line);
        const auto deadline = Clock::now() + std::chrono::seconds(5);
        while (f.client->stats().accepted == before && Clock::now() < deadline) {
            f.client->wait(seconds(Clock::now()), 1.0);
            const auto arrived = Clock::now();
            f.poll();
            if (f.client->stats().accepted == before) continue;
            client.push_back(std::chrono::duration<double>(Clock::now() - arrived).count());
            endToEnd.push_back(wallClock() - f.client->lastReportTime());
            EXPECT_NEAR(f.poll().head.position.x, 0.001 * i, kPositionTolerance);
        }
        ASSERT_EQ(f.server->answer(), "ok");
    }
    ASSERT_EQ(client.size(), 300u);
    auto percentile = [](std::vector<double> v, double p) {
        std::sort(v.begin(), v.end());
        return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))] * 1e6;
    };
    std::printf(
        "vrpn loopback latency over %zu poses by %s (microseconds): client, socket readable to pose: median "
        "%.1f, p99 %.1f; end to end, server time stamp to pose: median %.1f, p99 %.1f\n",
        client.size(), GetParam() ? "UDP" : "TCP", percentile(client, 0.5), percentile(client, 0.99),
        percentile(endToEnd, 0.5), percentile(endToEnd, 0.99));
    EXPECT_TRUE(f.server->quit());
}

INSTANTIATE_TEST_SUITE_P(Vrpn, VrpnLoopbackChannel, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& p) { return p.param ? "Udp" : "Tcp"; });

}  // namespace
}  // namespace cavewall::input
