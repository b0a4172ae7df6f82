#include "input/network_source.h"
#include "input/pose_math.h"
#include "input/tracking_pipeline.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cstring>
#include <thread>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

NetworkSource& network(std::unique_ptr<TrackerSource>& s) {
    auto* n = dynamic_cast<NetworkSource*>(s.get());
    EXPECT_NE(n, nullptr);
    return *n;
}

// Polls until `done` holds or 3 s pass (a bounded wait: the test fails instead of hanging).
template <class Done>
Sample pollUntil(TrackerSource& source, Done done) {
    const auto start = std::chrono::steady_clock::now();
    Sample s;
    while (std::chrono::steady_clock::now() - start < std::chrono::seconds(3)) {
        s = source.poll(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (done(s)) return s;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ADD_FAILURE() << "timed out waiting for packets";
    return s;
}

TEST(UdpLoopback, DTrackHeadReachesTheCaveFrameAndGarbageIsCounted) {
    auto source = makeTracker("dtrack:udp://127.0.0.1:0?body=1&stale=1");
    const int port = network(source).port();
    ASSERT_GT(port, 0);
    std::thread sender([port] {
        EXPECT_TRUE(sendUdp("127.0.0.1", port, "garbage \x01\x02"));
        EXPECT_TRUE(sendUdp("127.0.0.1", port, "fr 1\n6d 1 [1 1.0][100 1700"));  // truncated
        EXPECT_TRUE(sendUdp("127.0.0.1", port, "fr 1\n6d 1 [1 1.0][nan 0 0 0 0 0][1 0 0 0 1 0 0 0 1]"));
        // Body 1 at (100, 1700, -200) mm, not rotated.
        EXPECT_TRUE(sendUdp("127.0.0.1", port, "fr 2\n6d 1 [1 1.0][100 1700 -200 0 0 0][1 0 0 0 1 0 0 0 1]\n"));
    });
    sender.join();
    const Sample s = pollUntil(*source, [&](const Sample&) { return source->stats().packets == 4; });
    EXPECT_TRUE(s.headValid);
    const SourceStats stats = source->stats();
    EXPECT_EQ(stats.malformed, 2u);
    EXPECT_EQ(stats.nonFinite, 1u);
    EXPECT_EQ(stats.accepted, 1u);
    // Calibration: the tracker origin sits 0.5 m right of the cave origin, turned 90° left.
    PipelineConfig config;
    config.caveFromTracker = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.0, 0.0)) *
                             glm::mat4_cast(glm::angleAxis(M_PI / 2, glm::dvec3(0, 1, 0)));
    TrackingPipeline pipeline(config);
    const TrackedFrame f = pipeline.update(s);
    // (0.1, 1.7, -0.2) m turned 90° about +Y is (-0.2, 1.7, -0.1); plus 0.5 m in x.
    EXPECT_NEAR(glm::distance(f.head.pose.position, glm::dvec3(0.3, 1.7, -0.1)), 0.0, 1e-12);
    EXPECT_EQ(f.head.state, TrackState::Tracked);
}

TEST(UdpLoopback, OpenTrackHeadAndForeignSenders) {
    // Only 127.0.0.2 is accepted: datagrams from 127.0.0.1 are foreign and counted.
    auto foreign = makeTracker("opentrack:udp://127.0.0.2:0");
    const double values[6] = {10.0, 150.0, -20.0, 0.0, 0.0, 0.0};
    ASSERT_TRUE(sendUdp("127.0.0.1", network(foreign).port(), encodeOpenTrack(values)));
    pollUntil(*foreign, [&](const Sample&) { return foreign->stats().packets == 1; });
    EXPECT_EQ(foreign->stats().foreign, 1u);
    EXPECT_FALSE(foreign->poll(10.0).headValid);

    auto source = makeTracker("opentrack:udp://127.0.0.1:0?stale=1");
    const int port = network(source).port();
    std::thread sender([&] {
        EXPECT_TRUE(sendUdp("127.0.0.1", port, std::string(47, 'x')));
        EXPECT_TRUE(sendUdp("127.0.0.1", port, encodeOpenTrack(values)));
    });
    sender.join();
    const Sample s = pollUntil(*source, [&](const Sample&) { return source->stats().packets == 2; });
    ASSERT_TRUE(s.headValid);
    EXPECT_EQ(source->stats().malformed, 1u);
    // Centimetres -> metres.
    EXPECT_NEAR(glm::distance(s.head.position, glm::dvec3(0.1, 1.5, -0.2)), 0.0, 1e-12);
}

