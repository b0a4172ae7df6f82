// The glTF loader on files made to crash it: sizes and offsets whose sums wrap around, counts
// that would allocate gigabytes, GLB headers that lie, JSON nested thousands deep, URIs naming
// folders. Each is a cavewall::Error saying where, what, expected vs got.
#include "config/error.h"
#include "scenes/loader.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <limits>

namespace cavewall::scenes {
namespace {

using testing::GltfBuilder;
using ::testing::HasSubstr;
using testing::testOutput;
using ::testing::ThrowsMessage;
using testing::triangleFile;

void put32(std::string& s, std::size_t at, std::uint32_t v) { std::memcpy(s.data() + at, &v, 4); }

// A GLB of the builder's document: JSON chunk padded with spaces, BIN chunk with zeros.
std::string glb(GltfBuilder b) {
    b.j["buffers"] = {{{"byteLength", b.bin.size()}}};
    std::string json = b.text();
    while (json.size() % 4) json += ' ';
    std::string bin(b.bin.begin(), b.bin.end());
    while (bin.size() % 4) bin += '\0';
    std::string out(12, '\0');
    out.replace(0, 4, "glTF");
    put32(out, 4, 2);
    out += std::string(8, '\0') + json + std::string(8, '\0') + bin;
    put32(out, 8, static_cast<std::uint32_t>(out.size()));
    put32(out, 12, static_cast<std::uint32_t>(json.size()));
    put32(out, 16, 0x4E4F534Au);
    put32(out, 20 + json.size(), static_cast<std::uint32_t>(bin.size()));
    put32(out, 24 + json.size(), 0x004E4942u);
    return out;
}

std::filesystem::path writeBytes(const std::string& name, const std::string& bytes) {
    const auto file = testOutput("gltf_hostile") / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

struct Case {
    const char* name;
    std::function<void(GltfBuilder&)> breakIt;
    const char* message;
};

TEST(GltfHostile, SizesFromTheFileAreCheckedWithoutOverflow) {
    const Case cases[] = {
        // offset + stride * (count - 1) wrapped around to a small number before (a SIGSEGV).
        {"byteOffset near 2^64",
         [](GltfBuilder& b) {
             b.j["accessors"][0]["byteOffset"] = 18446744073457893632ull;
             b.j["accessors"][0]["count"] = 1000000;
             b.j["bufferViews"][0]["byteStride"] = 252;
         },
         "broken.gltf: accessors[0]: 1000000 elements of 12 bytes, 252 apart from byte 18446744073457893632, need more "
         "than 2^64 bytes of bufferView 0 (expected at most 36)"},
        // 2^31 VEC3 doubles would be 48 GiB; the range check comes before the allocation.
        {"count 2^31", [](GltfBuilder& b) { b.j["accessors"][0]["count"] = 2147483648ull; },
         "broken.gltf: accessors[0]: 2147483648 elements of 12 bytes, 12 apart from byte 0, need 25769803776 bytes of "
         "bufferView 0 (expected at most 36)"},
        {"count 2^31 without a view",
         [](GltfBuilder& b) {
             b.j["accessors"][0].erase("bufferView");
             b.j["accessors"][0]["count"] = 2147483648ull;
         },
         "broken.gltf: accessors[0]: count 2147483648 without a bufferView (expected at most 16777216)"},
        {"sparse count -5",
         [](GltfBuilder& b) {
             b.j["accessors"][0]["sparse"] = {{"count", -5},
                                              {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
                                              {"values", {{"bufferView", 0}}}};
         },
         "broken.gltf: accessors[0].sparse.count: expected at least 1 sparse value, got -5"},
        {"buffer byteLength 0",
         [](GltfBuilder& b) {
             b.j["buffers"] = {{{"byteLength", 0}}};
         },
         "broken.gltf: not a valid glTF file"},
        {"buffer URI '.'",
         [](GltfBuilder& b) {
             b.j["buffers"] = {{{"byteLength", 36}, {"uri", "."}}};
         },
         "is not a regular file (expected a buffer or image file)"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        GltfBuilder b = triangleFile();
        c.breakIt(b);
        const auto file = writeBytes("broken.gltf", b.text());
        EXPECT_THAT([&] { loadGltf(file); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(GltfHostile, DeepJsonIsRefusedBeforeTheParserRecurses) {
    GltfBuilder b = triangleFile();
    std::string text = b.text();
    // 20,000 nested arrays in the asset's extras (tinygltf converts extras recursively).
    const std::string deep = std::string(20000, '[') + std::string(20000, ']');
    text.insert(text.find("\"asset\":{") + 9, "\"extras\":" + deep + ",");
    EXPECT_THAT([&] { loadGltf(writeBytes("deep.gltf", text)); },
                ThrowsMessage<Error>(HasSubstr("deep.gltf: JSON is nested too deeply at byte")));
    EXPECT_THAT([&] { loadGltf(writeBytes("deep.gltf", text)); },
                ThrowsMessage<Error>(HasSubstr("(expected at most 128 levels of arrays and objects, got more)")));
    // The same inside a GLB's JSON chunk.
    b.j["asset"]["extras"] = nlohmann::json::array();
    nlohmann::json* leaf = &b.j["asset"]["extras"];
    for (int i = 0; i < 500; ++i) leaf = &(*leaf = nlohmann::json::array({nlohmann::json::array()}))[0];
    EXPECT_THAT([&] { loadGltf(writeBytes("deep.glb", glb(b))); },
                ThrowsMessage<Error>(HasSubstr("deep.glb: JSON chunk: JSON is nested too deeply")));
    // Brackets inside strings do not count.
    GltfBuilder ok = triangleFile();
    ok.j["asset"]["generator"] = std::string(1000, '[');
    EXPECT_NO_THROW(loadGltf(writeBytes("brackets.glb", glb(ok))));
}

struct GlbCase {
    const char* name;
    std::function<void(std::string&)> breakIt;
    std::string message;
};

TEST(GltfHostile, GlbHeadersSayWhichChunkAndOffset) {
    const std::string good = glb(triangleFile());
    const std::uint32_t jsonLength = [&] {
        std::uint32_t v;
        std::memcpy(&v, good.data() + 12, 4);
        return v;
    }();
    const std::size_t binAt = 20 + jsonLength;
    const std::string at = std::to_string(binAt), at4 = std::to_string(binAt + 4);
    const GlbCase cases[] = {
        {"short header", [](std::string& s) { s.resize(7); },
         "GLB header at byte 0: the file is truncated (expected 12 bytes of header, got 7)"},
        {"version 1", [](std::string& s) { put32(s, 4, 1); },
         "GLB header at byte 4: unsupported version (expected 2, got 1)"},
        {"truncated file", [](std::string& s) { s.resize(s.size() - 10); },
         "GLB header at byte 8: total length is " + std::to_string(good.size()) + " but the file has " +
             std::to_string(good.size() - 10) + " bytes (expected at most " + std::to_string(good.size() - 10) +
             "; the file is truncated)"},
        {"JSON type", [](std::string& s) { put32(s, 16, 0x12345678u); },
         "GLB chunk 0 at byte 16: wrong chunk type (expected 0x4E4F534A, JSON, got 0x12345678)"},
        {"empty JSON", [](std::string& s) { put32(s, 12, 0); },
         "GLB chunk 0 (JSON) at byte 12: empty JSON chunk (expected a length of at least 1, got 0)"},
        {"JSON too long", [](std::string& s) { put32(s, 12, 0xFFFFFFF0u); },
         "GLB chunk 0 (JSON) at byte 12: length 4294967280 runs past the end"},
        {"BIN type", [binAt](std::string& s) { put32(s, binAt + 4, 0x41414141u); },
         "GLB chunk 1 at byte " + at4 + ": wrong chunk type (expected 0x004E4942, BIN, got 0x41414141)"},
        {"BIN length odd", [binAt](std::string& s) { put32(s, binAt, 3); },
         "GLB chunk 1 (BIN) at byte " + at + ": bad length (expected a multiple of 4 of at least 4, got 3)"},
        // tinygltf compared the BIN length without its 8-byte header: 8 bytes past the end.
        {"BIN length 8 too long",
         [binAt](std::string& s) {
             std::uint32_t n;
             std::memcpy(&n, s.data() + binAt, 4);
             put32(s, binAt, n + 8);
         },
         "GLB chunk 1 (BIN) at byte " + at +
             ": length 44 runs past the end (expected at most 36 bytes after the "
             "chunk header)"},
    };
    for (const GlbCase& c : cases) {
        SCOPED_TRACE(c.name);
        std::string bytes = good;
        c.breakIt(bytes);
        const auto file = writeBytes("broken.glb", bytes);
        EXPECT_THAT([&] { loadGltf(file); }, ThrowsMessage<Error>(HasSubstr("broken.glb: " + c.message)));
    }
    EXPECT_NO_THROW(loadGltf(writeBytes("good.glb", good)));
}

// No "scenes" and every node somebody's child: before, nothing was drawn and nothing said.
TEST(GltfHostile, NodeCycleWithoutScenesIsAnError) {
    GltfBuilder b = triangleFile();
    b.addNode({{"children", {0}}});
    b.j["nodes"][0]["children"] = {1};
    std::string text = b.text();
    nlohmann::json j = nlohmann::json::parse(text);
    j.erase("scenes");
    EXPECT_THAT([&] { loadGltf(writeBytes("cycle.gltf", j.dump())); },
                ThrowsMessage<Error>(HasSubstr("cycle.gltf: nodes[1].children[0]: node 0 is its own ancestor "
                                               "(expected a tree, got a cycle)")));
}

TEST(GltfHostile, FarAwayNodesAreSkippedWithTheirName) {
    GltfBuilder b = triangleFile();
    b.j["nodes"][0]["name"] = "far-pump";
    b.j["nodes"][0]["matrix"] = {1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    b.addNode({{"mesh", 0}, {"name", "near"}, {"translation", {1, 2, 3}}});
    const Scene s = loadGltf(writeBytes("far.gltf", b.text()));
    ASSERT_EQ(s.objects.size(), 1u);  // the near one is drawn
    EXPECT_EQ(s.objects[0].name, "near");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_THAT(s.warnings[0], HasSubstr("scene 'far.gltf': node 0 ('far-pump'): ignoring mesh 'mesh 0' because its "
                                         "transform places it at (5e+299, 0.5, 0) (expected within 1e+09 units"));
}

// Exporters write NaN normals on degenerate triangles: those are made again from the
// triangles (here the unit triangle in z = 0, so +Z), the others stay as stored.
TEST(GltfHostile, NonFiniteNormalsAreRegeneratedWithAWarning) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int nrm = b.addFloats({0, 0, 1, nan, nan, nan, 0, 0, 1}, "VEC3", 3);
    b.j["meshes"].push_back(
        {{"name", "bracket"}, {"primitives", {{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}}}}});
    b.addNode({{"mesh", 0}});
    const Scene s = loadGltf(writeBytes("nan_normals.gltf", b.text()));
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].normals[1], glm::vec3(0, 0, 1));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_THAT(s.warnings[0], HasSubstr("mesh 'bracket': regenerated 1 of 3 normals that were not finite"));
    // A NaN elsewhere (texture coordinates) still refuses the file: it cannot be drawn right.
    const int uv = b.addFloats({0, 0, nan, 0, 1, 1}, "VEC2", 2);
    b.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
    EXPECT_THAT([&] { loadGltf(writeBytes("nan_uv.gltf", b.text())); },
                ThrowsMessage<Error>(HasSubstr("attributes.TEXCOORD_0: contains a value that is not finite")));
}

}  // namespace
}  // namespace cavewall::scenes
