// The glTF loader on tiny files written by the tests: one feature per case (errors:
// gltf_errors_test.cpp).
#include "scenes/gltf_materials.h"
#include "scenes/loader.h"
#include "scenes/mesh_tools.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

namespace cavewall::scenes {
namespace {

using testing::GltfBuilder;
using testing::testOutput;
using testing::triangleFile;

TEST(NodePattern, StarsMatchAnyRunAndEverythingElseItself) {
    EXPECT_TRUE(matchesNodePattern("Hall wall 3", "Hall*"));
    EXPECT_TRUE(matchesNodePattern("Hall wall 3", "*wall*"));
    EXPECT_TRUE(matchesNodePattern("wall", "*wall"));
    EXPECT_TRUE(matchesNodePattern("", "*"));
    EXPECT_TRUE(matchesNodePattern("abcbc", "a*bc"));
    EXPECT_FALSE(matchesNodePattern("Hall wall 3", "wall*"));
    EXPECT_FALSE(matchesNodePattern("abcbd", "a*bc"));
    EXPECT_FALSE(matchesNodePattern("", "a"));
    EXPECT_FALSE(matchesNodePattern("a", ""));
}

TEST(NodePattern, ManyStarsOnALongNameDoNotBlowUp) {
    // A backtracking matcher tries every split of 200 characters among 20 stars (about 10^26
    // ways) before it says no; this one is linear per star.
    const std::string name(200, 'a');
    std::string pattern;
    for (int i = 0; i < 20; ++i) pattern += "*a";
    EXPECT_FALSE(matchesNodePattern(name, pattern + "*b"));
    EXPECT_TRUE(matchesNodePattern(name, pattern + "*"));
}

TEST(GltfLoader, EmbeddedTriangleGetsGeneratedNormalAndBounds) {
    const Scene s = loadGltf(triangleFile().write("triangle.gltf"));
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.name, "triangle");
    EXPECT_TRUE(s.warnings.empty());
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));  // no indices: vertices in order
    // Counter-clockwise seen from +Z: the generated normal is +Z at every vertex.
    for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
    EXPECT_EQ(m.bounds.max, glm::dvec3(1, 1, 0));
    EXPECT_FALSE(s.objects[0].flipWinding);
}

TEST(GltfLoader, IndexWidths8And16And32BitGiveTheSameTriangles) {
    for (int width : {1, 2, 4}) {
        SCOPED_TRACE(width);
        GltfBuilder b;
        const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
        const std::vector<std::uint32_t> quad = {0, 1, 2, 0, 2, 3};
        int idx = width == 1   ? b.addIndices(std::vector<std::uint8_t>(quad.begin(), quad.end()))
                  : width == 2 ? b.addIndices(std::vector<std::uint16_t>(quad.begin(), quad.end()))
                               : b.addIndices(quad);
        b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}})}});
        const Scene s = loadGltf(b.write("widths.gltf"));
        EXPECT_EQ(s.meshes[0].indices, quad);
    }
}

TEST(GltfLoader, StripsAndFansBecomeListsWithTheSameWinding) {
    // Four vertices of a unit square, counter-clockwise from +Z in both layouts.
    const std::vector<float> strip = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const std::vector<float> fan = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    for (int mode : {5, 6}) {
        SCOPED_TRACE(mode);
        GltfBuilder b;
        const int pos = b.addFloats(mode == 5 ? strip : fan, "VEC3", 3);
        b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}}}, {"mode", mode}})}});
        const Scene s = loadGltf(b.write("strip_fan.gltf"));
        const Mesh& m = s.meshes[0];
        // glTF: strip triangles (0,1,2), (1,3,2); fan triangles (0,1,2), (0,2,3).
        EXPECT_EQ(m.indices, mode == 5 ? (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2})
                                       : (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
        for (std::size_t t = 0; t < 2; ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], bb = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            EXPECT_GT(glm::cross(bb - a, c - a).z, 0.0f);  // every triangle faces +Z
        }
    }
}

