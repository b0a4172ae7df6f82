// The glTF loader on broken and hostile files: every problem is a cavewall::Error naming the
// file and the glTF path; nothing crashes.
#include "config/error.h"
#include "scenes/loader.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cctype>
#include <functional>
#include <limits>

namespace cavewall::scenes {
namespace {

using testing::GltfBuilder;
using ::testing::HasSubstr;
using testing::testOutput;
using ::testing::ThrowsMessage;
using testing::triangleFile;

struct ErrorCase {
    const char* name;
    std::function<void(GltfBuilder&)> breakIt;
    const char* message;
};

TEST(GltfLoader, BrokenFilesNameTheFileAndTheGltfPath) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ErrorCase cases[] = {
        {"accessor index", [](GltfBuilder& b) { b.j["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7; },
         "broken.gltf: meshes[0].primitives[0].attributes.POSITION: accessor 7 is out of range (expected < 1 "
         "accessors)"},
        {"vertex index",
         [](GltfBuilder& b) {
             b.j["meshes"][0]["primitives"][0]["indices"] = b.addIndices(std::vector<std::uint16_t>{0, 1, 3});
         },
         "broken.gltf: meshes[0].primitives[0].indices: index 3 at position 2 is out of range (expected < 3 vertices)"},
        {"accessor past its view", [](GltfBuilder& b) { b.j["accessors"][0]["count"] = 4; },
         "broken.gltf: accessors[0]: 4 elements of 12 bytes, 12 apart from byte 0, need 48 bytes of bufferView 0 "
         "(expected at most 36)"},
        {"truncated buffer", [](GltfBuilder& b) { b.j["bufferViews"][0]["byteLength"] = 400; },
         "broken.gltf: bufferViews[0]: byte range 0 + 400 exceeds buffer 0"},
        {"NaN position", [nan](GltfBuilder& b) { std::memcpy(b.bin.data() + 4, &nan, 4); },
         "broken.gltf: meshes[0].primitives[0].attributes.POSITION: vertex 0 is not finite"},
        {"wrong attribute type",
         [](GltfBuilder& b) {
             b.j["accessors"][0]["type"] = "VEC2";
             b.j["accessors"][0]["count"] = 2;
         },
         "broken.gltf: meshes[0].primitives[0].attributes.POSITION: accessor 0 has type VEC2 (expected VEC3)"},
        {"node mesh", [](GltfBuilder& b) { b.j["nodes"][0]["mesh"] = 3; },
         "broken.gltf: nodes[0].mesh: mesh 3 is out of range (expected < 1 meshes)"},
        {"node cycle",
         [](GltfBuilder& b) {
             b.j["nodes"][0]["children"] = {0};
             b.j["scenes"] = {{{"nodes", {0}}}};
         },
         "broken.gltf: nodes[0].children[0]: node 0 is its own ancestor (expected a tree, got a cycle)"},
        {"material", [](GltfBuilder& b) { b.j["meshes"][0]["primitives"][0]["material"] = 2; },
         "broken.gltf: meshes[0].primitives[0].material: material 2 is out of range (expected < 0 materials)"},
        {"required extension", [](GltfBuilder& b) { b.j["extensionsRequired"] = {"EXT_lights_image_based"}; },
         "broken.gltf: extensionsRequired[0]: extension 'EXT_lights_image_based' is not supported"},
        {"texture",
         [](GltfBuilder& b) {
             b.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 4}}}}}}};
         },
         "broken.gltf: materials[0].pbrMetallicRoughness.baseColorTexture.index: texture 4 is out of range"},
    };
    for (const ErrorCase& c : cases) {
        SCOPED_TRACE(c.name);
        GltfBuilder b = triangleFile();
        c.breakIt(b);
        const auto file = b.write("broken.gltf");
        EXPECT_THAT([&] { loadGltf(file); }, ThrowsMessage<Error>(HasSubstr(c.message)));
        EXPECT_THAT([&] { loadGltf(file); }, ThrowsMessage<Error>(HasSubstr(file.string() + ": ")));
    }
}

