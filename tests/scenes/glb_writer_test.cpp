// The .glb writer: what it writes loads back unchanged, and the container is well formed.
#include "scenes/glb_writer.h"
#include "scenes/loader.h"
#include "scenes/primitives.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>

namespace cavewall::scenes {
namespace {

Scene sampleScene() {
    Scene s;
    s.name = "sample";
    Material m;
    m.name = "glass";
    m.baseColorFactor = {0.2f, 0.4f, 0.6f, 0.5f};
    m.alphaMode = AlphaMode::Blend;
    m.doubleSided = true;
    s.materials.push_back(m);
    s.meshes.push_back(makeBox({1, 2, 3}, {1, 0.5f, 0.25f, 1}));
    s.meshes[0].material = 0;
    s.meshes.push_back(makeCylinder(0.5f, 1.0f, 12, {0, 1, 0, 1}));
    addObject(s, 0, glm::dmat4(1.0), "box-a");
    addObject(s, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(1e5, 0, -3)), "box-far");
    addObject(s, 1, glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1)), "mirrored");
    return s;
}

TEST(GlbWriter, WhatIsWrittenLoadsBackUnchanged) {
    const Scene s = sampleScene();
    const auto file = testing::testOutput("glb") / "sample.glb";
    writeGlb(s, file);
    const Scene back = loadGltf(file);
    EXPECT_TRUE(back.warnings.empty());
    ASSERT_EQ(back.meshes.size(), 2u);  // the box is instanced twice but stored once
    ASSERT_EQ(back.objects.size(), 3u);
    for (std::size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(back.meshes[i].positions, s.meshes[i].positions);  // float data is copied bit for bit
        EXPECT_EQ(back.meshes[i].normals, s.meshes[i].normals);
        EXPECT_EQ(back.meshes[i].colors, s.meshes[i].colors);
        EXPECT_EQ(back.meshes[i].indices, s.meshes[i].indices);
        EXPECT_EQ(back.meshes[i].material, s.meshes[i].material);
    }
    for (std::size_t o = 0; o < 3; ++o) {
        EXPECT_EQ(back.objects[o].name, s.objects[o].name);
        EXPECT_EQ(back.objects[o].worldFromModel, s.objects[o].worldFromModel);  // doubles in JSON, exact
        EXPECT_EQ(back.objects[o].flipWinding, s.objects[o].flipWinding);
    }
    EXPECT_TRUE(back.objects[2].flipWinding);
    const Material& m = back.materials.at(0);
    EXPECT_EQ(m.name, "glass");
    EXPECT_EQ(m.baseColorFactor, s.materials[0].baseColorFactor);
    EXPECT_EQ(m.alphaMode, AlphaMode::Blend);
    EXPECT_TRUE(m.doubleSided);
}

TEST(GlbWriter, ContainerHeaderAndChunksAreWellFormed) {
    const std::vector<std::uint8_t> b = glbBytes(sampleScene());
    ASSERT_GE(b.size(), 28u);
    auto u32 = [&](std::size_t at) {
        std::uint32_t v;
        std::memcpy(&v, b.data() + at, 4);
        return v;
    };
    EXPECT_EQ(std::string(b.begin(), b.begin() + 4), "glTF");
    EXPECT_EQ(u32(4), 2u);        // container version 2
    EXPECT_EQ(u32(8), b.size());  // total length
    const std::uint32_t jsonLength = u32(12);
    EXPECT_EQ(u32(16), 0x4E4F534Au);                   // "JSON"
    EXPECT_EQ(jsonLength % 4, 0u);                     // chunks are 4-byte aligned
    EXPECT_EQ(u32(20 + jsonLength + 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(20 + jsonLength + 8 + u32(20 + jsonLength), b.size());
    const auto json = nlohmann::json::parse(b.begin() + 20, b.begin() + 20 + jsonLength);
    EXPECT_EQ(json["asset"]["version"], "2.0");
    // glTF requires min and max on every POSITION accessor.
    for (const auto& mesh : json["meshes"]) {
        const auto& acc = json["accessors"][mesh["primitives"][0]["attributes"]["POSITION"].get<int>()];
        EXPECT_TRUE(acc.contains("min") && acc.contains("max"));
    }
}

}  // namespace
}  // namespace cavewall::scenes