TEST(GltfLoader, PointsAndLinesAreSkippedWithAWarning) {
    GltfBuilder b = triangleFile();
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0}, "VEC3", 3);
    b.j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", pos}}}, {"mode", 1}});
    const Scene s = loadGltf(b.write("lines.gltf"));
    EXPECT_EQ(s.meshes.size(), 1u);  // only the triangle
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0],
              "scene 'lines.gltf': ignoring primitive 1 of mesh 0 because it has mode LINES "
              "(only triangles, strips and fans are drawn)");
}

TEST(GltfLoader, LeftoverIndicesAreDroppedWithAWarning) {
    GltfBuilder b = triangleFile();
    b.j["meshes"][0]["primitives"][0]["indices"] = b.addIndices(std::vector<std::uint8_t>{0, 1, 2, 2, 1});
    const Scene s = loadGltf(b.write("leftover.gltf"));
    EXPECT_EQ(s.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0],
              "scene 'leftover.gltf': primitive 0 of mesh 0 has 5 indices, not a multiple of 3; "
              "dropping the last 2");
}

TEST(GltfLoader, InterleavedNormalizedAttributesAreDecoded) {
    // One vertex = position (3 floats) + unsigned-byte normalized RGBA colour + signed-short
    // normalized normal (padded to 4 shorts): stride 12 + 4 + 8 = 24 bytes.
    struct Vertex {
        float p[3];
        std::uint8_t c[4];
        std::int16_t n[4];
    };
    const Vertex v[3] = {{{0, 0, 0}, {255, 0, 51, 255}, {0, 0, 32767, 0}},
                         {{1, 0, 0}, {0, 255, 0, 255}, {0, 0, 32767, 0}},
                         {{0, 1, 0}, {0, 0, 255, 0}, {0, 0, -32768, 0}}};
    GltfBuilder b;
    const int view = b.addView(v, sizeof v, sizeof(Vertex));
    const int pos = b.addAccessor(view, 5126, 3, "VEC3");
    const int col = b.addAccessor(view, 5121, 3, "VEC4", 12, true);
    const int nrm = b.addAccessor(view, 5122, 3, "VEC3", 16, true);
    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}, {"COLOR_0", col}, {"NORMAL", nrm}}}})}});
    const Mesh m = loadGltf(b.write("interleaved.gltf")).meshes[0];
    EXPECT_EQ(m.positions[2], glm::vec3(0, 1, 0));
    EXPECT_NEAR(m.colors[0].b, 0.2f, 1e-6f);  // 51 / 255
    EXPECT_EQ(m.colors[2].a, 0.0f);
    EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));   // 32767 / 32767
    EXPECT_EQ(m.normals[2], glm::vec3(0, 0, -1));  // -32768 / 32767 clamps to -1
}

TEST(GltfLoader, SparseAccessorWithoutBufferViewStartsFromZeros) {
    GltfBuilder b;
    const std::vector<std::uint16_t> which = {2};
    const std::vector<float> values = {0, 5, 0};
    const int iv = b.addView(which.data(), 2), vv = b.addView(values.data(), 12);
    const int pos = b.addAccessor(-1, 5126, 3, "VEC3");
    b.j["accessors"][pos]["sparse"] = {
        {"count", 1}, {"indices", {{"bufferView", iv}, {"componentType", 5123}}}, {"values", {{"bufferView", vv}}}};
    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}}}})}});
    const Mesh m = loadGltf(b.write("sparse.gltf")).meshes[0];
    EXPECT_EQ(m.positions[0], glm::vec3(0));
    EXPECT_EQ(m.positions[2], glm::vec3(0, 5, 0));
    // All three corners are collinear (two at the origin): the only triangle is degenerate and
    // the normals fall back to +Y instead of NaN.
    EXPECT_EQ(countDegenerateTriangles(m), 1u);
    for (const glm::vec3& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(GltfLoader, DegenerateTrianglesDoNotPoisonNormals) {
    GltfBuilder b;
    // Triangle 0 is a proper +Z triangle; triangle 1 repeats vertex 0 and triangle 2 is collinear.
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0}, "VEC3", 3);
    const int idx = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 0, 1, 0, 1, 3});
    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}})}});
    const Mesh m = loadGltf(b.write("degenerate.gltf")).meshes[0];
    EXPECT_EQ(countDegenerateTriangles(m), 2u);
    for (int v = 0; v < 3; ++v) EXPECT_EQ(m.normals[v], glm::vec3(0, 0, 1));
    EXPECT_EQ(m.normals[3], glm::vec3(0, 1, 0));  // only used by the collinear triangle
}