TEST(GltfLoader, DeepHierarchiesAreRefusedNotOverflowed) {
    GltfBuilder b = triangleFile();
    for (int i = 1; i <= 1200; ++i) b.addNode({{"children", {i - 1}}});  // node i parents node i - 1
    b.j["scenes"] = {{{"nodes", {1200}}}};
    EXPECT_THAT([&] { loadGltf(b.write("deep.gltf")); },
                ThrowsMessage<Error>(HasSubstr("the node hierarchy is deeper than 1000 levels")));
}

TEST(GltfLoader, UnreadableFilesNameTheFile) {
    const auto dir = testOutput("gltf");
    std::ofstream(dir / "bad.gltf") << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [";
    EXPECT_THAT([&] { loadGltf(dir / "bad.gltf"); },
                ThrowsMessage<Error>(HasSubstr("bad.gltf: not a valid glTF file")));
    EXPECT_THAT([&] { loadGltf(dir / "missing.glb"); },
                ThrowsMessage<Error>(HasSubstr("missing.glb: cannot open the glTF file")));
    GltfBuilder b = triangleFile();
    const auto file = b.write("nobin.gltf", false, "absent.bin");
    EXPECT_THAT([&] { loadGltf(file); }, ThrowsMessage<Error>(HasSubstr("nobin.gltf: not a valid glTF file")));
    std::ofstream(dir / "short.glb", std::ios::binary) << "glTF\x02";
    EXPECT_THAT(
        [&] { loadGltf(dir / "short.glb"); },
        ThrowsMessage<Error>(HasSubstr("short.glb: GLB header at byte 0: the file is truncated (expected 12 bytes "
                                       "of header, got 5)")));
    // An external buffer file shorter than its byteLength (36 bytes of positions, 20 written).
    std::ofstream(dir / "cut.bin", std::ios::binary).write(reinterpret_cast<const char*>(b.bin.data()), 20);
    EXPECT_THAT([&] { loadGltf(b.write("cut.gltf", false, "cut.bin")); },
                ThrowsMessage<Error>(HasSubstr("cut.gltf: not a valid glTF file: File size mismatch")));
}

// Digits changed at random in the JSON (indices, counts, offsets, strides) and bytes changed in
// the buffer: every load either succeeds or throws cavewall::Error; nothing crashes (run under
// the sanitizers to catch out-of-range reads).
TEST(GltfLoader, CorruptedFilesThrowErrorsButNeverCrash) {
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    const int nrm = b.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int uv = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2", 2);
    const int idx = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}},
                                   {"indices", idx},
                                   {"mode", 4}})}});
    b.addNode({{"mesh", 0}, {"children", {0}}});
    const std::string text = b.text();
    const auto file = testOutput("gltf") / "fuzz.gltf";
    std::uint64_t state = 12345;
    auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return state >> 33;
    };
    int loaded = 0, refused = 0;
    for (int i = 0; i < 400; ++i) {
        std::string t = text;
        for (int k = 0; k < 3; ++k) {
            const std::size_t at = next() % t.size();
            if (std::isdigit(static_cast<unsigned char>(t[at])))
                t[at] = static_cast<char>('0' + next() % 10);
            else if (at > t.find("base64,") && t[at] != '"')
                t[at] = "AZaz09+/"[next() % 8];  // buffer bytes
        }
        std::ofstream(file, std::ios::binary) << t;
        try {
            const Scene s = loadGltf(file);
            for (const Mesh& m : s.meshes)
                for (std::uint32_t v : m.indices) ASSERT_LT(v, m.positions.size());
            ++loaded;
        } catch (const Error&) {
            ++refused;
        }
    }
    // Both outcomes happen: the mutations are neither all harmless nor all fatal.
    EXPECT_GT(loaded, 0);
    EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace cavewall::scenes
