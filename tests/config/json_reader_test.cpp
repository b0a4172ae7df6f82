#include "config/json_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cavewall::config {
namespace {

using ::testing::HasSubstr;

TEST(JsonReader, PathsNameNestedElements) {
    const auto doc = JsonDocument::fromText(R"({"a": {"b": [1, 2, {"c": true}]}})", "x.json");
    const auto items = doc.root().at("a").at("b").items();
    EXPECT_EQ(items[2].at("c").path(), "a.b[2].c");
    EXPECT_THAT([&] { items[2].at("c").number(); },
                ThrowsMessage<Error>(HasSubstr("x.json: a.b[2].c: expected a number, got true")));
}

TEST(JsonReader, IntegerAndRangeChecks) {
    const auto doc = JsonDocument::fromText(R"([3, 2.5, -7])", "x.json");
    const auto v = doc.root().items(3, 3);
    EXPECT_EQ(v[0].integer(0, 10), 3);
    EXPECT_THAT([&] { v[1].integer(0, 10); }, ThrowsMessage<Error>(HasSubstr("[1]: expected an integer, got 2.5")));
    EXPECT_THAT([&] { v[2].number(0, 1); },
                ThrowsMessage<Error>(HasSubstr("[2]: expected a number in [0, 1], got -7")));
}

TEST(JsonReader, RotationFromAnglesAndQuaternion) {
    const auto doc = JsonDocument::fromText(R"([{"pitchDeg": 90}, [0, 0, 0, 2]])", "x.json");
    const auto v = doc.root().items();
    // Pitch 90° turns forward (-Z) to up (+Y).
    const glm::dvec3 f = v[0].rotation() * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(f.y, 1.0, 1e-12);
    EXPECT_THAT([&] { v[1].rotation(); }, ThrowsMessage<Error>(HasSubstr("got length 2")));
}

TEST(JsonReader, LongStringsAreSummarised) {
    EXPECT_EQ(describeJson(std::string(100, 'x')), "a string of 100 characters");
    EXPECT_EQ(describeJson(nlohmann::json::array({1, 2})), "an array of 2");
}

}  // namespace
// Numbers for messages and reports: the shortest form, or a fixed number of decimals.
TEST(JsonReader, FormatsNumbersShortAndFixed) {
    EXPECT_EQ(formatNumber(0.064), "0.064");
    EXPECT_EQ(formatNumber(1e-9), "1e-09");
    EXPECT_EQ(formatFixed(59.5714, 1), "59.6");
    EXPECT_EQ(formatFixed(7.19701, 2), "7.20");
    EXPECT_EQ(formatFixed(3.0, 0), "3");
    EXPECT_EQ(formatFixed(-0.0004, 3), "-0.000");
    EXPECT_EQ(formatFixed(std::numeric_limits<double>::infinity(), 1), "inf");
    EXPECT_EQ(formatFixed(-std::numeric_limits<double>::infinity(), 1), "-inf");
    EXPECT_EQ(formatFixed(std::nan(""), 2), "nan");
    EXPECT_EQ(formatFixed(-std::nan(""), 2), "nan");  // not "-nan"
}

}  // namespace cavewall::config
