// Compressed glTF: EXT_meshopt_compression files built here with meshoptimizer's encoders
// (exact round trips, every rule's message), and files that Debian's gltfpack and
// draco_transcoder write from shared models (the pack_compressed.cmake fixture), compared with
// the originals. Images are compared in tests/render/gl/compressed_scenes_gl_test.cpp.
#include "config/error.h"
#include "scenes/loader.h"
#include "tests/scenes/gltf_builder.h"
#include "tests/scenes/packed_variants.h"

#include <meshoptimizer.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace cavewall::scenes {
namespace {

using testing::GltfBuilder;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using Json = nlohmann::json;

const std::filesystem::path kReal = CAVEWALL_REAL_SCENES;
const std::filesystem::path kPacked = CAVEWALL_BINARY_DIR "/tests/scenes/packed";

// Triangles with each one's smallest index first: meshopt's index codec keeps every triangle
// and its winding but may rotate its three indices.
std::vector<std::uint32_t> rotated(std::vector<std::uint32_t> v) {
    for (std::size_t t = 0; t + 2 < v.size(); t += 3)
        while (v[t] > v[t + 1] || v[t] > v[t + 2]) std::rotate(v.begin() + t, v.begin() + t + 1, v.begin() + t + 3);
    return v;
}

// A 9 x 9 vertex patch of z = 0.2 sin(x) cos(y) over [0, 2]², 128 triangles, with unit
// normals and texture coordinates.
struct Patch {
    std::vector<float> positions, normals4, texCoords;  // xyz, xyzw (w = 0), uv
    std::vector<std::uint32_t> indices;
    static constexpr int kSide = 9;
    Patch() {
        for (int j = 0; j < kSide; ++j)
            for (int i = 0; i < kSide; ++i) {
                const float x = 2.0f * i / (kSide - 1), y = 2.0f * j / (kSide - 1);
                positions.insert(positions.end(), {x, y, 0.2f * std::sin(x) * std::cos(y)});
                // The surface's normal: (-dz/dx, -dz/dy, 1), normalised.
                glm::vec3 n(-0.2f * std::cos(x) * std::cos(y), 0.2f * std::sin(x) * std::sin(y), 1.0f);
                n = glm::normalize(n);
                normals4.insert(normals4.end(), {n.x, n.y, n.z, 0.0f});
                texCoords.insert(texCoords.end(), {x / 2.0f, 1.0f - y / 2.0f});
            }
        for (std::uint32_t j = 0; j + 1 < kSide; ++j)
            for (std::uint32_t i = 0; i + 1 < kSide; ++i) {
                const std::uint32_t a = j * kSide + i, b = a + 1, c = a + kSide, d = c + 1;
                indices.insert(indices.end(), {a, b, d, a, d, c});
            }
    }
    std::size_t vertices() const { return positions.size() / 3; }
};

// The patch as EXT_meshopt_compression with a fallback buffer: positions unfiltered (exact),
// normals with the octahedral filter (8 bits), texture coordinates with the exponential
// filter (16-bit mantissa), indices in TRIANGLES mode. bufferViews 0-2 are the attributes, 3
// the indices; buffer 0 holds the compressed bytes, buffer 1 is the fallback.
GltfBuilder meshoptPatch(const Patch& p) {
    const std::size_t n = p.vertices();
    std::vector<std::uint8_t> compressed;
    GltfBuilder b;
    std::uint64_t fallbackSize = 0;
    auto addView = [&](const std::vector<std::uint8_t>& bytes, std::size_t stride, std::size_t count, const char* mode,
                       const char* filter, bool attribute) {
        Json ext = {{"buffer", 0},
                    {"byteOffset", compressed.size()},
                    {"byteLength", bytes.size()},
                    {"byteStride", stride},
                    {"count", count},
                    {"mode", mode}};
        if (filter) ext["filter"] = filter;
        Json view = {{"buffer", 1},
                     {"byteOffset", fallbackSize},
                     {"byteLength", stride * count},
                     {"extensions", {{"EXT_meshopt_compression", ext}}}};
        if (attribute) view["byteStride"] = stride;
        b.j["bufferViews"].push_back(view);
        compressed.insert(compressed.end(), bytes.begin(), bytes.end());
        while (compressed.size() % 4) compressed.push_back(0);
        fallbackSize += (stride * count + 3) / 4 * 4;
        return static_cast<int>(b.j["bufferViews"].size()) - 1;
    };
    auto vertexCodec = [&](const void* data, std::size_t stride) {
        std::vector<std::uint8_t> out(meshopt_encodeVertexBufferBound(n, stride));
        out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, n, stride));
        return out;
    };
    const int pos = addView(vertexCodec(p.positions.data(), 12), 12, n, "ATTRIBUTES", nullptr, true);
    std::vector<std::int8_t> oct(n * 4);
    meshopt_encodeFilterOct(oct.data(), n, 4, 8, p.normals4.data());
    const int nrm = addView(vertexCodec(oct.data(), 4), 4, n, "ATTRIBUTES", "OCTAHEDRAL", true);
    std::vector<std::uint32_t> exp(n * 2);
    meshopt_encodeFilterExp(exp.data(), n, 8, 16, p.texCoords.data());
    const int uv = addView(vertexCodec(exp.data(), 8), 8, n, "ATTRIBUTES", "EXPONENTIAL", true);
    std::vector<std::uint8_t> idx(meshopt_encodeIndexBufferBound(p.indices.size(), n));
    idx.resize(meshopt_encodeIndexBuffer(idx.data(), idx.size(), p.indices.data(), p.indices.size()));
    const int ind = addView(idx, 2, p.indices.size(), "TRIANGLES", nullptr, false);
    const Json attributes = {{"POSITION", b.addAccessor(pos, 5126, n, "VEC3")},
                             {"NORMAL", b.addAccessor(nrm, 5120, n, "VEC3", 0, true)},
                             {"TEXCOORD_0", b.addAccessor(uv, 5126, n, "VEC2")}};
    const int mesh =
        b.addMesh({{"attributes", attributes}, {"indices", b.addAccessor(ind, 5123, p.indices.size(), "SCALAR")}});
    b.addNode({{"mesh", mesh}});
    b.j["extensionsUsed"] = {"EXT_meshopt_compression"};
    b.j["extensionsRequired"] = {"EXT_meshopt_compression"};
    b.j["buffers"] = {
        {{"byteLength", compressed.size()},
         {"uri", "data:application/octet-stream;base64," + testing::base64(compressed)}},
        {{"byteLength", fallbackSize}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
    b.bin = compressed;
    return b;
}

TEST(CompressedGltf, MeshoptDecodesExactlyWhereNoFilterIsUsed) {
    const Patch p;
    const Scene s = loadGltf(meshoptPatch(p).write("meshopt-patch.gltf"));
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.positions.size(), p.vertices());
    ASSERT_EQ(m.normals.size(), p.vertices());
    ASSERT_EQ(m.texCoords0.size(), p.vertices());
    EXPECT_EQ(rotated(m.indices), rotated(p.indices));
    for (std::size_t i = 0; i < p.vertices(); ++i) {
        SCOPED_TRACE(i);
        // The vertex codec is lossless: the same floats, bit for bit.
        EXPECT_EQ(m.positions[i], glm::vec3(p.positions[3 * i], p.positions[3 * i + 1], p.positions[3 * i + 2]));
        // 8-bit octahedral: a component step of 2/127 in the folded square, about 1° at worst;
        // 0.02 per component allows that with rounding on both axes.
        const glm::vec3 n(p.normals4[4 * i], p.normals4[4 * i + 1], p.normals4[4 * i + 2]);
        EXPECT_LT(glm::length(m.normals[i] - n), 0.02f);
        // 16-bit mantissa with a shared exponent: relative error below 2^-15 of the larger
        // component (at most 1), so 1e-4 absolute.
        EXPECT_NEAR(m.texCoords0[i].x, p.texCoords[2 * i], 1e-4);
        EXPECT_NEAR(m.texCoords0[i].y, p.texCoords[2 * i + 1], 1e-4);
    }
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST(CompressedGltf, MeshoptInGlbWithTheFallbackAfterTheBinChunk) {
    // The layout gltfpack writes: buffer 0 is the GLB's BIN chunk (no uri), buffer 1 the
    // fallback. tinygltf alone refuses it ("Invalid 'byteLength'").
    const Patch p;
    GltfBuilder b = meshoptPatch(p);
    b.j["buffers"][0].erase("uri");
    Json doc = Json::parse(b.text());
    std::string json = doc.dump();
    while (json.size() % 4) json += ' ';
    std::vector<std::uint8_t> bin = b.bin;
    while (bin.size() % 4) bin.push_back(0);
    std::string glb = "glTF";
    auto word = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
    word(2);
    word(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    word(static_cast<std::uint32_t>(json.size()));
    glb += "JSON" + json;
    word(static_cast<std::uint32_t>(bin.size()));
    glb.append("BIN\0", 4);
    glb.append(bin.begin(), bin.end());
    const auto file = testing::testOutput("gltf") / "meshopt-patch.glb";
    std::ofstream(file, std::ios::binary) << glb;
    const Scene s = loadGltf(file);
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(rotated(s.meshes[0].indices), rotated(p.indices));
}

struct ErrorCase {
    const char* name;
    std::function<void(GltfBuilder&)> breakIt;
    const char* message;
};

Json& meshoptOf(GltfBuilder& b, int view) { return b.j["bufferViews"][view]["extensions"]["EXT_meshopt_compression"]; }

TEST(CompressedGltf, BrokenMeshoptFilesNameTheViewAndTheRule) {
    const ErrorCase cases[] = {
        {"unknown mode", [](GltfBuilder& b) { meshoptOf(b, 0)["mode"] = "QUADS"; },
         "bufferViews[0].extensions.EXT_meshopt_compression.mode: unknown mode 'QUADS' (expected ATTRIBUTES, "
         "TRIANGLES or INDICES)"},
        {"unknown filter", [](GltfBuilder& b) { meshoptOf(b, 1)["filter"] = "POLAR"; },
         "bufferViews[1].extensions.EXT_meshopt_compression.filter: unknown filter 'POLAR'"},
        {"attribute stride", [](GltfBuilder& b) { meshoptOf(b, 0)["byteStride"] = 6; },
         "bufferViews[0].extensions.EXT_meshopt_compression.byteStride: expected a multiple of 4 from 4 to 256 for "
         "mode ATTRIBUTES, got 6"},
        {"triangle count", [](GltfBuilder& b) { meshoptOf(b, 3)["count"] = 383; },
         "bufferViews[3].extensions.EXT_meshopt_compression.count: expected a multiple of 3 for mode TRIANGLES, got "
         "383"},
        {"filter on indices", [](GltfBuilder& b) { meshoptOf(b, 3)["filter"] = "OCTAHEDRAL"; },
         "bufferViews[3].extensions.EXT_meshopt_compression.filter: index data takes no filter"},
        {"octahedral stride", [](GltfBuilder& b) { meshoptOf(b, 0)["filter"] = "OCTAHEDRAL"; },
         "bufferViews[0].extensions.EXT_meshopt_compression.byteStride: expected 4 or 8 for filter OCTAHEDRAL, got 12"},
        {"negative offset", [](GltfBuilder& b) { meshoptOf(b, 0)["byteOffset"] = -4; },
         "bufferViews[0].extensions.EXT_meshopt_compression.byteOffset: expected a non-negative integer, got -4"},
        {"missing count", [](GltfBuilder& b) { meshoptOf(b, 0).erase("count"); },
         "bufferViews[0].extensions.EXT_meshopt_compression.count: missing (expected a non-negative integer)"},
        {"view length", [](GltfBuilder& b) { b.j["bufferViews"][0]["byteLength"] = 960; },
         "bufferViews[0].byteLength: 960 does not match the compressed view (expected byteStride x count = 12 x 81 "
         "= 972)"},
        {"view stride", [](GltfBuilder& b) { b.j["bufferViews"][1]["byteStride"] = 8; },
         "bufferViews[1].byteStride: 8 differs from the extension's (expected 4)"},
        {"compressed range", [](GltfBuilder& b) { meshoptOf(b, 3)["byteOffset"] = 100000; },
         "bufferViews[3].extensions.EXT_meshopt_compression: byte range 100000 + "},
        {"source is the fallback", [](GltfBuilder& b) { meshoptOf(b, 2)["buffer"] = 1; },
         "bufferViews[2].extensions.EXT_meshopt_compression.buffer: buffer 1 is a fallback buffer (expected the "
         "buffer of compressed bytes)"},
        {"plain view of the fallback",
         [](GltfBuilder& b) {
             b.j["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 4}});
         },
         "bufferViews[4]: buffer 1 is a fallback buffer without data (expected EXT_meshopt_compression on every view "
         "of it)"},
        {"more than the codec can expand",
         [](GltfBuilder& b) {
             meshoptOf(b, 0)["count"] = 1000000;
             b.j["bufferViews"][0]["byteLength"] = 12000000;
         },
         "compressed bytes cannot hold 12000000 decoded bytes (expected at most 64 per compressed byte)"},
        {"truncated data",
         [](GltfBuilder& b) { meshoptOf(b, 0)["byteLength"] = meshoptOf(b, 0)["byteLength"].get<int>() - 40; },
         "bufferViews[0].extensions.EXT_meshopt_compression: the compressed bytes are malformed or do not hold "
         "byteStride x count"},
        {"version", [](GltfBuilder& b) { b.bin[0] = 0xb0; },
         "bufferViews[0].extensions.EXT_meshopt_compression: unsupported bitstream version (header byte 0xB0"},
        {"required extension", [](GltfBuilder& b) { b.j["extensionsRequired"].push_back("EXT_lights_area"); },
         "broken-meshopt.gltf: extensionsRequired[1]: extension 'EXT_lights_area' is not supported (supported: "},
        {"required KTX2 textures", [](GltfBuilder& b) { b.j["extensionsRequired"].push_back("KHR_texture_basisu"); },
         "broken-meshopt.gltf: extensionsRequired[1]: extension 'KHR_texture_basisu' is not supported; textures must "
         "have a PNG or JPEG image"},
        {"KTX2 texture without a fallback image",
         [](GltfBuilder& b) {
             b.j["textures"] = {{{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}}};
             b.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
         },
         "broken-meshopt.gltf: textures[0]: has no PNG or JPEG source, only an image of extension "
         "'KHR_texture_basisu', which is not supported (expected a 'source' image)"},
    };
    const Patch p;
    for (const ErrorCase& c : cases) {
        SCOPED_TRACE(c.name);
        GltfBuilder b = meshoptPatch(p);
        c.breakIt(b);
        b.j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + testing::base64(b.bin);
        const auto file = b.write("broken-meshopt.gltf");
        EXPECT_THAT([&] { loadGltf(file); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(CompressedGltf, BrokenDracoBitstreamNamesThePrimitive) {
    GltfBuilder b = testing::triangleFile();
    const std::vector<std::uint8_t> junk = {'D', 'R', 'A', 'C', 'O', 2, 2, 1, 1, 0, 0, 0, 9, 9, 9, 9};
    const int view = b.addView(junk.data(), junk.size());
    b.j["meshes"][0]["primitives"][0]["extensions"] = {
        {"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", {{"POSITION", 0}}}}}};
    b.j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    EXPECT_THAT([&] { loadGltf(b.write("broken-draco.gltf")); },
                ThrowsMessage<Error>(HasSubstr("broken-draco.gltf: meshes[0].primitives[0].extensions."
                                               "KHR_draco_mesh_compression: the Draco bitstream does not decode")));
}

// --- Files written by gltfpack and draco_transcoder (pack_compressed.cmake) ---

bool onCi() {
    const char* ci = std::getenv("CI");
    return ci && std::string(ci) == "true";
}

std::size_t drawnTriangles(const Scene& s) {
    std::size_t n = 0;
    for (const Object& o : s.objects) n += s.meshes[o.mesh].indices.size() / 3;
    return n;
}

using test::kVariants;
using test::Variant;

TEST(CompressedGltf, PackedCopiesOfSharedModelsKeepTheirTrianglesAndBounds) {
    std::vector<std::string> missing;  // files a missing tool did not write
    for (const Variant& v : kVariants) {
        SCOPED_TRACE(v.packed);
        const std::filesystem::path file = kPacked / v.packed;
        if (!std::filesystem::exists(file)) {
            if (onCi())
                ADD_FAILURE() << file
                              << " is missing (the pack_compressed fixture needs gltfpack and "
                                 "draco_transcoder; tools/install-deps.sh installs them)";
            missing.push_back(v.packed);
            continue;
        }
        const Scene original = loadSceneFile(kReal / v.model);
        const Scene packed = loadSceneFile(file);
        // gltfpack merges and reorders meshes; on these models it keeps every triangle (on
        // others it may drop ones that quantization makes degenerate).
        EXPECT_EQ(drawnTriangles(packed), drawnTriangles(original));
        // Positions are quantized to 14 bits (gltfpack) or 11 bits (draco_transcoder) of each
        // mesh's extent: 2^-11 of the largest extent is within 0.001 of the model's diagonal.
        const Bounds a = original.bounds(), b = packed.bounds();
        const double tolerance = 1e-3 * glm::length(a.max - a.min);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(b.min[k], a.min[k], tolerance) << "axis " << k;
            EXPECT_NEAR(b.max[k], a.max[k], tolerance) << "axis " << k;
        }
        for (const std::string& w : packed.warnings) ADD_FAILURE() << "unexpected warning: " << w;
    }
    if (!missing.empty())
        GTEST_SKIP() << missing.size()
                     << " of the packed files are missing (gltfpack or draco_transcoder is not "
                        "installed), first "
                     << missing.front();
}

}  // namespace
}  // namespace cavewall::scenes
