#include "hierarchy/cluster_cache.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cavewall::hierarchy {
namespace {

using ::testing::HasSubstr;

ClusterRecord record() {
    ClusterRecord r;
    for (int f = 0; f < kBoxFaces; ++f) {
        r.faces[f] = {glm::vec3(0.25f, 0.5f, 0.125f), 0.75f};
        for (int g = 0; g < kFaceRegions; ++g)
            r.files[impostorFileName(f, g)] = {static_cast<std::uint64_t>(100 + f * 10 + g), 0x0123456789abcdefull};
    }
    r.accuracy.textured.fill(0.875);
    r.accuracy.average.fill(0.5);
    return r;
}

TEST(ClusterCache, ARecordReadsBackAsWritten) {
    const ClusterRecord r = record();
    EXPECT_EQ(parseClusterRecord(clusterRecordJson(r), "cluster.json"), r);
    // Another version is stale: nothing else is read.
    EXPECT_EQ(parseClusterRecord(R"({"version": 1, "averages": []})", "cluster.json").version, 1);
}

// Every field is checked, and the message names the file and the field.
TEST(ClusterCache, ABadRecordIsRefusedByFileAndField) {
    nlohmann::json good = nlohmann::json::parse(clusterRecordJson(record()));
    const struct {
        const char* name;
        void (*edit)(nlohmann::json&);
        const char* message;
    } cases[] = {
        {"coverage", [](nlohmann::json& j) { j["averages"][2][3] = 1.5; }, "c.json: averages[2][3]"},
        {"a face missing", [](nlohmann::json& j) { j["averages"].erase(5); }, "c.json: averages"},
        {"accuracy below 0", [](nlohmann::json& j) { j["textured"][0] = -0.1; }, "c.json: textured[0]"},
        {"a file missing", [](nlohmann::json& j) { j["files"].erase("f5r4.tx"); }, "f5r4.tx"},
        {"an extra file",
         [](nlohmann::json& j) {
             j["files"]["../x.tx"] = {{"bytes", 1}, {"hash", "0"}};
         },
         "expected only the 30 files"},
        {"a bad hash", [](nlohmann::json& j) { j["files"]["f0r0.tx"]["hash"] = "xyz"; }, "expected 16 lowercase hex"},
        {"no bytes", [](nlohmann::json& j) { j["files"]["f0r0.tx"]["bytes"] = 0; }, "files.f0r0.tx.bytes"},
        {"an unknown key", [](nlohmann::json& j) { j["extra"] = 1; }, "extra"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        nlohmann::json j = good;
        c.edit(j);
        EXPECT_THAT([&] { parseClusterRecord(j.dump(), "c.json"); },
                    ::testing::ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    EXPECT_THAT([] { parseClusterRecord("{\"version\": 2, ", "c.json"); },
                ::testing::ThrowsMessage<Error>(HasSubstr("c.json")));
}

std::vector<scenes::Image> chain(std::vector<glm::ivec2> sizes) {
    std::vector<scenes::Image> levels;
    for (glm::ivec2 s : sizes)
        levels.push_back({"l", s.x, s.y, std::vector<std::uint8_t>(static_cast<std::size_t>(s.x) * s.y * 4)});
    return levels;
}

TEST(ClusterCache, ImpostorLevelsMustBeTheFacesMipChain) {
    EXPECT_EQ(impostorLevelsProblem(chain({{8, 5}, {4, 2}, {2, 1}, {1, 1}}), {8, 5}), "");
    EXPECT_EQ(impostorLevelsProblem(chain({{16, 16}}), {8, 5}), "MIP level 0: expected 8 x 5 texels, got 16 x 16");
    EXPECT_EQ(impostorLevelsProblem(chain({{8, 5}, {4, 2}}), {8, 5}),
              "expected MIP levels down to 1 x 1, got 2 ending at 4 x 2");
    EXPECT_EQ(impostorLevelsProblem(chain({{1, 1}, {1, 1}}), {1, 1}), "expected 1 MIP levels down to 1 x 1, got 2");
    std::vector<scenes::Image> shortRgba = chain({{2, 2}, {1, 1}});
    shortRgba[0].rgba.resize(3);
    EXPECT_EQ(impostorLevelsProblem(shortRgba, {2, 2}), "MIP level 0: expected RGBA8 texels");
    EXPECT_EQ(impostorLevelsProblem({}, {2, 2}), "expected MIP levels down to 1 x 1, got 0 ending at none");
}

}  // namespace
}  // namespace cavewall::hierarchy
