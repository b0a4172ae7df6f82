// The VRPN client against a hand-written fake server on loopback TCP: specs, a good stream,
// garbage, a refused connection. (The real VRPN server is in tests/vrpn, label net.)
#include "input/vrpn_client.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A listening TCP socket on 127.0.0.1 that the test drives by hand.
class FakeServer {
public:
    FakeServer() {
        _listen = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        EXPECT_EQ(::bind(_listen, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
        EXPECT_EQ(::listen(_listen, 4), 0);
        socklen_t len = sizeof a;
        ::getsockname(_listen, reinterpret_cast<sockaddr*>(&a), &len);
        _port = ntohs(a.sin_port);
    }
    ~FakeServer() {
        closeClient();
        ::close(_listen);
    }
    int port() const { return _port; }
    // Accepts the client's connection while polling it (the client connects inside poll()).
    bool accept(VrpnSource& client, double& now) {
        for (int i = 0; i < 300 && _client < 0; ++i) {
            client.poll(now += 0.01);
            pollfd p{_listen, POLLIN, 0};
            if (::poll(&p, 1, 10) > 0) _client = ::accept(_listen, nullptr, nullptr);
        }
        return _client >= 0;
    }
    void send(const std::string& bytes) {
        ASSERT_EQ(::send(_client, bytes.data(), bytes.size(), MSG_NOSIGNAL), static_cast<ssize_t>(bytes.size()));
    }
    void closeClient() {
        if (_client >= 0) ::close(_client);
        _client = -1;
    }

private:
    int _listen = -1, _client = -1, _port = 0;
};

VrpnConfig configFor(int port) {
    VrpnConfig c;
    c.host = "127.0.0.1";
    c.port = port;
    c.retrySeconds = 0.05;
    c.staleSeconds = 10.0;
    return c;
}

// Polls (waiting on the socket between polls) until `done` holds, at most 3 s of wall time.
template <class Done>
Sample pollUntil(VrpnSource& client, double& now, Done done) {
    const auto start = std::chrono::steady_clock::now();
    Sample s;
    while (std::chrono::steady_clock::now() - start < std::chrono::seconds(3)) {
        s = client.poll(now += 0.001);
        if (done(s)) return s;
        client.wait(now, 0.05);
    }
    ADD_FAILURE() << "timed out; client problem: " << client.problem();
    return s;
}

std::string greeting() {
    std::string s = encodeVrpnCookie();
    s += encodeVrpnMessage(0, kVrpnSenderDescription, 0.0, encodeVrpnName("Tracker0"));
    s += encodeVrpnMessage(0, kVrpnTypeDescription, 0.0, encodeVrpnName("vrpn_Tracker Pos_Quat"));
    s += encodeVrpnMessage(1, kVrpnTypeDescription, 0.0, encodeVrpnName("vrpn_Button Change"));
    return s;
}

std::string pose(int sensor, glm::dvec3 p) {
    const double position[3] = {p.x, p.y, p.z}, quaternion[4] = {0.0, 0.0, 0.0, 1.0};
    return encodeVrpnMessage(0, 0, 0.0, encodeVrpnTrackerPose(sensor, position, quaternion));
}

TEST(VrpnClient, SpecsAndTheirErrors) {
    const auto source = makeTracker("vrpn:Tracker0@localhost");
    EXPECT_EQ(source->describe(), "vrpn Tracker0@127.0.0.1:3883");
    EXPECT_TRUE(source->isLive());
    EXPECT_EQ(makeTracker("vrpn:DTrack@127.0.0.1:3999?head=3&hand=-1&buttons=Wand0")->describe(),
              "vrpn DTrack@127.0.0.1:3999");
    struct Case {
        const char* spec;
        const char* message;
    };
    const Case cases[] = {
        {"vrpn:Tracker0", "expected DEVICE@HOST[:PORT] after 'vrpn:', such as Tracker0@localhost, got 'Tracker0'"},
        {"vrpn:@localhost", "expected DEVICE@HOST[:PORT]"},
        {"vrpn:Tracker0@", "expected DEVICE@HOST[:PORT]"},
        {"vrpn:Tracker0@:3883", "expected a host after '@'"},
        {"vrpn:Tracker0@localhost:0", "port: expected an integer in [1, 65535], got \"0\""},
        {"vrpn:Tracker0@localhost:38x", "port: expected an integer in [1, 65535], got \"38x\""},
        {"vrpn:Tracker0@localhost?head=1&hand=1", "expected two different sensors, got 1 for both"},
        {"vrpn:Tracker0@localhost?body=1", "unknown parameter 'body'"},
        {"vrpn:Tracker0@localhost?retry=0", "retry: expected a number in [0.01, 60]"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.spec);
        EXPECT_THAT([&] { makeTracker(c.spec); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(VrpnClient, HeadHandAndButtonsFromAFakeServer) {
    FakeServer server;
    VrpnSource client(configFor(server.port()));
    double now = 0.0;
    ASSERT_TRUE(server.accept(client, now));
    server.send(greeting() + pose(0, {0.1, 1.7, 0.2}) + pose(1, {0.3, 1.2, -0.4}) +
                encodeVrpnMessage(0, 1, 0.0, std::string("\0\0\0\1\0\0\0\1", 8)));
    const Sample s =
        pollUntil(client, now, [](const Sample& s) { return s.headValid && s.handValid && s.wand.buttons; });
    EXPECT_TRUE(client.connected());
    EXPECT_EQ(s.head.position, glm::dvec3(0.1, 1.7, 0.2));
    EXPECT_EQ(s.hand.position, glm::dvec3(0.3, 1.2, -0.4));
    EXPECT_EQ(s.wand.buttons, 2u);
    EXPECT_EQ(client.stats().accepted, 3u);
    EXPECT_EQ(client.problem(), "");
}

TEST(VrpnClient, PosesOutsideTheVolumeAreCounted) {
    FakeServer server;
    VrpnConfig c = configFor(server.port());
    c.volume = {{-2.0, -0.5, -2.0}, {2.0, 3.0, 2.0}};
    VrpnSource client(c);
    double now = 0.0;
    ASSERT_TRUE(server.accept(client, now));
    server.send(greeting() + pose(0, {1e6, 1.7, 0.0}) + pose(0, {0.0, 1.7, 0.0}));
    const Sample s = pollUntil(client, now, [](const Sample& s) { return s.headValid; });
    EXPECT_EQ(s.head.position, glm::dvec3(0.0, 1.7, 0.0));
    EXPECT_EQ(client.stats().outside, 1u);
}

TEST(VrpnClient, GarbageIsAClearErrorAndTheClientConnectsAgain) {
    FakeServer server;
    VrpnSource client(configFor(server.port()));
    double now = 0.0;
    ASSERT_TRUE(server.accept(client, now));
    server.send("GET / HTTP/1.1\r\nHost: x\r\n\r\n");
    pollUntil(client, now, [&](const Sample&) { return !client.problem().empty(); });
    EXPECT_THAT(client.problem(), HasSubstr("vrpn Tracker0@127.0.0.1:" + std::to_string(server.port()) +
                                            ": bad data from the server: expected a VRPN cookie"));
    EXPECT_THAT(client.problem(), HasSubstr("got 'GET / HTTP/1.1\\x0d\\x0aHost: x\\x0d'"));
    EXPECT_THAT(client.problem(), HasSubstr("trying again every 0.05 s"));
    EXPECT_EQ(client.stats().malformed, 1u);
    EXPECT_FALSE(client.connected());
    server.closeClient();

    // A good server on the same port afterwards is used; a framing error later is also an error.
    ASSERT_TRUE(server.accept(client, now));
    server.send(greeting() + pose(0, {0.0, 1.5, 0.0}));
    Sample s = pollUntil(client, now, [](const Sample& s) { return s.headValid; });
    EXPECT_EQ(s.head.position.y, 1.5);
    EXPECT_EQ(client.connections(), 1u);
    EXPECT_EQ(client.problem(), "");
    server.send(std::string(24, '\xff'));
    s = pollUntil(client, now, [&](const Sample&) { return !client.problem().empty(); });
    EXPECT_FALSE(s.headValid);  // a closed connection loses the devices at once
    EXPECT_THAT(client.problem(), HasSubstr("bad data from the server: message length 4294967295"));
}

TEST(VrpnClient, ASilentServiceOnThePortSaysSo) {
    FakeServer server;  // accepts, then sends nothing
    VrpnSource client(configFor(server.port()));
    double now = 0.0;
    ASSERT_TRUE(server.accept(client, now));
    for (int i = 0; i < 8 && client.problem().empty(); ++i) client.poll(now += 0.5);  // the poll clock
    EXPECT_THAT(client.problem(), HasSubstr("no VRPN cookie within 3 s (is this a VRPN server?)"));
    EXPECT_FALSE(client.connected());
}

TEST(VrpnClient, ARefusedConnectionSaysSo) {
    int port = 0;
    {
        FakeServer closed;  // a port that was free a moment ago and now has no listener
        port = closed.port();
    }
    VrpnSource client(configFor(port));
    double now = 0.0;
    pollUntil(client, now, [&](const Sample&) { return !client.problem().empty(); });
    EXPECT_THAT(client.problem(), HasSubstr("cannot connect: Connection refused; trying again every 0.05 s"));
    EXPECT_FALSE(client.poll(now += 0.01).headValid);
}

TEST(VrpnClient, AServerThatNeverCallsBackSaysSo) {
    int port = 0;
    {
        FakeServer closed;
        port = closed.port();
    }
    VrpnConfig c = configFor(port);
    c.udp = true;  // the server is asked to connect back; nobody does
    VrpnSource client(c);
    for (double now = 0.0; now < 4.0; now += 0.5) client.poll(now);  // the poll clock, not wall time
    EXPECT_THAT(client.problem(), HasSubstr("the server has not connected back within 3 s"));
    EXPECT_THAT(client.problem(), HasSubstr("asking again every 0.05 s"));
    EXPECT_FALSE(client.connected());
}

}  // namespace
}  // namespace cavewall::input
