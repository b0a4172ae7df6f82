// VRPN's byte protocol on hand-built buffers: framing, names, device payloads, and a session
// fed whole, split and broken streams.
#include "input/vrpn_protocol.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;

// A big-endian int32 as 4 bytes.
std::string be32(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

// What a server sends first: its cookie, then sender 3 = "Tracker0", sender 5 = "Other", and
// types 7 = pose, 8 = button change, 9 = button states (ids are the server's own, any values).
std::string serverGreeting() {
    std::string s = encodeVrpnCookie();
    s += encodeVrpnMessage(3, kVrpnSenderDescription, 0.0, encodeVrpnName("Tracker0"));
    s += encodeVrpnMessage(5, kVrpnSenderDescription, 0.0, encodeVrpnName("Other"));
    s += encodeVrpnMessage(7, kVrpnTypeDescription, 0.0, encodeVrpnName("vrpn_Tracker Pos_Quat"));
    s += encodeVrpnMessage(8, kVrpnTypeDescription, 0.0, encodeVrpnName("vrpn_Button Change"));
    s += encodeVrpnMessage(9, kVrpnTypeDescription, 0.0, encodeVrpnName("vrpn_Button States"));
    return s;
}

std::string poseMessage(std::int32_t sender, int sensor, glm::dvec3 p, glm::dquat q, double time = 1.5) {
    const double position[3] = {p.x, p.y, p.z}, quaternion[4] = {q.x, q.y, q.z, q.w};
    return encodeVrpnMessage(sender, 7, time, encodeVrpnTrackerPose(sensor, position, quaternion));
}

TEST(VrpnProtocol, CookieIsTwentyFourBytesAndChecksTheMajorVersion) {
    const std::string cookie = encodeVrpnCookie();
    ASSERT_EQ(cookie.size(), kVrpnCookieSize);
    EXPECT_EQ(cookie.substr(0, 19), "vrpn: ver. 07.38  0");
    EXPECT_EQ(checkVrpnCookie(cookie), "");
    std::string otherMinor = cookie;
    otherMinor.replace(14, 2, "35");  // a minor difference is fine, as VRPN itself allows
    EXPECT_EQ(checkVrpnCookie(otherMinor), "");
    std::string otherMajor = cookie;
    otherMajor.replace(11, 2, "08");
    EXPECT_THAT(checkVrpnCookie(otherMajor), HasSubstr("got 'vrpn: ver. 08.38  0'"));
    EXPECT_THAT(checkVrpnCookie("HTTP/1.1 400 Bad Request\r\n"), HasSubstr("got 'HTTP/1.1 400 Bad Request'"));
    EXPECT_THAT(checkVrpnCookie(std::string("\x01\xff", 2)), HasSubstr("got '\\x01\\xff'"));
}

TEST(VrpnProtocol, MessageHeaderAndPaddingRoundTrip) {
    const std::string m = encodeVrpnMessage(4, 11, 1700000000.25, "abc");
    ASSERT_EQ(m.size(), 24u + 8u);          // header padded to 24, 3 payload bytes padded to 8
    EXPECT_EQ(m.substr(0, 4), be32(27));    // the length counts the unpadded payload
    const std::string stream = m + "next";  // the payload points into the bytes given
    const VrpnTaken t = takeVrpnMessage(stream);
    ASSERT_EQ(t.status, VrpnTake::Message);
    EXPECT_EQ(t.consumed, m.size());
    EXPECT_EQ(t.message.sender, 4);
    EXPECT_EQ(t.message.type, 11);
    EXPECT_DOUBLE_EQ(t.message.time, 1700000000.25);
    EXPECT_EQ(t.message.payload, "abc");
}

TEST(VrpnProtocol, TruncatedMessagesNeedMoreAndImpossibleLengthsAreBad) {
    const std::string m = encodeVrpnMessage(4, 11, 0.0, "abcdefghij");
    for (std::size_t n = 0; n < m.size(); ++n) {
        SCOPED_TRACE(n);
        EXPECT_EQ(takeVrpnMessage(std::string_view(m).substr(0, n)).status, VrpnTake::NeedMore);
    }
    std::string shortLength = m;
    shortLength.replace(0, 4, be32(23));
    const VrpnTaken bad = takeVrpnMessage(shortLength);
    EXPECT_EQ(bad.status, VrpnTake::Bad);
    EXPECT_THAT(bad.error, HasSubstr("message length 23: expected 24"));
    std::string hugeLength = m;
    hugeLength.replace(0, 4, be32(0xFFFFFFF0u));
    EXPECT_EQ(takeVrpnMessage(hugeLength).status, VrpnTake::Bad);
}

TEST(VrpnProtocol, NamesNeedTheirLengthAndNul) {
    EXPECT_EQ(parseVrpnName(encodeVrpnName("Tracker0")), "Tracker0");
    struct Case {
        const char* name;
        std::string payload;
    };
    const Case cases[] = {
        {"empty", ""},
        {"length only", be32(1)},
        {"length zero", be32(0) + "a"},
        {"length past the end", be32(9) + std::string("abc\0", 4)},
        {"no NUL", be32(3) + "abc"},
        {"NUL inside", be32(4) + std::string("a\0b\0", 4)},
        {"too long", be32(201) + std::string(200, 'a') + std::string(1, '\0')},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(parseVrpnName(c.payload), std::nullopt);
    }
}

TEST(VrpnProtocol, TrackerPoseIsBigEndianDoublesAfterTwoInts) {
    const double position[3] = {0.125, -1.5, 2.0}, quaternion[4] = {0.0, 0.6, 0.0, 0.8};
    const std::string payload = encodeVrpnTrackerPose(2, position, quaternion);
    ASSERT_EQ(payload.size(), 64u);
    EXPECT_EQ(payload.substr(8, 8), std::string("\x3f\xc0\0\0\0\0\0\0", 8));  // 0.125, most significant first
    PacketDrop why = PacketDrop::Malformed;
    const auto r = parseVrpnTrackerPose(payload, &why);
    ASSERT_TRUE(r);
    EXPECT_EQ(why, PacketDrop::None);
    EXPECT_EQ(r->sensor, 2);
    EXPECT_EQ(r->pose.position, glm::dvec3(0.125, -1.5, 2.0));
    EXPECT_NEAR(r->pose.orientation.w, 0.8, 1e-15);  // VRPN's order is x, y, z, w
    EXPECT_NEAR(r->pose.orientation.y, 0.6, 1e-15);
}

TEST(VrpnProtocol, BadTrackerPayloadsAreDroppedWithAReason) {
    const double position[3] = {0.0, 1.7, 0.0}, unit[4] = {0.0, 0.0, 0.0, 1.0};
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const double nanPosition[3] = {nan, 1.7, 0.0}, infQuaternion[4] = {0.0, inf, 0.0, 1.0};
    const double longQuaternion[4] = {0.0, 0.0, 0.0, 1.2}, zeroQuaternion[4] = {0.0, 0.0, 0.0, 0.0};
    const std::string good = encodeVrpnTrackerPose(0, position, unit);
    struct Case {
        const char* name;
        std::string payload;
        PacketDrop why;
    };
    const Case cases[] = {
        {"truncated", good.substr(0, 63), PacketDrop::Malformed},
        {"too long", good + std::string(8, '\0'), PacketDrop::Malformed},
        {"negative sensor", be32(0xFFFFFFFFu) + good.substr(4), PacketDrop::Malformed},
        {"NaN position", encodeVrpnTrackerPose(0, nanPosition, unit), PacketDrop::NonFinite},
        {"infinite quaternion", encodeVrpnTrackerPose(0, position, infQuaternion), PacketDrop::NonFinite},
        {"quaternion not unit", encodeVrpnTrackerPose(0, position, longQuaternion), PacketDrop::Malformed},
        {"zero quaternion", encodeVrpnTrackerPose(0, position, zeroQuaternion), PacketDrop::Malformed},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        PacketDrop why = PacketDrop::None;
        EXPECT_EQ(parseVrpnTrackerPose(c.payload, &why), std::nullopt);
        EXPECT_EQ(why, c.why);
    }
}

TEST(VrpnProtocol, ButtonChangesAndStates) {
    const auto change = parseVrpnButtonChange(be32(3) + be32(1));
    ASSERT_TRUE(change);
    EXPECT_EQ(change->button, 3);
    EXPECT_TRUE(change->pressed);
    EXPECT_EQ(parseVrpnButtonChange(be32(3) + be32(2)), std::nullopt);  // states are 0 or 1
    EXPECT_EQ(parseVrpnButtonChange(be32(3)), std::nullopt);
    EXPECT_EQ(parseVrpnButtonStates(be32(3) + be32(1) + be32(0) + be32(1)), 0b101u);
    EXPECT_EQ(parseVrpnButtonStates(be32(3) + be32(1) + be32(0)), std::nullopt);  // one state missing
    EXPECT_EQ(parseVrpnButtonStates(be32(0xFFFFFFFFu)), std::nullopt);
    EXPECT_EQ(parseVrpnButtonStates(be32(0)), 0u);
}

TEST(VrpnSession, PassesOnTheNamedDevicesReportsOnly) {
    VrpnSession session("Tracker0", "Tracker0");
    std::string stream = serverGreeting();
    stream += poseMessage(3, 1, {0.1, 1.6, -0.2}, {1.0, 0.0, 0.0, 0.0}, 12.5);
    stream += poseMessage(5, 0, {9.0, 9.0, 9.0}, {1.0, 0.0, 0.0, 0.0});  // another device
    stream += encodeVrpnMessage(3, 8, 0.0, be32(0) + be32(1));
    stream += encodeVrpnMessage(3, 42, 0.0, "an undescribed type");
    stream += encodeVrpnMessage(3, -3, 0.0, "a UDP description, ignored over TCP");
    VrpnUpdates u;
    ASSERT_TRUE(session.feed(stream, u)) << session.error();
    EXPECT_TRUE(session.cookieReceived());
    EXPECT_EQ(u.messages, 10u);
    ASSERT_EQ(u.poses.size(), 1u);
    EXPECT_EQ(u.poses[0].sensor, 1);
    EXPECT_EQ(u.poses[0].pose.position, glm::dvec3(0.1, 1.6, -0.2));
    EXPECT_DOUBLE_EQ(u.poses[0].time, 12.5);
    ASSERT_EQ(u.changes.size(), 1u);
    EXPECT_EQ(u.changes[0].button, 0);
    EXPECT_EQ(u.malformed, 0u);
    EXPECT_EQ(session.buffered(), 0u);
}

TEST(VrpnSession, AStreamSplitAtEveryByteGivesTheSameReports) {
    std::string stream = serverGreeting();
    for (int i = 0; i < 3; ++i) stream += poseMessage(3, 0, {0.1 * i, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0});
    VrpnSession session("Tracker0", "Tracker0");
    std::vector<VrpnTrackerReport> poses;
    for (char c : stream) {
        VrpnUpdates u;
        ASSERT_TRUE(session.feed(std::string_view(&c, 1), u));
        poses.insert(poses.end(), u.poses.begin(), u.poses.end());
    }
    ASSERT_EQ(poses.size(), 3u);
    EXPECT_EQ(poses[2].pose.position, glm::dvec3(0.2, 1.7, 0.0));
}

TEST(VrpnSession, BadPayloadsAreCountedAndTheStreamGoesOn) {
    VrpnSession session("Tracker0", "Tracker0");
    std::string stream = serverGreeting();
    stream += encodeVrpnMessage(3, 7, 0.0, "short");                                // a pose of 5 bytes
    stream += poseMessage(3, 0, {0.0, 1.7, 0.0}, {0.0, 0.0, 0.0, 0.0});             // no rotation
    stream += encodeVrpnMessage(6, kVrpnSenderDescription, 0.0, be32(50) + "abc");  // length past the end
    stream += poseMessage(3, 0, {0.0, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0});
    VrpnUpdates u;
    ASSERT_TRUE(session.feed(stream, u));
    EXPECT_EQ(u.malformed, 3u);
    EXPECT_EQ(u.poses.size(), 1u);
}

TEST(VrpnSession, FramingErrorsStopTheSessionWithTheReason) {
    {
        VrpnSession session("Tracker0", "Tracker0");
        VrpnUpdates u;
        EXPECT_FALSE(session.feed("SSH-2.0-OpenSSH_9.2p1 Debian-2\r\n", u));
        EXPECT_THAT(session.error(), HasSubstr("expected a VRPN cookie"));
        EXPECT_THAT(session.error(), HasSubstr("got 'SSH-2.0-OpenSSH_9.2p1 De'"));
    }
    {
        VrpnSession session("Tracker0", "Tracker0");
        VrpnUpdates u;
        EXPECT_FALSE(session.feed(serverGreeting() + be32(5) + std::string(20, 'x'), u));
        EXPECT_THAT(session.error(), HasSubstr("message length 5"));
        EXPECT_EQ(u.messages, 5u);  // the descriptions before it still count
        EXPECT_FALSE(session.feed(poseMessage(3, 0, {}, {1.0, 0.0, 0.0, 0.0}), u));  // dead from now on
    }
}

TEST(VrpnSession, DatagramsCarryWholeMessagesWithTheNamesLearntOnTcp) {
    VrpnSession session("Tracker0", "Tracker0");
    VrpnUpdates u;
    session.feedDatagram(poseMessage(3, 0, {0.0, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0}), u);
    EXPECT_EQ(u.messages, 0u);  // before the cookie nothing counts
    ASSERT_TRUE(session.feed(serverGreeting(), u));
    u = {};
    const std::string two = poseMessage(3, 0, {0.0, 1.7, 0.0}, {1.0, 0.0, 0.0, 0.0}) +
                            poseMessage(3, 1, {0.2, 1.1, 0.0}, {1.0, 0.0, 0.0, 0.0});
    session.feedDatagram(two, u);
    ASSERT_EQ(u.poses.size(), 2u);
    EXPECT_EQ(u.poses[1].sensor, 1);
    u = {};
    session.feedDatagram(std::string_view(two).substr(0, two.size() - 8), u);  // the second one cut short
    EXPECT_EQ(u.poses.size(), 1u);
    EXPECT_EQ(u.malformed, 1u);
    EXPECT_FALSE(session.failed());  // a bad datagram is dropped, the connection goes on
}

TEST(VrpnProtocol, UdpDescriptionNamesThePortAndAddress) {
    const std::string message = encodeVrpnUdpDescription(40123, "127.0.0.1", 0.0);
    const VrpnTaken t = takeVrpnMessage(message);
    ASSERT_EQ(t.status, VrpnTake::Message);
    EXPECT_EQ(t.message.type, -3);
    EXPECT_EQ(t.message.sender, 40123);  // the port travels in the sender field
    EXPECT_EQ(t.message.payload, std::string("127.0.0.1\0", 10));
}

// Random bytes after a valid start never crash, never give a non-finite or non-unit pose.
TEST(VrpnSession, RandomBytesNeverGiveABadPose) {
    std::mt19937 rng(7);
    for (int round = 0; round < 200; ++round) {
        VrpnSession session("Tracker0", "Tracker0");
        std::string stream = serverGreeting();
        const int n = 1 + static_cast<int>(rng() % 400);
        for (int i = 0; i < n; ++i) stream.push_back(static_cast<char>(rng()));
        if (round % 2) stream.replace(stream.size() - n, 4, be32(24 + rng() % 200));  // a plausible length
        VrpnUpdates u;
        session.feed(stream, u);
        for (const VrpnTrackerReport& r : u.poses) {
            EXPECT_TRUE(std::isfinite(r.pose.position.x) && std::isfinite(r.pose.position.y) &&
                        std::isfinite(r.pose.position.z));
            EXPECT_NEAR(glm::length(r.pose.orientation), 1.0, 1e-12);
        }
    }
}

}  // namespace
}  // namespace cavewall::input
