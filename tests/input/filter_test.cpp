#include "input/dropout.h"
#include "input/one_euro.h"
#include "input/pose_math.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>

namespace cavewall::input {
namespace {

constexpr double kRate = 90.0;  // samples per second, a typical tracker

TEST(OneEuro, FirstSamplePassesAndRepeatedTimesAreIgnored) {
    OneEuroVec3 f;
    EXPECT_EQ(f.filter({1, 2, 3}, 0.0), glm::dvec3(1, 2, 3));
    // dt = 0 would divide by zero: the sample is ignored, the output stays finite and unchanged.
    EXPECT_EQ(f.filter({9, 9, 9}, 0.0), glm::dvec3(1, 2, 3));
    EXPECT_EQ(f.filter({9, 9, 9}, -1.0), glm::dvec3(1, 2, 3));
}

TEST(OneEuro, StepResponseIsMonotoneAndConverges) {
    OneEuroVec3 f;
    f.filter(glm::dvec3(0.0), 0.0);
    double prev = 0.0;
    for (int i = 1; i <= 2 * kRate; ++i) {
        const double x = f.filter({0.1, 0, 0}, i / kRate).x;  // a 10 cm step
        // A first-order low-pass with 0 < alpha < 1 moves towards the input and never past it.
        ASSERT_GE(x, prev);
        ASSERT_LE(x, 0.1);
        prev = x;
    }
    // After 2 s even the resting cutoff (1 Hz, tau = 0.16 s) has closed the gap to < 1e-5 m.
    EXPECT_NEAR(prev, 0.1, 1e-5);
}

TEST(OneEuro, ReducesJitterOfAStillHead) {
    OneEuroVec3 f;
    std::uint64_t rng = 11;
    double rawSq = 0.0, filteredSq = 0.0;
    int n = 0;
    for (int i = 0; i < 20 * kRate; ++i) {
        const glm::dvec3 noise(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
        const glm::dvec3 raw = glm::dvec3(0, 1.7, 0) + 0.001 * noise;  // ±1 mm jitter
        const glm::dvec3 out = f.filter(raw, i / kRate);
        if (i < kRate) continue;  // let the filter settle for 1 s
        rawSq += glm::dot(raw - glm::dvec3(0, 1.7, 0), raw - glm::dvec3(0, 1.7, 0));
        filteredSq += glm::dot(out - glm::dvec3(0, 1.7, 0), out - glm::dvec3(0, 1.7, 0));
        ++n;
    }
    const double rawRms = std::sqrt(rawSq / n), filteredRms = std::sqrt(filteredSq / n);
    std::printf("One Euro jitter: raw %.3f mm rms, filtered %.3f mm rms (%.1fx less)\n", rawRms * 1e3,
                filteredRms * 1e3, rawRms / filteredRms);
    // At rest the cutoff is about minCutoff (1 Hz) against a 45 Hz Nyquist band: white noise
    // drops by roughly sqrt(45 / (pi/2 * 1)) ≈ 5x; ask for at least 3x.
    EXPECT_LT(filteredRms, rawRms / 3.0);
}

TEST(OneEuro, FastMotionLagsLessThanSlowMotion) {
    // The cutoff rises with speed: the lag behind a ramp is a smaller fraction of the distance
    // travelled per second when moving fast.
    const auto lagAt = [](double speed) {
        OneEuroVec3 f;
        glm::dvec3 out(0.0);
        for (int i = 0; i <= 3 * kRate; ++i) out = f.filter({speed * i / kRate, 0, 0}, i / kRate);
        return (speed * 3.0 - out.x) / speed;  // seconds behind
    };
    EXPECT_LT(lagAt(1.0), 0.5 * lagAt(0.01));
    // At 1 m/s: cutoff ≈ 1 + 20 * 1 = 21 Hz, tau = 7.6 ms: lag about 8 ms.
    EXPECT_LT(lagAt(1.0), 0.015);
}

TEST(OneEuro, OrientationFollowsAndEstimatesAngularVelocity) {
    OneEuroQuat f;
    glm::dquat out;
    for (int i = 0; i <= 3 * kRate; ++i) out = f.filter(yawPitchRoll(0.5 * i / kRate, 0.0), i / kRate);  // 0.5 rad/s
    EXPECT_NEAR(f.angularVelocity().y, 0.5, 1e-3);
    EXPECT_NEAR(glm::length(glm::dvec2(f.angularVelocity().x, f.angularVelocity().z)), 0.0, 1e-9);
    // Exponential smoothing of a ramp lags by speed * dt * (1 - alpha) / alpha = speed * tau with
    // tau = 1 / (2π fc) and fc = minCutoff + beta * speed = 1 + 10 * 0.5 = 6 Hz: 0.01326 rad.
    EXPECT_NEAR(yawOf(forwardOf(out)), 1.5 - 0.5 / (2.0 * M_PI * 6.0), 1e-4);
}

TEST(Dropout, HoldsThenEasesToTheDefault) {
    const Pose home{{0, 1.7, 0}, {1, 0, 0, 0}}, seen{{1, 1.5, -1}, yawPitchRoll(1.0, 0.0)};
    DropoutPolicy p({0.5, 1.0}, home);
    EXPECT_EQ(p.update(0.0, std::nullopt), home);  // never seen: the default
    EXPECT_EQ(p.state(), TrackState::Default);
    EXPECT_EQ(p.update(1.0, seen), seen);
    EXPECT_EQ(p.state(), TrackState::Tracked);
    // Lost at 1.0: held unchanged through 1.5 s.
    EXPECT_EQ(p.update(1.2, std::nullopt), seen);
    EXPECT_EQ(p.update(1.5, std::nullopt), seen);
    EXPECT_EQ(p.state(), TrackState::Holding);
    // Halfway through the ease (2.0 s) smoothstep(0.5) = 0.5: the midpoint, yaw 0.5 rad.
    const Pose mid = p.update(2.0, std::nullopt);
    EXPECT_EQ(p.state(), TrackState::Easing);
    EXPECT_NEAR(glm::distance(mid.position, glm::dvec3(0.5, 1.6, -0.5)), 0.0, 1e-12);
    EXPECT_NEAR(yawOf(forwardOf(mid.orientation)), 0.5, 1e-12);
    // The ease is monotone and ends at the default at 2.5 s.
    EXPECT_LT(p.update(2.25, std::nullopt).position.x, 0.5);
    EXPECT_EQ(p.update(2.6, std::nullopt), home);
    EXPECT_EQ(p.state(), TrackState::Default);
    // Seen again: used at once.
    EXPECT_EQ(p.update(3.0, seen), seen);
}

TEST(Prediction, ConstantVelocityExtrapolation) {
    const Pose p{{1, 1.7, 0}, {1, 0, 0, 0}};
    const Pose q = predictPose(p, {0.5, 0, -1}, {0, 2.0, 0}, 0.05);
    // 50 ms at (0.5, 0, -1) m/s moves (0.025, 0, -0.05); 2 rad/s turns 0.1 rad about +Y.
    EXPECT_NEAR(glm::distance(q.position, glm::dvec3(1.025, 1.7, -0.05)), 0.0, 1e-15);
    EXPECT_NEAR(yawOf(forwardOf(q.orientation)), 0.1, 1e-12);
}

TEST(Prediction, BringsTheFilteredHeadCloserToWhereItWillBe) {
    // A head moving at 0.8 m/s and turning at 1 rad/s, 50 ms of latency.
    const double latency = 0.05;
    const auto truth = [](double t) { return Pose{{0.8 * t, 1.7, 0}, yawPitchRoll(1.0 * t, 0.0)}; };
    PipelineConfig withPrediction;
    withPrediction.latencySeconds = latency;
    TrackingPipeline predicted(withPrediction), plain(PipelineConfig{});
    TrackedFrame a, b;
    for (int i = 0; i <= 2 * kRate; ++i) {
        const double t = i / kRate;
        const Sample s{t, truth(t), truth(t), true, true, {}};
        a = predicted.update(s);
        b = plain.update(s);
    }
    const Pose future = truth(2.0 + latency);
    const double predictedError = glm::distance(a.head.pose.position, future.position);
    const double plainError = glm::distance(b.head.pose.position, future.position);
    std::printf("prediction over 50 ms at 0.8 m/s: error %.2f mm with, %.2f mm without\n", predictedError * 1e3,
                plainError * 1e3);
    // Without prediction the error is at least the 40 mm travelled during the latency.
    EXPECT_GT(plainError, 0.04);
    EXPECT_LT(predictedError, 0.25 * plainError);
    // The same for the yaw: the filter's lag remains (about 15 ms at 11 Hz cutoff), the 50 ms do not.
    const double yawError = std::fabs(angleDifference(yawOf(forwardOf(a.head.pose.orientation)), 2.0 + latency));
    const double plainYawError = std::fabs(angleDifference(yawOf(forwardOf(b.head.pose.orientation)), 2.0 + latency));
    EXPECT_GT(plainYawError, 0.05);
    EXPECT_LT(yawError, 0.4 * plainYawError);
}

TEST(Pipeline, CalibratesIntoTheCaveFrameAndHandlesDropouts) {
    PipelineConfig c;
    // Tracker origin 1.2 m up and 0.3 m behind the cave origin, axes turned 180° about +Y.
    c.caveFromTracker = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1.2, 0.3)) *
                        glm::mat4_cast(glm::angleAxis(M_PI, glm::dvec3(0, 1, 0)));
    c.position.enabled = c.orientation.enabled = false;  // see the calibration alone
    TrackingPipeline pipeline(c);
    Sample s;
    s.head.position = {0.1, 0.5, 0.2};
    s.headValid = true;
    const TrackedFrame f = pipeline.update(s);
    // Turned 180°: (0.1, 0.5, 0.2) -> (-0.1, 0.5, -0.2); plus (0, 1.2, 0.3).
    EXPECT_NEAR(glm::distance(f.head.pose.position, glm::dvec3(-0.1, 1.7, 0.1)), 0.0, 1e-12);
    // The tracker's forward (-Z) is the cave's +Z.
    EXPECT_NEAR(glm::distance(forwardOf(f.head.pose.orientation), glm::dvec3(0, 0, 1)), 0.0, 1e-12);
    EXPECT_EQ(f.hand.state, TrackState::Default);  // the hand was never valid
    EXPECT_EQ(f.hand.pose, c.defaultHand);
    // A NaN pose counts as a drop-out and never reaches the output.
    s.time = 0.1;
    s.head.position.x = NAN;
    const TrackedFrame g = pipeline.update(s);
    EXPECT_EQ(g.head.state, TrackState::Holding);
    EXPECT_TRUE(isFinite(g.head.pose));
}

TEST(Pipeline, ConfigAndContextFromTheDisplay) {
    // cave4: walls at x = ±1.5 and z = ±1.5, the head at (0, 1.7, 0).
    const config::DisplayConfig cave = config::loadDisplayConfig("cave4");
    const TrackerContext context = trackerContextFor(cave);
    EXPECT_EQ(context.floorMin, glm::dvec2(-1.5, -1.5));
    EXPECT_EQ(context.floorMax, glm::dvec2(1.5, 1.5));
    EXPECT_EQ(context.standingEyeHeight, 1.7);
    // desktop: one 0.6 m monitor 0.6 m ahead of a head at (0, 1.2, 0); the footprint (x in
    // [-0.3, 0.3], z in [-0.6, 0]) is widened to 1 m around its centre (0, -0.3).
    const TrackerContext desk = trackerContextFor(config::loadDisplayConfig("desktop"));
    EXPECT_NEAR(glm::distance(desk.floorMin, glm::dvec2(-0.5, -0.8)), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(desk.floorMax, glm::dvec2(0.5, 0.2)), 0.0, 1e-12);
    config::DisplayConfig tracked = cave;
    tracked.tracking.latencyMs = 25.0;
    const PipelineConfig c = pipelineConfigFor(tracked);
    EXPECT_EQ(c.latencySeconds, 0.025);
    EXPECT_EQ(c.defaultHead.position, glm::dvec3(0, 1.7, 0));
    // The default hand: 0.2 m right, 0.4 m down, 0.35 m ahead of the default head.
    EXPECT_NEAR(glm::distance(c.defaultHand.position, glm::dvec3(0.2, 1.3, -0.35)), 0.0, 1e-12);
}

}  // namespace
}  // namespace cavewall::input
