#pragma once
// A glTF file with large textures, for the texture-budget tests: one 1 m square quad per image,
// side by side along +X in z = 0 (facing +Z), each textured with its own PNG written beside the
// file. Each image shows four flat quadrants (visible at any size) under a one-pixel checker of
// +-kChecker levels (detail no screen resolves, averaged away by reduction and by MIP levels).

#include "scenes/image_io.h"
#include "tests/scenes/gltf_builder.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace cavewall::scenes::testing {

inline constexpr int kChecker = 24;

inline Image quadrantImage(int width, int height) {
    static const std::uint8_t kQuadrants[4][3] = {{200, 60, 60}, {60, 180, 70}, {70, 90, 200}, {190, 180, 60}};
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* q = kQuadrants[(x * 2 >= width ? 1 : 0) + (y * 2 >= height ? 2 : 0)];
            const int d = (x + y) % 2 ? kChecker : -kChecker;
            std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * width + x) * 4];
            for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(q[c] + d);
            p[3] = 255;
        }
    return img;
}

// Writes `<name>.gltf` and `<name>-<i>.png` under testOutput("gltf"); names must be unique per
// test (ctest runs each test case in its own process, in parallel).
inline std::filesystem::path writeTexturedQuads(const std::string& name, const std::vector<glm::ivec2>& sizes) {
    GltfBuilder b;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        const float x0 = static_cast<float>(i), x1 = x0 + 1.0f;
        const int pos = b.addFloats({x0, 0, 0, x1, 0, 0, x1, 1, 0, x0, 1, 0}, "VEC3", 3);
        // glTF's (0, 0) is the image's top-left corner: the quad's top edge.
        const int uv = b.addFloats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
        const int idx = b.addIndices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
        const std::string png = name + "-" + std::to_string(i) + ".png";
        writeImage(testOutput("gltf") / png, quadrantImage(sizes[i].x, sizes[i].y));
        b.j["images"].push_back({{"uri", png}});
        b.j["textures"].push_back({{"source", i}});
        b.j["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
        const int mesh =
            b.addMesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"indices", idx}, {"material", i}});
        b.addNode({{"mesh", mesh}});
    }
    return b.write(name + ".gltf");
}

}  // namespace cavewall::scenes::testing
