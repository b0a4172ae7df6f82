#pragma once
// The compressed copies of shared models that the packed_gltf fixture writes
// (tests/scenes/pack_compressed.cmake), each with the original it was made from; read by the
// compressed-glTF unit and GL tests.

namespace cavewall::test {

struct Variant {
    const char* model;   // under scenes-real
    const char* packed;  // under the fixture's folder
};

const Variant kVariants[] = {
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-q.glb"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-c.glb"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-cc.glb"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-noq.glb"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-c-noq.glb"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-cc-noq.glb"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-text/NegativeScaleTest-cc.gltf"},
    {"NegativeScaleTest/NegativeScaleTest.gltf", "NegativeScaleTest-draco.glb"},
    {"TextureTransformTest/TextureTransformTest.gltf", "TextureTransformTest-q.glb"},
    {"TextureTransformTest/TextureTransformTest.gltf", "TextureTransformTest-cc.glb"},
    {"TextureTransformTest/TextureTransformTest.gltf", "TextureTransformTest-cc-noq.glb"},
    {"TextureTransformTest/TextureTransformTest.gltf", "TextureTransformTest-text/TextureTransformTest-cc.gltf"},
    {"TextureTransformTest/TextureTransformTest.gltf", "TextureTransformTest-draco.glb"},
};

}  // namespace cavewall::test
