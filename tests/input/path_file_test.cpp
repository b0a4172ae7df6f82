#include "input/path_file.h"
#include "input/pose_math.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace cavewall::input {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Four samples at uneven times; the head turns from yaw 0 to yaw 90° between 1 s and 3 s.
const char* const kCsv =
    "# a recorded head\n"
    "t,x,y,z,qx,qy,qz,qw\n"
    "0, 0,1.7,0, 0,0,0,1\n"
    "1, 1,1.7,0, 0,0,0,1\n"
    "3, 1,1.5,2, 0,0.70710678118654752,0,0.70710678118654752\n"
    "3.5, 0,1.7,2, 0,0.70710678118654752,0,0.70710678118654752\n";

std::filesystem::path outputDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    std::filesystem::path p = dir ? dir : std::filesystem::temp_directory_path();
    std::filesystem::create_directories(p);
    return p;
}

TEST(PathFile, SplinePassesThroughEverySample) {
    const RecordedPath path = parsePathCsv(kCsv, "head.csv");
    ASSERT_EQ(path.head.size(), 4u);
    EXPECT_TRUE(path.hand.empty());
    for (const PathKey& k : path.head) {
        SCOPED_TRACE(k.time);
        // Hermite interpolation is exact at the knots.
        EXPECT_EQ(interpolatePath(path.head, k.time).position, k.pose.position);
    }
    // Outside the samples the path holds its ends.
    EXPECT_EQ(interpolatePath(path.head, -1.0).position, path.head.front().pose.position);
    EXPECT_EQ(interpolatePath(path.head, 9.0).position, path.head.back().pose.position);
}

TEST(PathFile, SplineIsC1AcrossSamples) {
    const RecordedPath path = parsePathCsv(kCsv, "head.csv");
    // The velocity just before and just after an inner sample agree (C1); a piecewise-linear
    // path would jump from (1, 0, 0) m/s to (0, -0.1, 1) m/s at t = 1.
    const double h = 1e-6;
    for (double t : {1.0, 3.0}) {
        SCOPED_TRACE(t);
        const glm::dvec3 before =
            (interpolatePath(path.head, t).position - interpolatePath(path.head, t - h).position) / h;
        const glm::dvec3 after =
            (interpolatePath(path.head, t + h).position - interpolatePath(path.head, t).position) / h;
        EXPECT_LT(glm::distance(before, after), 1e-4);
    }
}

TEST(PathFile, OrientationSlerpMidpoint) {
    const RecordedPath path = parsePathCsv(kCsv, "head.csv");
    // Halfway between yaw 0 (t = 1) and yaw 90° (t = 3) is yaw 45°.
    const glm::dvec3 forward = forwardOf(interpolatePath(path.head, 2.0).orientation);
    EXPECT_NEAR(yawOf(forward), M_PI / 4, 1e-12);
    EXPECT_NEAR(forward.y, 0.0, 1e-12);
}

TEST(PathFile, JsonWithHandAndEulerAngles) {
    const RecordedPath path = parsePathJson(
        R"({"samples": [{"t": 0, "position": [0, 1.7, 0], "orientation": {"yawDeg": 0},
                         "hand": {"position": [0.2, 1.3, -0.3], "orientation": [0, 0, 0, 1]}},
                        {"t": 2, "position": [2, 1.7, 0], "orientation": {"yawDeg": 90},
                         "hand": {"position": [2.2, 1.3, -0.3], "orientation": [0, 0, 0, 1]}}]})",
        "walk.json");
    ASSERT_EQ(path.hand.size(), 2u);
    // Two samples: the tangents are the chord, so the spline is the straight line at constant speed.
    EXPECT_NEAR(glm::distance(interpolatePath(path.head, 0.5).position, glm::dvec3(0.5, 1.7, 0)), 0.0, 1e-12);
    EXPECT_NEAR(yawOf(forwardOf(interpolatePath(path.head, 1.0).orientation)), M_PI / 4, 1e-12);
    EXPECT_NEAR(interpolatePath(path.hand, 1.0).position.x, 1.2, 1e-12);
}

