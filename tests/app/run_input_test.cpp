// The clock of a session's input (app/run_input.h): a person's session moves at its stated
// speed whatever the frame rate; simulated sessions step 1/60 s a frame.
#include "app/run_input.h"

#include "config/display_config.h"
#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>

namespace cavewall::app {
namespace {

using namespace std::chrono_literals;

// A 40 m hall: a floor slab, nothing in the way of a flight along -Z from its middle.
scenes::Scene hall() {
    scenes::Scene s;
    s.meshes.push_back(scenes::makeBox(glm::vec3(40.0f, 0.2f, 40.0f), glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)));
    scenes::addObject(s, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -0.1, 0.0)), "floor");
    return s;
}

RunOptions desktopOptions() {
    RunOptions o;
    o.display = config::loadDisplayConfig("desktop");
    o.tracker = "desktop";
    o.window = WindowMode::Window;
    o.nav = Navigation::Fly;
    return o;
}

// A clock that only moves when the test (or a sleep) moves it.
struct FakeClock {
    LiveClock::TimePoint now{};
    std::vector<LiveClock::TimePoint> sleeps;
    LiveClock clock() {
        return {[this] { return now; },
                [this](LiveClock::TimePoint t) {
                    sleeps.push_back(t);
                    now = std::max(now, t);
                }};
    }
};

glm::dvec3 eye(const walkthrough::FrameInput& in) {
    return glm::dvec3(in.worldFromCave * glm::dvec4(in.head.position, 1.0));
}

const input::Event kForward{input::EventType::KeyDown, 0.0, 'W', {}};

// Frames 0 and 1 (W pressed at frame 1), then `frames` more, each `drawing` apart on the fake
// clock; returns the distance flown over those frames and the last frame's time.
std::pair<double, double> fly(RunInput& input, FakeClock& fake, int frames, LiveClock::TimePoint::duration drawing) {
    input.next(0, false);
    fake.now += drawing;
    const glm::dvec3 start = eye(input.next(1, false, {kForward}));
    walkthrough::FrameInput in;
    for (int i = 2; i < 2 + frames; ++i) {
        fake.now += drawing;
        in = input.next(i, false);
    }
    return {glm::distance(eye(in), start), in.time};
}

TEST(RunInput, ADesktopSessionMovesAtItsSpeedWhateverTheFrameRate) {
    const scenes::Scene scene = hall();
    const scenes::SceneDescription description;
    for (const auto drawing : {100ms, 40ms}) {
        SCOPED_TRACE(std::chrono::duration<double>(drawing).count());
        FakeClock fake;
        RunInput input(desktopOptions(), scene, description, true, fake.clock());
        const double seconds = std::chrono::duration<double>(drawing).count();
        const auto [flown, t] = fly(input, fake, 10, drawing);
        ASSERT_TRUE(input.speed());
        // Ten frames drawn `drawing` apart: the clock's time, and the speed times that time.
        EXPECT_NEAR(t, 11 * seconds, 1e-9);
        EXPECT_NEAR(flown, *input.speed() * 10 * seconds, 1e-6);
        EXPECT_TRUE(fake.sleeps.empty());  // never ahead of the clock
    }
}

TEST(RunInput, AFastDesktopSessionIsHeldToSixtyFramesASecond) {
    const scenes::Scene scene = hall();
    FakeClock fake;
    RunInput input(desktopOptions(), scene, {}, true, fake.clock());
    const auto [flown, t] = fly(input, fake, 10, 1ms);
    EXPECT_NEAR(t, 11 * kRunStep, 1e-9);
    EXPECT_NEAR(flown, *input.speed() * 10 * kRunStep, 1e-6);
    EXPECT_EQ(fake.sleeps.size(), 11u);  // every frame after the first waited for its time
}

TEST(RunInput, AStalledFrameMovesTheViewerAQuarterSecondAtMost) {
    const scenes::Scene scene = hall();
    FakeClock fake;
    RunInput input(desktopOptions(), scene, {}, true, fake.clock());
    const auto [flown, t] = fly(input, fake, 1, 2s);
    EXPECT_NEAR(t, 4.0, 1e-9);  // the clock's time goes on
    EXPECT_NEAR(flown, *input.speed() * kMaxLiveStep, 1e-6);
}

TEST(RunInput, WithoutRealTimeEveryFrameIsOneSixtiethOfASecond) {
    const scenes::Scene scene = hall();
    FakeClock fake;
    RunInput input(desktopOptions(), scene, {}, false, fake.clock());
    const auto [flown, t] = fly(input, fake, 10, 100ms);
    EXPECT_DOUBLE_EQ(t, 11 * kRunStep);
    EXPECT_NEAR(flown, *input.speed() * 10 * kRunStep, 1e-6);
    EXPECT_TRUE(fake.sleeps.empty());
}

// A scene's walk path runs over its floors: the desktop walks it at walking pace, as it does
// from a start found standing on a floor, not at the building's diagonal / 20.
TEST(RunInput, AWalkPathIsWalkedAtWalkingPace) {
    const scenes::Scene scene = hall();  // 56.6 m diagonal: 2.83 m/s in the air
    RunInput air(desktopOptions(), scene, {}, false);
    ASSERT_TRUE(air.speed());
    EXPECT_NEAR(*air.speed(), glm::length(scene.bounds().size()) / 20.0, 1e-9);
    EXPECT_GT(*air.speed(), input::kWalkingSpeed);
    scenes::SceneDescription path;
    path.walkPath = {{0.0, 1.7, 10.0}, {0.0, 1.7, -10.0}};
    RunInput walk(desktopOptions(), scene, path, false);
    ASSERT_TRUE(walk.speed());
    EXPECT_DOUBLE_EQ(*walk.speed(), input::kWalkingSpeed);
}

}  // namespace
}  // namespace cavewall::app