TEST(GltfLoader, AreaWeightedNormalsFavourTheLargerFace) {
    GltfBuilder b;
    // Vertex 0 is shared by a 1x1 triangle facing +Z and a 3x3 triangle facing +X.
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -3, 0, 3, 0}, "VEC3", 3);
    const int idx = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 3, 4});
    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}})}});
    const Mesh m = loadGltf(b.write("weighted.gltf")).meshes[0];
    // Sum of area vectors (0,0,1) + (9,0,0), normalised: x = 9/sqrt(82), z = 1/sqrt(82).
    EXPECT_NEAR(m.normals[0].x, 9.0 / std::sqrt(82.0), 1e-6);
    EXPECT_NEAR(m.normals[0].z, 1.0 / std::sqrt(82.0), 1e-6);
}

TEST(GltfLoader, SharedMeshMatrixAndTrsAndNegativeDeterminant) {
    GltfBuilder b = triangleFile();
    // Node 0 (triangleFile) plus: a TRS node, a matrix node, and a mirrored parent of a mirrored child.
    b.addNode({{"mesh", 0},
               {"translation", {1, 2, 3}},
               {"rotation", {0, 0.7071067811865476, 0, 0.7071067811865476}},
               {"scale", {2, 2, 2}}});
    b.addNode({{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 5, 0, 0, 1}}});
    const int child = b.addNode({{"mesh", 0}, {"scale", {-1, 1, 1}}});
    b.addNode({{"children", {child}}, {"scale", {1, -1, 1}}});
    const Scene s = loadGltf(b.write("instances.gltf"));
    ASSERT_EQ(s.meshes.size(), 1u);  // one glTF mesh, four instances: never copied
    ASSERT_EQ(s.objects.size(), 4u);
    for (const Object& o : s.objects) EXPECT_EQ(o.mesh, 0);
    // TRS = T * R * S: vertex (1,0,0) scaled to (2,0,0), turned 90° about +Y to (0,0,-2), moved by (1,2,3).
    const glm::dvec4 p = s.objects[1].worldFromModel * glm::dvec4(1, 0, 0, 1);
    EXPECT_NEAR(p.x, 1.0, 1e-9);
    EXPECT_NEAR(p.y, 2.0, 1e-9);
    EXPECT_NEAR(p.z, 1.0, 1e-9);
    // The matrix is column-major: translation (5, 0, 0) in elements 12..14, z mirrored.
    EXPECT_EQ(s.objects[2].worldFromModel[3], glm::dvec4(5, 0, 0, 1));
    EXPECT_TRUE(s.objects[2].flipWinding);
    // Mirror in x under a mirror in y: world det = +1, no flip although the child's own det < 0.
    // The child node is visited after its parent in scene order; it is the 4th object.
    EXPECT_FALSE(s.objects[3].flipWinding);
    EXPECT_FALSE(s.objects[1].flipWinding);
}

