// Batch keys and the grouping of draws into batches (render/render_scene.h, render_list.h).
#include "render/render_list.h"
#include "tests/render/render_test_scenes.h"

#include <gtest/gtest.h>

namespace cavewall::render {
namespace {

using testing::addCube;
using testing::addImage;
using testing::Look;

TEST(Batches, FaceModeFollowsDoubleSidedAndWinding) {
    EXPECT_EQ(faceMode(false, false), FaceMode::CullCcw);
    EXPECT_EQ(faceMode(false, true), FaceMode::CullCw);
    EXPECT_EQ(faceMode(true, false), FaceMode::BothCcw);
    EXPECT_EQ(faceMode(true, true), FaceMode::BothCw);
}

TEST(Batches, KeysNameTheTextureItsSamplerTheFaceModeAndAlphaTesting) {
    scenes::Material m;
    m.baseColorTexture.image = 1;
    m.baseColorTexture.wrapS = scenes::Wrap::ClampToEdge;     // 1
    m.baseColorTexture.wrapT = scenes::Wrap::MirroredRepeat;  // 2
    const BatchKey k = batchKey(m, false, true, 2);
    EXPECT_EQ(k.texture, 1);
    EXPECT_EQ(k.sampler, 1 * 3 + 2);
    EXPECT_EQ(k.faces, FaceMode::CullCcw);
    // A texture index beyond the scene's images is no texture (and no sampler).
    EXPECT_EQ(batchKey(m, false, true, 1), BatchKey{});
    // Without back-face culling everything is double-sided, keeping its winding.
    EXPECT_EQ(batchKey(m, true, false, 2).faces, FaceMode::BothCw);
    // Only alpha-MASK materials are alpha-tested (blended ones blend, they do not discard).
    EXPECT_FALSE(k.alphaTest);
    m.alphaMode = scenes::AlphaMode::Mask;
    EXPECT_TRUE(batchKey(m, false, true, 2).alphaTest);
    m.alphaMode = scenes::AlphaMode::Blend;
    EXPECT_FALSE(batchKey(m, false, true, 2).alphaTest);
}

// Five cubes: untextured CCW (0, 3), textured CCW (1, 4), untextured mirrored CW (2).
scenes::Scene fiveCubes() {
    scenes::Scene scene;
    const int image = addImage(scene);
    for (int i = 0; i < 5; ++i) {
        Look look;
        if (i == 1 || i == 4) look.image = image;
        look.mirrored = i == 2;
        addCube(scene, {i, 0, -3}, 0.5, look);
    }
    return scene;
}

std::vector<Draw> draws(std::initializer_list<int> objects) {
    std::vector<Draw> out;
    for (int o : objects) out.push_back({o, 0});
    return out;
}

TEST(Batches, ByKeyMakesOneBatchPerKeyInKeyOrderKeepingTheGivenOrderWithin) {
    const scenes::Scene scene = fiveCubes();
    const RenderScene rs(scene, false);
    ASSERT_TRUE(scene.objects[2].flipWinding);
    std::vector<Draw> list = draws({0, 1, 2, 3, 4});
    std::vector<Batch> batches;
    appendBatches(rs, list, true, 0, batches);
    // Keys ascend by texture first: untextured (-1) CCW [0, 3], untextured CW [2], texture 0 [1, 4].
    ASSERT_EQ(batches.size(), 3u);
    const std::vector<int> order{0, 3, 2, 1, 4};
    for (std::size_t d = 0; d < order.size(); ++d) EXPECT_EQ(list[d].object, order[d]) << "draw " << d;
    EXPECT_EQ(batches[0].first, 0);
    EXPECT_EQ(batches[0].count, 2);
    EXPECT_EQ(batches[1].first, 2);
    EXPECT_EQ(batches[1].count, 1);
    EXPECT_EQ(batches[2].first, 3);
    EXPECT_EQ(batches[2].count, 2);
    for (const Batch& b : batches)  // every draw of a batch has the batch's key
        for (int d = b.first; d < b.first + b.count; ++d) EXPECT_EQ(rs.batchKey(list[d].object), b.key);
    EXPECT_LT(batches[0].key, batches[1].key);
    EXPECT_LT(batches[1].key, batches[2].key);
}

TEST(Batches, InGivenOrderOnlyNeighboursMergeAndBatchesFollowEarlierOnes) {
    const scenes::Scene scene = fiveCubes();
    const RenderScene rs(scene, false);
    std::vector<Draw> list = draws({1, 4, 0, 3, 2, 0});
    std::vector<Batch> batches(1);  // a batch already there stays; the new ones index after `offset`
    appendBatches(rs, list, false, 7, batches);
    // The one before + [1, 4], [0, 3], [2], then [0] again: equal keys apart stay apart.
    ASSERT_EQ(batches.size(), 5u);
    ASSERT_EQ(list.size(), 6u);
    EXPECT_EQ(list[4].object, 2);  // the order is untouched
    EXPECT_EQ(batches[1].first, 7);
    EXPECT_EQ(batches[1].count, 2);
    EXPECT_EQ(batches[2].first, 9);
    EXPECT_EQ(batches[2].count, 2);
    EXPECT_EQ(batches[3].first, 11);
    EXPECT_EQ(batches[3].count, 1);
    EXPECT_EQ(batches[4].first, 12);
    EXPECT_EQ(batches[4].key, batches[2].key);
}

}  // namespace
}  // namespace cavewall::render
