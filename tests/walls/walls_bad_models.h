#pragma once
// Small glTF models that once made `cavewall walls` hang or fail on its own proposal: a very
// long hall, boxes scattered over a large volume, and degenerate models (one point, a vertical
// plane only, far from the origin, nothing at all).

#include "tests/scenes/gltf_builder.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::test {

struct Box {
    float x0, y0, z0, x1, y1, z1;
};

// One mesh per box (a unit cube scaled and moved by its node), named "<prefix><i>".
inline scenes::testing::GltfBuilder boxesFile(const std::vector<Box>& boxes, const std::string& prefix = "box") {
    scenes::testing::GltfBuilder b;
    const std::vector<float> cube = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    const std::vector<std::uint16_t> faces = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                              3, 6, 2, 3, 7, 6, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
    const int pos = b.addFloats(cube, "VEC3", 3);
    const int idx = b.addIndices(faces);
    const int mesh = b.addMesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}});
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& x = boxes[i];
        b.addNode({{"name", prefix + std::to_string(i)},
                   {"mesh", mesh},
                   {"translation", {x.x0, x.y0, x.z0}},
                   {"scale", {x.x1 - x.x0, x.y1 - x.y0, x.z1 - x.z0}}});
    }
    return b;
}

// A hall `length` metres long (x) and 20 m wide (z), 5 m high: floor, ceiling and side walls
// as thin boxes, and a 1 m box of content every 50 m.
inline scenes::testing::GltfBuilder longHall(float length) {
    std::vector<Box> boxes = {{0, -0.1f, 0, length, 0, 20},
                              {0, 5, 0, length, 5.1f, 20},
                              {0, 0, -0.1f, length, 5, 0},
                              {0, 0, 20, length, 5, 20.1f}};
    for (float x = 25; x < length; x += 50) boxes.push_back({x, 0, 9.5f, x + 1, 1, 10.5f});
    return boxesFile(boxes);
}

// `count` 1 m boxes at pseudo-random places over 2 km x 200 m x 2 km (a fixed sequence).
inline scenes::testing::GltfBuilder scatteredBoxes(int count) {
    std::uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
    };
    std::vector<Box> boxes;
    for (int i = 0; i < count; ++i) {
        const float x = 2000 * next(), y = 200 * next(), z = 2000 * next();
        boxes.push_back({x, y, z, x + 1, y + 1, z + 1});
    }
    return boxesFile(boxes);
}

// One triangle whose three vertices are `p` (give or take `spread` metres).
inline scenes::testing::GltfBuilder pointFile(float x, float y, float z, float spread = 0) {
    scenes::testing::GltfBuilder b;
    const int pos = b.addFloats({x, y, z, x + spread, y, z, x, y + spread, z}, "VEC3", 3);
    const int mesh = b.addMesh({{"attributes", {{"POSITION", pos}}}});
    b.addNode({{"name", "speck"}, {"mesh", mesh}});
    return b;
}

// A 10 m x 3 m vertical quad in the plane z = 0: nothing to stand on.
inline scenes::testing::GltfBuilder verticalPlaneFile() {
    scenes::testing::GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 10, 0, 0, 10, 3, 0, 0, 3, 0}, "VEC3", 3);
    const int idx = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    const int mesh = b.addMesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}});
    b.addNode({{"name", "wall"}, {"mesh", mesh}});
    return b;
}

// A 10 m x 3 m x 10 m room with a table, offset by (`offset`, 0, `offset`).
inline scenes::testing::GltfBuilder roomAt(float offset) {
    const float o = offset;
    return boxesFile({{o, -0.1f, o, o + 10, 0, o + 10}, {o + 4, 0, o + 4, o + 6, 1, o + 6}});
}

// A file with a node and no mesh: a scene without geometry.
inline scenes::testing::GltfBuilder emptyFile() {
    scenes::testing::GltfBuilder b;
    b.addNode({{"name", "nothing"}});
    b.j["buffers"] = nlohmann::json::array();
    return b;
}

}  // namespace cavewall::test