TEST(GltfLoader, MaterialsTexturesAndTextureTransform) {
    GltfBuilder b = triangleFile();
    const int uv = b.addFloats({0, 0, 1, 0, 0, 1}, "VEC2", 2);
    b.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = uv;
    b.j["meshes"][0]["primitives"][0]["material"] = 1;
    // A 1x1 red PNG with alpha 128, embedded (written by hand: IHDR RGBA 8-bit, one IDAT).
    const std::vector<std::uint8_t> png = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
        0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1f, 0x15, 0xc4, 0x89, 0x00, 0x00, 0x00,
        0x0d, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xd0, 0x00, 0x00, 0x04, 0x81, 0x01, 0x80,
        0x2c, 0x56, 0x44, 0x7e, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    b.j["images"] = {{{"uri", "data:image/png;base64," + testing::base64(png)}}};
    b.j["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}}};
    b.j["textures"] = {{{"source", 0}, {"sampler", 0}}};
    b.j["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_variants"};
    b.j["extensionsRequired"] = {"KHR_texture_transform", "KHR_materials_variants"};
    b.j["materials"] = {
        {{"alphaMode", "MASK"}, {"alphaCutoff", 0.25}},
        {{"name", "tex"},
         {"doubleSided", true},
         {"alphaMode", "BLEND"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.5, 0.25, 1, 0.75}},
           {"baseColorTexture",
            {{"index", 0},
             {"texCoord", 0},
             {"extensions",
              {{"KHR_texture_transform",
                {{"offset", {0.5, 0}}, {"rotation", 1.5707963267948966}, {"scale", {2, 3}}, {"texCoord", 1}}}}}}}}}}};
    const Scene s = loadGltf(b.write("material.gltf"));
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_EQ(s.materials[0].alphaMode, AlphaMode::Mask);
    EXPECT_EQ(s.materials[0].alphaCutoff, 0.25f);
    const Material& m = s.materials[1];
    EXPECT_EQ(s.meshes[0].material, 1);
    EXPECT_EQ(m.alphaMode, AlphaMode::Blend);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_EQ(m.baseColorTexture.image, 0);
    EXPECT_EQ(m.baseColorTexture.texCoord, 1);  // the extension's texCoord overrides the info's
    EXPECT_EQ(m.baseColorTexture.wrapS, Wrap::ClampToEdge);
    EXPECT_EQ(m.baseColorTexture.wrapT, Wrap::MirroredRepeat);
    // Spec order T * R * S: (1, 0) scales to (2, 0), rotates by 90° (R's first row is
    // (cos, sin)) to (0, -2), then moves by (0.5, 0) to (0.5, -2).
    const glm::vec3 uv10 = m.baseColorTexture.transform * glm::vec3(1, 0, 1);
    EXPECT_NEAR(uv10.x, 0.5f, 1e-6f);
    EXPECT_NEAR(uv10.y, -2.0f, 1e-6f);
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].width, 1);
    EXPECT_EQ(s.images[0].rgba, (std::vector<std::uint8_t>{255, 0, 0, 128}));
}

TEST(GltfLoader, TextureTransformMatchesTheSpecExample) {
    // KHR_texture_transform README: offset [0, 1], rotation pi/2, scale [0.5, 0.5] "utilizes only
    // the lower left quadrant of the source image" (v grows downwards): the unit square must map
    // onto u in [0, 0.5], v in [0.5, 1].
    const glm::mat3 m = textureTransform({0, 1}, 1.5707963267948966f, {0.5f, 0.5f});
    for (glm::vec2 uv : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(0.3f, 0.7f)}) {
        const glm::vec3 t = m * glm::vec3(uv, 1);
        EXPECT_GE(t.x, -1e-6f);
        EXPECT_LE(t.x, 0.5f + 1e-6f);
        EXPECT_GE(t.y, 0.5f - 1e-6f);
        EXPECT_LE(t.y, 1.0f + 1e-6f);
    }
    // Corner (1, 0) goes to (0, 0.5): scaled to (0.5, 0), turned to (0, -0.5), moved down by 1.
    const glm::vec3 corner = m * glm::vec3(1, 0, 1);
    EXPECT_NEAR(corner.x, 0.0f, 1e-6f);
    EXPECT_NEAR(corner.y, 0.5f, 1e-6f);
}

TEST(GltfLoader, UrisWithSpacesAndPercentEncodingResolve) {
    GltfBuilder b = triangleFile();
    const auto dir = testOutput("gltf");
    std::ofstream(dir / "my data.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(b.bin.data()), static_cast<std::streamsize>(b.bin.size()));
    for (const char* uri : {"my data.bin", "my%20data.bin"}) {
        SCOPED_TRACE(uri);
        const Scene s = loadGltf(b.write("spaces.gltf", false, uri));
        EXPECT_EQ(s.triangleCount(), 1u);
    }
}

}  // namespace
}  // namespace cavewall::scenes