TEST(UdpLoopback, PoseGoesStaleWithoutPackets) {
    auto source = makeTracker("dtrack:udp://127.0.0.1:0?stale=0.05");
    ASSERT_TRUE(sendUdp("127.0.0.1", network(source).port(), "fr 1\n6d 1 [1 1.0][0 0 0 0 0 0][1 0 0 0 1 0 0 0 1]\n"));
    const Sample s = pollUntil(*source, [](const Sample& x) { return x.headValid; });
    // 50 ms after the last packet the head counts as lost.
    EXPECT_FALSE(source->poll(s.time + 0.06).headValid);
}

TEST(UdpLoopback, AFloodDoesNotStallAPoll) {
    auto source = makeTracker("dtrack:udp://127.0.0.1:0");
    const int port = network(source).port();
    for (int i = 0; i < 1500; ++i) sendUdp("127.0.0.1", port, "junk");
    // One poll reads at most 1024 datagrams (fewer if the socket buffer dropped some): its work
    // is bounded by count, not by a clock read in the test.
    source->poll(0.0);
    const std::size_t first = source->stats().packets;
    EXPECT_LE(first, 1024u);
    EXPECT_EQ(source->stats().malformed, first);
    source->poll(0.0);  // the next poll takes the rest, again at most 1024
    EXPECT_LE(source->stats().packets - first, 1024u);
    EXPECT_EQ(source->stats().malformed, source->stats().packets);
}

// Finite but absurd positions (1e300 mm, -4e9 mm) would put the head at 1e297 m. Against the
// default volume of cave4 (its screens +-1.5 m, 0..3 m high, grown by 2 m) they are drops,
// counted, and the last good pose stays; so are 5.5 m up and 3.6 m behind.
TEST(UdpLoopback, DTrackFloodOutsideTheTrackingVolumeIsDropped) {
    const config::DisplayConfig cave = config::loadDisplayConfig("cave4");
    const config::TrackingVolume volume = config::trackingVolumeOf(cave);
    EXPECT_EQ(volume.min, glm::dvec3(-3.5, -2.0, -3.5));
    EXPECT_EQ(volume.max, glm::dvec3(3.5, 5.0, 3.5));
    auto source = makeTracker("dtrack:udp://127.0.0.1:0?body=1&stale=10", trackerContextFor(cave));
    const int port = network(source).port();
    const char* bad[] = {"1e300 0 0", "-4e9 1700 0", "0 5.5e3 0", "100 1700 -3600"};
    EXPECT_TRUE(sendUdp("127.0.0.1", port, "fr 1\n6d 1 [1 1.0][100 1700 -200 0 0 0][1 0 0 0 1 0 0 0 1]\n"));
    for (int i = 0; i < 100; ++i)
        EXPECT_TRUE(sendUdp("127.0.0.1", port,
                            "fr 2\n6d 1 [1 1.0][" + std::string(bad[i % 4]) + " 0 0 0][1 0 0 0 1 0 0 0 1]\n"));
    const Sample s = pollUntil(*source, [&](const Sample&) { return source->stats().packets == 101; });
    EXPECT_EQ(source->stats().accepted, 1u);
    EXPECT_EQ(source->stats().outside, 100u);
    EXPECT_EQ(source->stats().dropped(), 100u);
    EXPECT_TRUE(s.headValid);
    EXPECT_NEAR(glm::distance(s.head.position, glm::dvec3(0.1, 1.7, -0.2)), 0.0, 1e-12);
}

