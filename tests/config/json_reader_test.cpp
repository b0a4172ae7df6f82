#include "config/json_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
}  // namespace cavewall::config
