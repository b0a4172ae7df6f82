#include "input/sim_walk.h"
#include "input/pose_math.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(SimWalk, SameSeedSameSamplesWhateverThePollOrder) {
    auto a = makeTracker("sim:walk?seed=3&dropouts=1");
    auto b = makeTracker("sim:walk?seed=3&dropouts=1");
    // b is polled backwards first: the walk is a function of time, not of the poll history.
    for (int i = 900; i >= 0; i -= 7) b->poll(i / 90.0);
    for (int i = 0; i <= 900; ++i) {
        const Sample sa = a->poll(i / 90.0), sb = b->poll(i / 90.0);
        ASSERT_EQ(sa, sb) << "at sample " << i;  // bit-identical, including jitter and drop-outs
    }
}

TEST(SimWalk, DifferentSeedsWalkDifferently) {
    auto a = makeTracker("sim:walk?seed=1"), b = makeTracker("sim:walk?seed=2");
    EXPECT_GT(glm::distance(a->poll(10.0).head.position, b->poll(10.0).head.position), 0.01);
}

TEST(SimWalk, HeadStaysInsideTheFloorAreaAndMovesLikeAPerson) {
    TrackerContext context;
    context.floorMin = {-1.0, -2.0};
    context.floorMax = {2.0, 1.0};
    // A tracker whose origin is 1 m in front of the cave origin: samples come in tracker frame.
    context.caveFromTracker = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -1.0));
    for (std::uint64_t seed : {0ull, 1ull, 42ull}) {
        SCOPED_TRACE(seed);
        SimWalk walk({seed, false}, context);
        double minY = 10.0, maxY = 0.0, maxStep = 0.0, travelled = 0.0;
        glm::dvec3 prev = transformPose(context.caveFromTracker, walk.at(0.0).head).position;
        for (int i = 1; i <= 120 * 90; ++i) {
            const glm::dvec3 p = transformPose(context.caveFromTracker, walk.at(i / 90.0).head).position;
            ASSERT_GE(p.x, -1.0);
            ASSERT_LE(p.x, 2.0);
            ASSERT_GE(p.z, -2.0);
            ASSERT_LE(p.z, 1.0);
            minY = std::min(minY, p.y);
            maxY = std::max(maxY, p.y);
            maxStep = std::max(maxStep, glm::distance(p, prev));
            travelled += glm::distance(glm::dvec2(p.x, p.z), glm::dvec2(prev.x, prev.z));
            prev = p;
        }
        // Standing at 1.7 m (+ bob and jitter), crouching to 65 % of it (1.105 m) at some point.
        EXPECT_LT(maxY, 1.72);
        EXPECT_LT(minY, 1.2);
        EXPECT_GT(minY, 1.7 * 0.65 - 0.01);
        // Human speeds: never more than 3 m/s between samples (1/90 s), yet it walks around.
        EXPECT_LT(maxStep, 3.0 / 90.0);
        EXPECT_GT(travelled, 10.0);
    }
}

TEST(SimWalk, DropoutsReportTheLastPose) {
    SimWalk walk({7, true}, TrackerContext{});
    int dropped = 0;
    Sample prev = walk.at(0.0);
    for (int i = 1; i <= 60 * 90; ++i) {
        const Sample s = walk.at(i / 90.0);
        if (!s.headValid) {
            ++dropped;
            // A lost head does not move: it reports the pose it was lost with.
            if (!prev.headValid) {
                EXPECT_EQ(s.head, prev.head);
            }
        }
        prev = s;
    }
    // Drop-outs of 0.1-1.5 s every 2-8 s: between 1 % and 50 % of a minute.
    EXPECT_GT(dropped, 60 * 90 / 100);
    EXPECT_LT(dropped, 60 * 90 / 2);
    SimWalk steady({7, false}, TrackerContext{});
    for (int i = 0; i <= 60 * 90; ++i) ASSERT_TRUE(steady.at(i / 90.0).headValid);
}

TEST(SimWalk, HandIsBelowAndInFrontOfTheHeadAndTriggerCycles) {
    SimWalk walk({5, false}, TrackerContext{});
    const Sample s = walk.at(12.5);
    const glm::dvec3 d = s.hand.position - s.head.position;
    EXPECT_NEAR(d.y, -0.4, 1e-9);  // held 0.4 m below the head
    EXPECT_NEAR(glm::length(glm::dvec2(d.x, d.z)), std::hypot(0.2, 0.35), 1e-9);
    // The trigger is held from 3 s to 4 s of every 6 s.
    EXPECT_TRUE(walk.at(3.5).wand.pressed(0));
    EXPECT_FALSE(walk.at(4.5).wand.pressed(0));
}

TEST(TrackerSpec, BadSpecsAreErrors) {
    const struct {
        const char* spec;
        const char* message;
    } cases[] = {
        {"", "tracker '': expected SCHEME:TARGET"},
        {"walk", "tracker 'walk': expected SCHEME:TARGET"},
        {"usb:wand",
         "tracker 'usb:wand': unknown scheme 'usb' (expected one of: sim, file, replay, dtrack, opentrack, vrpn)"},
        {"sim:run", "unknown simulation 'run' (expected: walk)"},
        {"sim:walk?seed=-1", "seed: expected an integer in [0, 9223372036854775807], got \"-1\""},
        {"sim:walk?seed=1.5", "seed: expected an integer in [0, 9223372036854775807], got \"1.5\""},
        {"sim:walk?dropouts=maybe", "dropouts: expected 0, 1, true or false, got \"maybe\""},
        {"sim:walk?speed=2", "unknown parameter 'speed' (expected one of: seed, dropouts)"},
        {"sim:walk?seed", "expected parameters as key=value joined by '&', got 'seed'"},
        {"sim:walk?seed=1&seed=2", "seed: given more than once"},
        {"file:", "expected file:PATH, got an empty path"},
        {"file:/nonexistent/path.csv", "/nonexistent/path.csv"},
        {"file:track.txt", "track.txt: expected a .csv or .json path file, got extension '.txt'"},
        {"replay:", "expected replay:PATH, got an empty path"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.spec);
        EXPECT_THAT([&] { makeTracker(c.spec); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
}  // namespace cavewall::input