// Random 48-byte datagrams used to pass opentrack's range check one time in ~64 and move the
// head. Random doubles are implausible in range, in the volume or in their tiny magnitudes.
TEST(UdpLoopback, OpenTrackRandomFloodNeverMovesTheHead) {
    const config::DisplayConfig cave = config::loadDisplayConfig("cave4");
    auto source = makeTracker("opentrack:udp://127.0.0.1:0?stale=10", trackerContextFor(cave));
    const int port = network(source).port();
    const double good[6] = {10, 170, -20, 0, 0, 0};
    EXPECT_TRUE(sendUdp("127.0.0.1", port, encodeOpenTrack(good)));
    std::uint64_t state = 18;
    auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return state;
    };
    for (int i = 0; i < 100; ++i) {
        std::string packet(48, '\0');
        for (int k = 0; k < 48; k += 8) {
            const std::uint64_t r = next();
            std::memcpy(packet.data() + k, &r, 8);
        }
        EXPECT_TRUE(sendUdp("127.0.0.1", port, packet));
    }
    // Far but within opentrack's +-100 m range: outside the volume.
    const double far[6] = {5000, 170, 0, 0, 0, 0};
    EXPECT_TRUE(sendUdp("127.0.0.1", port, encodeOpenTrack(far)));
    const Sample s = pollUntil(*source, [&](const Sample&) { return source->stats().packets == 102; });
    EXPECT_EQ(source->stats().accepted, 1u);
    EXPECT_EQ(source->stats().dropped(), 101u);
    EXPECT_EQ(source->stats().outside, 1u);
    EXPECT_NEAR(glm::distance(s.head.position, glm::dvec3(0.1, 1.7, -0.2)), 0.0, 1e-12);
}

TEST(UdpLoopback, BadSpecsAreErrors) {
    const struct {
        const char* spec;
        const char* message;
    } cases[] = {
        {"dtrack:tcp://127.0.0.1:5000", "expected udp://HOST:PORT after 'dtrack:', got 'tcp://127.0.0.1:5000'"},
        {"dtrack:udp://127.0.0.1:99999", "port: expected an integer in [0, 65535], got \"99999\""},
        {"dtrack:udp://nowhere:5000", "host: expected a numeric IPv4 address, localhost or *, got 'nowhere'"},
        {"dtrack:udp://127.0.0.1:0?body=x", "body: expected an integer in [0, 1000000], got \"x\""},
        {"opentrack:udp://127.0.0.1:0?body=1",
         "unknown parameter 'body' (expected one of: bind, stale, invert, volume)"},
        {"dtrack:udp://127.0.0.1:0?volume=1,2,3",
         "volume: expected six comma-separated numbers within 1000 (x0,y0,z0,x1,y1,z1 "
         "in metres), got '1,2,3'"},
        {"dtrack:udp://127.0.0.1:0?volume=-3,0,-3,3,1e300,3",
         "volume: expected six comma-separated numbers within 1000"},
        {"opentrack:udp://127.0.0.1:0?volume=3,0,-3,-3,4,3",
         "volume: expected the first corner below the second on "
         "every axis, got '3,0,-3,-3,4,3'"},
        {"opentrack:udp://127.0.0.1:0?invert=yaw,spin",
         "invert: expected a comma-separated list of x, y, z, yaw, pitch, roll, got 'spin'"},
        {"dtrack:udp://127.0.0.1:0?bind=1.2.3",
         "bind address: expected a numeric IPv4 address or localhost, got '1.2.3'"},
        {"dtrack:udp://192.168.1.5:5000", "is not on this machine but the listener binds to 127.0.0.1 by default"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.spec);
        EXPECT_THAT([&] { makeTracker(c.spec); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
}  // namespace cavewall::input
