#include "tests/support/run_cli.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;

glm::dmat4 matrixFrom(const nlohmann::json& a) {
    glm::dmat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = a[i].get<double>();  // column-major
    return m;
}

glm::dvec3 vec3From(const nlohmann::json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}; }

TEST(FrustumCli, JsonMatricesMapEveryScreensCornersToNdcCorners) {
    const CliResult r =
        runCavewall({"frustum", "--display", "cave4", "--mono", "--eye", "0.4,1.5,-0.3", "--head-yaw", "30", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["screens"].size(), 4u);
    for (const auto& s : j["screens"]) {
        SCOPED_TRACE(s["name"].get<std::string>());
        const glm::dmat4 clipFromCave = matrixFrom(s["projection"]) * matrixFrom(s["view"]);
        // A reader outside the project gets clip = projection * view * cave, OpenGL NDC, y up.
        const glm::dvec4 ll = clipFromCave * glm::dvec4(vec3From(s["lowerLeft"]), 1);
        const glm::dvec4 ul = clipFromCave * glm::dvec4(vec3From(s["upperLeft"]), 1);
        EXPECT_NEAR(ll.x / ll.w, -1, 1e-9);
        EXPECT_NEAR(ll.y / ll.w, -1, 1e-9);
        EXPECT_NEAR(ul.y / ul.w, 1, 1e-9);
        EXPECT_EQ(s["eyePosition"], nlohmann::json::array({0.4, 1.5, -0.3}));  // mono: the head
    }
}

TEST(FrustumCli, BadInputGivesAClearErrorAndNonZeroExit) {
    const struct {
        std::vector<std::string> args;
        const char* message;
    } cases[] = {
        {{"frustum", "--display", "cave4", "--eye", "1,nan,2"}, "--eye: expected a finite number, got 'nan'"},
        {{"frustum", "--display", "cave4", "--eye", "1,2"}, "--eye: expected three comma-separated numbers"},
        {{"frustum", "--display", "nowhere.json"}, "nowhere.json: cannot open the file"},
        {{"frustum", "--eye", "0,1,0"}, "--display: required flag is missing"},
        {{"frustum", "--display", "cave4", "--bogus", "1"}, "--bogus: unknown flag"},
        // A stray word is an error, and an unknown last flag is named as unknown (not as a flag
        // expecting a value).
        {{"frustum", "--display", "cave4", "stray"}, "frustum: unexpected word 'stray' (expected only --flags)"},
        {{"frustum", "--display", "cave4", "--bogus"}, "--bogus: unknown flag (expected one of: --display"},
        {{"frustum", "--display", "cave4", "--eye"}, "--eye: expected a value after the flag, got nothing"},
        {{"frustum", "--display", "cave4", "--eye", "0,1e308,0", "--json"},
         "--eye: expected coordinates in [-1000, 1000] m, got 1e+308"},
        {{"frobnicate"}, "unknown command 'frobnicate'"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.message);
        const CliResult r = runCavewall(c.args);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

// cave4 is a stereo CAVE: a frustum per screen and eye, the eyes 0.064 m apart; --mono gives one
// per screen, from the head, and contradicting --stereo is an error.
TEST(FrustumCli, Cave4IsStereoAndMonoIsOneFlagAway) {
    const CliResult stereo = runCavewall({"frustum", "--display", "cave4", "--json"});
    ASSERT_EQ(stereo.exitCode, 0) << stereo.err;
    const auto s = nlohmann::json::parse(stereo.out)["screens"];
    ASSERT_EQ(s.size(), 8u);
    EXPECT_NEAR(glm::length(vec3From(s[0]["eyePosition"]) - vec3From(s[1]["eyePosition"])), 0.064, 1e-12);
    const CliResult mono = runCavewall({"frustum", "--display", "cave4", "--mono", "--json"});
    ASSERT_EQ(mono.exitCode, 0) << mono.err;
    EXPECT_EQ(nlohmann::json::parse(mono.out)["screens"].size(), 4u);
    const CliResult both = runCavewall({"bench", "x.json", "--mono", "--stereo", "separate"});
    EXPECT_NE(both.exitCode, 0);
    EXPECT_THAT(both.err, HasSubstr("--mono and --stereo separate: expected one stereo mode, got both"));
}

TEST(FrustumCli, EyeBehindAScreenIsGuardedAndFlagged) {
    // 2 m in front of the front wall is 0.5 m behind the back of cave4: fine for the front wall,
    // but z = -2 is behind the front wall itself.
    const CliResult r = runCavewall({"frustum", "--display", "cave4", "--mono", "--eye", "0,1.5,-2", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["screens"][0]["eyeGuard"], "behind");
    EXPECT_EQ(j["screens"][3]["eyeGuard"], "none");  // the floor is still below the eye
}

TEST(BenchCli, StabilityReportPassesEveryCase) {
    const CliResult r = runCavewall({"bench", "--stability"});
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("| near/far ratio 1e+09 | inversions |"));
    EXPECT_THAT(r.out, HasSubstr(", 0 failed"));
}

}  // namespace
}  // namespace cavewall::test
