#include "input/packets.h"
#include "input/pose_math.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace cavewall::input {
namespace {

// Body 1 at (100, 1700, -200) mm, rotated 90° about +Y: the matrix columns are the images of
// the axes, x -> -z (0 0 -1), y -> y (0 1 0), z -> x (1 0 0), sent column by column.
const std::string kHead6d = "6d 1 [1 1.000][100 1700 -200 0 90 0][0 0 -1 0 1 0 1 0 0]";
const std::string kFlystick = "6df2 1 1 [0 1.000 6 2][250 1200 -400][1 0 0 0 1 0 0 0 1][5 -0.5 0.25]";

TEST(DTrack, ParsesFrameBodyAndFlystick) {
    PacketDrop why = PacketDrop::Malformed;
    const auto f =
        parseDTrack("fr 123\r\nts 39596.024831\r\n6dcal 2\r\n" + kHead6d + "\r\n" + kFlystick + "\r\n", &why);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(why, PacketDrop::None);
    EXPECT_EQ(f->frame, 123u);
    EXPECT_DOUBLE_EQ(*f->timestamp, 39596.024831);
    ASSERT_EQ(f->bodies.size(), 1u);
    const DTrackBody& b = f->bodies[0];
    EXPECT_EQ(b.id, 1);
    EXPECT_TRUE(b.tracked());
    // Millimetres -> metres.
    EXPECT_NEAR(glm::distance(b.pose.position, glm::dvec3(0.1, 1.7, -0.2)), 0.0, 1e-12);
    // The rotation maps the body's -Z (forward) to -X: a 90° turn to the left about +Y.
    const glm::dvec3 forward = b.pose.orientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(glm::distance(forward, glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
    ASSERT_EQ(f->flysticks.size(), 1u);
    const DTrackFlystick& s = f->flysticks[0];
    EXPECT_EQ(s.id, 0);
    EXPECT_NEAR(glm::distance(s.pose.position, glm::dvec3(0.25, 1.2, -0.4)), 0.0, 1e-12);
    // Button word 5 = buttons 0 and 2; ct0, ct1 are the joystick.
    EXPECT_TRUE(s.wand.pressed(0));
    EXPECT_FALSE(s.wand.pressed(1));
    EXPECT_TRUE(s.wand.pressed(2));
    EXPECT_EQ(s.wand.joystick, glm::dvec2(-0.5, 0.25));
}

TEST(DTrack, UntrackedDevicesKeepIdentityAndAreFlagged) {
    // DTrack sends quality -1 and zeros for a Flystick out of view; buttons still count.
    const auto f = parseDTrack("fr 1\n6df2 1 1 [0 -1.000 6 2][0 0 0][0 0 0 0 0 0 0 0 0][1 0 0]\n");
    ASSERT_TRUE(f.has_value());
    ASSERT_EQ(f->flysticks.size(), 1u);
    EXPECT_FALSE(f->flysticks[0].tracked());
    EXPECT_EQ(f->flysticks[0].pose.orientation, glm::dquat(1, 0, 0, 0));
    EXPECT_TRUE(f->flysticks[0].wand.pressed(0));
}

TEST(DTrack, SeveralBodiesAndUnknownLines) {
    const auto f = parseDTrack(
        "fr 7\n3d 1 [0 1.0][1 2 3]\n6d 2 [0 1.0][0 0 0 0 0 0][1 0 0 0 1 0 0 0 1] [1 0.5][10 20 30 0 0 0][1 0 0 0 1 0 0 "
        "0 1]\n");
    ASSERT_TRUE(f.has_value());
    ASSERT_EQ(f->bodies.size(), 2u);
    EXPECT_EQ(f->bodies[1].id, 1);
    EXPECT_NEAR(f->bodies[1].pose.position.z, 0.03, 1e-15);  // 30 mm
}

struct BadPacket {
    const char* name;
    std::string packet;
    PacketDrop why;
};

TEST(DTrack, DropsGarbageTruncatedAndNonFinitePackets) {
    const BadPacket cases[] = {
        {"empty", "", PacketDrop::Malformed},
        {"random text", "hello world\n", PacketDrop::Malformed},
        {"binary", std::string("\x01\x02\xff\x00\x10", 5), PacketDrop::Malformed},
        {"only a timestamp", "ts 1.5\n", PacketDrop::Malformed},
        {"truncated body", "fr 1\n6d 1 [1 1.000][100 1700 -200 0 90 0][0 0 -1 0 1", PacketDrop::Malformed},
        {"missing body", "fr 1\n6d 2 [1 1.000][100 1700 -200 0 90 0][0 0 -1 0 1 0 1 0 0]", PacketDrop::Malformed},
        {"short block", "fr 1\n6d 1 [1 1.000][100 1700 0 0 0][1 0 0 0 1 0 0 0 1]", PacketDrop::Malformed},
        {"trailing junk", "fr 1\n" + kHead6d + " x", PacketDrop::Malformed},
        {"word for number", "fr 1\n6d 1 [1 one][0 0 0 0 0 0][1 0 0 0 1 0 0 0 1]", PacketDrop::Malformed},
        {"negative count", "fr 1\n6d -1\n", PacketDrop::Malformed},
        {"fractional frame", "fr 1.5\n", PacketDrop::Malformed},
        {"not a rotation", "fr 1\n6d 1 [1 1.0][0 0 0 0 0 0][2 0 0 0 1 0 0 0 1]", PacketDrop::Malformed},
        {"a reflection", "fr 1\n6d 1 [1 1.0][0 0 0 0 0 0][-1 0 0 0 1 0 0 0 1]", PacketDrop::Malformed},
        {"overflow", "fr 1\n6d 1 [1 1.0][1e999 0 0 0 0 0][1 0 0 0 1 0 0 0 1]", PacketDrop::Malformed},
        {"upper-case line id", "FR 1\n", PacketDrop::Malformed},
        {"truncated flystick", "fr 1\n6df2 1 1 [0 1.000 6 2][250 1200 -400][1 0 0 0 1 0 0 0 1][5 -0.5",
         PacketDrop::Malformed},
        {"more flysticks than defined", "fr 1\n6df2 1 2 [0 1 0 0][0 0 0][1 0 0 0 1 0 0 0 1][]", PacketDrop::Malformed},
        {"NaN position", "fr 1\n6d 1 [1 1.0][nan 0 0 0 0 0][1 0 0 0 1 0 0 0 1]", PacketDrop::NonFinite},
        {"infinite timestamp", "fr 1\nts inf\n", PacketDrop::NonFinite},
        {"NaN joystick", "fr 1\n6df2 1 1 [0 1.000 6 2][0 0 0][1 0 0 0 1 0 0 0 1][0 nan 0]", PacketDrop::NonFinite},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        PacketDrop why = PacketDrop::None;
        EXPECT_FALSE(parseDTrack(c.packet, &why).has_value());
        EXPECT_EQ(why, c.why);
    }
}

TEST(DTrack, EveryPrefixOfAValidPacketIsSafe) {
    // Truncation at any byte must never crash or read past the end (run under sanitizers);
    // a prefix is either dropped or a valid frame with fewer devices.
    const std::string full = "fr 9\n" + kHead6d + "\n" + kFlystick + "\n";
    for (std::size_t n = 0; n <= full.size(); ++n) {
        const auto f = parseDTrack(full.substr(0, n));
        if (f) {
            EXPECT_LE(f->bodies.size() + f->flysticks.size(), 2u);
        }
    }
}

TEST(DTrack, MutatedPacketsNeverCrashAndAreAllAccountedFor) {
    // 20000 valid packets with 1-4 random bytes changed (deterministic): each is either accepted
    // with finite poses or dropped with a reason. Run under the sanitizers this also proves that
    // no mutation makes the parser read out of bounds.
    const std::string full = "fr 9\n" + kHead6d + "\n" + kFlystick + "\n";
    std::uint64_t rng = 5;
    int accepted = 0, dropped = 0;
    for (int i = 0; i < 20000; ++i) {
        std::string p = full;
        const int edits = 1 + static_cast<int>(nextRandom(rng) % 4);
        for (int e = 0; e < edits; ++e) p[nextRandom(rng) % p.size()] = static_cast<char>(nextRandom(rng) & 0xFF);
        PacketDrop why = PacketDrop::None;
        const auto f = parseDTrack(p, &why);
        if (!f) {
            EXPECT_NE(why, PacketDrop::None);
            ++dropped;
            continue;
        }
        ++accepted;
        for (const auto& b : f->bodies) ASSERT_TRUE(isFinite(b.pose));
        for (const auto& s : f->flysticks) ASSERT_TRUE(isFinite(s.pose) && std::isfinite(s.wand.joystick.x));
    }
    EXPECT_GT(dropped, 1000);  // most byte changes break the syntax
    EXPECT_GT(accepted, 100);  // some only change a digit
}

TEST(OpenTrack, DecodesCentimetresAndDegrees) {
    const double values[6] = {10.0, -5.0, 20.0, 90.0, 0.0, 0.0};
    PacketDrop why = PacketDrop::Malformed;
    const auto pose = parseOpenTrack(encodeOpenTrack(values), {}, &why);
    ASSERT_TRUE(pose.has_value());
    EXPECT_EQ(why, PacketDrop::None);
    // Centimetres -> metres on the documented axes.
    EXPECT_NEAR(glm::distance(pose->position, glm::dvec3(0.1, -0.05, 0.2)), 0.0, 1e-15);
    // Yaw +90° turns forward (-Z) to -X (a left turn).
    EXPECT_NEAR(glm::distance(pose->orientation * glm::dvec3(0, 0, -1), glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
}

TEST(OpenTrack, PitchAndInvert) {
    const double values[6] = {10.0, 0.0, 0.0, 0.0, 30.0, 0.0};
    // Pitch +30° looks up: forward gets a positive y of sin 30° = 0.5.
    const auto up = parseOpenTrack(encodeOpenTrack(values));
    ASSERT_TRUE(up.has_value());
    EXPECT_NEAR((up->orientation * glm::dvec3(0, 0, -1)).y, 0.5, 1e-12);
    OpenTrackInvert inv;
    inv.pitch = inv.x = true;
    const auto flipped = parseOpenTrack(encodeOpenTrack(values), inv);
    ASSERT_TRUE(flipped.has_value());
    EXPECT_NEAR((flipped->orientation * glm::dvec3(0, 0, -1)).y, -0.5, 1e-12);
    EXPECT_NEAR(flipped->position.x, -0.1, 1e-15);
}

TEST(OpenTrack, DropsWrongSizesNonFiniteAndImplausibleValues) {
    const double ok[6] = {0, 0, 0, 0, 0, 0};
    const std::string good = encodeOpenTrack(ok);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const double withNan[6] = {0, 0, 0, nan, 0, 0}, withInf[6] = {inf, 0, 0, 0, 0, 0};
    const double farAway[6] = {0, 0, 20000, 0, 0, 0}, spun[6] = {0, 0, 0, 0, 0, 720};
    const BadPacket cases[] = {
        {"empty", "", PacketDrop::Malformed},
        {"truncated", good.substr(0, 47), PacketDrop::Malformed},
        {"one double", good.substr(0, 8), PacketDrop::Malformed},
        {"too long", good + "x", PacketDrop::Malformed},
        {"text", std::string(48, 'a'), PacketDrop::Malformed},  // 'aaaaaaaa' decodes to ~1e45
        {"NaN yaw", encodeOpenTrack(withNan), PacketDrop::NonFinite},
        {"infinite x", encodeOpenTrack(withInf), PacketDrop::NonFinite},
        {"200 m away", encodeOpenTrack(farAway), PacketDrop::Malformed},
        {"720 degrees", encodeOpenTrack(spun), PacketDrop::Malformed},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        PacketDrop why = PacketDrop::None;
        EXPECT_FALSE(parseOpenTrack(c.packet, {}, &why).has_value());
        EXPECT_EQ(why, c.why);
    }
}

}  // namespace
}  // namespace cavewall::input