struct BadFile {
    const char* name;
    std::string text;
    bool json;
    const char* message;
};

TEST(PathFile, BadFilesNameTheLineOrJsonPath) {
    const BadFile cases[] = {
        {"empty", "", false, "p.csv: expected a header line t,x,y,z,qx,qy,qz,qw, got an empty file"},
        {"wrong header", "time,x,y,z\n", false, "p.csv:1: expected the header t,x,y,z,qx,qy,qz,qw"},
        {"short row", "t,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,0\n", false, "p.csv:3: expected 8 values, got 3"},
        {"word", "t,x,y,z,qx,qy,qz,qw\n0,0,abc,0,0,0,0,1\n", false,
         "p.csv:2: column y: expected a finite number, got 'abc'"},
        {"nan", "t,x,y,z,qx,qy,qz,qw\n0,nan,0,0,0,0,0,1\n", false,
         "p.csv:2: column x: expected a finite number, got 'nan'"},
        {"zero quaternion", "t,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,0\n", false,
         "p.csv:2: expected a unit quaternion, got one of length 0"},
        {"time backwards", "t,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n2,0,0,0,0,0,0,1\n1,0,0,0,0,0,0,1\n", false,
         "p.csv:4: times must strictly increase (expected more than 2, got 1)"},
        {"one sample", "t,x,y,z,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n", false, "p.csv: expected at least 2 samples, got 1"},
        {"json one sample", R"({"samples": [{"t": 0, "position": [0,0,0], "orientation": [0,0,0,1]}]})", true,
         "p.json: samples: expected an array of at least 2 elements, got 1"},
        {"json bad position", R"({"samples": [{"t": 0, "position": [0,0], "orientation": [0,0,0,1]}, {}]})", true,
         "p.json: samples[0].position: expected an array of 3 elements, got 2"},
        {"json time", R"({"samples": [{"t": 1, "position": [0,0,0], "orientation": [0,0,0,1]},
                                      {"t": 1, "position": [0,0,0], "orientation": [0,0,0,1]}]})",
         true, "p.json: samples[1].t: times must strictly increase (expected more than 1, got 1)"},
        {"json hand missing",
         R"({"samples": [{"t": 0, "position": [0,0,0], "orientation": [0,0,0,1], "hand": {"position": [0,0,0], "orientation": [0,0,0,1]}},
                                              {"t": 1, "position": [0,0,0], "orientation": [0,0,0,1]}]})",
         true, "p.json: samples[1]: missing required key 'hand' (the first sample has one)"},
        {"json typo", R"({"samples": [{"t": 0, "postion": [0,0,0]}, {}]})", true,
         "p.json: samples[0]: unknown key 'postion'"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { c.json ? parsePathJson(c.text, "p.json") : parsePathCsv(c.text, "p.csv"); },
                    ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(PathFile, SourcePlaysFromItsFirstPollAndLoops) {
    const auto file = outputDir() / "path_source.csv";
    std::ofstream(file) << kCsv;
    auto once = makeTracker("file:" + file.string());
    auto looped = makeTracker("file:" + file.string() + "?loop=1");
    // The first poll (at 100 s) maps to the first sample (t = 0).
    EXPECT_EQ(once->poll(100.0).head.position, glm::dvec3(0, 1.7, 0));
    EXPECT_EQ(once->poll(101.0).head.position, glm::dvec3(1, 1.7, 0));
    EXPECT_EQ(once->poll(110.0).head.position, glm::dvec3(0, 1.7, 2));  // held at the end
    looped->poll(100.0);
    // 3.5 s long: 104.5 s is 4.5 s in, wrapping to 1 s.
    EXPECT_NEAR(glm::distance(looped->poll(104.5).head.position, glm::dvec3(1, 1.7, 0)), 0.0, 1e-12);
    EXPECT_TRUE(once->poll(111.0).headValid);
    EXPECT_FALSE(once->poll(111.0).handValid);  // no hand columns
}

}  // namespace
}  // namespace cavewall::input
