// Occlusion culling (RenderSettings::occlusion, render/gl/occlusion_culler.h): the same
// images as drawing everything, frame after frame while the eye moves and hidden objects come
// into view, with fewer triangles drawn where a wall hides most of the scene.
//
// The scene: one 2 m screen 1 m in front of the eye (90°, 128 x 128 pixels); a wall 3 m away
// covering the left three quarters of the view; behind it, 5 to 12 m away, a grid of boxes
// across the whole view (some seen beside the wall); a box and a blended pane in front of it.
#include "display/display.h"
#include "display/gl/frame_images.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace cavewall::render::gl {
namespace {

int addMesh(scenes::Scene& scene, scenes::Mesh mesh, glm::dvec3 at, int material = -1) {
    mesh.material = material;
    scene.meshes.push_back(std::move(mesh));
    return scenes::addObject(scene, static_cast<int>(scene.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), at),
                             "object");
}

// `wall` false: the boxes alone, nothing hidden.
scenes::Scene wallAndBoxes(bool wall = true) {
    scenes::Scene scene;
    // The wall: 3 m in front, from the view's left edge to x = 1.3 m (its edge crosses boxes behind).
    if (wall)
        addMesh(scene,
                scenes::makeTiledQuad({-4.0f, -4.0f, 0.0f}, {5.3f, 0, 0}, {0, 8.0f, 0}, 1, 1,
                                      glm::vec4(0.8f, 0.7f, 0.6f, 1), glm::vec4(0.8f, 0.7f, 0.6f, 1)),
                {0, 0, -3});
    for (int z = 0; z < 4; ++z)
        for (int y = -3; y <= 3; ++y)
            for (int x = -6; x <= 6; ++x) {
                const glm::vec4 colour(0.2f + 0.05f * static_cast<float>(x + 6), 0.3f + 0.1f * static_cast<float>(z),
                                       0.5f, 1.0f);
                addMesh(scene, scenes::makeBox({0.5f, 0.5f, 0.5f}, colour), {x * 1.0, y * 1.0, -5.0 - 2.0 * z});
            }
    addMesh(scene, scenes::makeBox({0.4f, 0.4f, 0.4f}, {0.9f, 0.2f, 0.2f, 1}), {-0.5, -0.3, -2});
    scenes::Material glass;
    glass.baseColorFactor = {0.2f, 0.6f, 0.9f, 0.5f};
    glass.alphaMode = scenes::AlphaMode::Blend;
    scene.materials.push_back(glass);
    addMesh(scene,
            scenes::makeTiledQuad({-0.5f, -0.5f, 0.0f}, {1, 0, 0}, {0, 1, 0}, 1, 1, glm::vec4(1.0f), glm::vec4(1.0f)),
            {0.3, 0.2, -1.5}, 0);
    return scene;
}

class OcclusionTest : public testing::GlTest {
protected:
    // Renders the eye positions in turn with and without culling; every image must be the same.
    void expectSameImages(const std::vector<glm::dvec3>& eyes, std::size_t minTriangles = 0, std::size_t minDraws = 0) {
        const scenes::Scene scene = wallAndBoxes(withWall);
        const display::Display display(testing::oneScreenDisplay(128));
        const display::gl::RenderTargets plainTargets(display, *context), culledTargets(display, *context);
        SceneRenderer plain(scene);
        RenderSettings settings;
        settings.occlusion = {
            .on = true, .minTriangles = minTriangles, .minDraws = minDraws, .minSavedShare = minSavedShare};
        SceneRenderer culled(scene, settings);
        for (std::size_t i = 0; i < eyes.size(); ++i) {
            const display::HeadPose head{eyes[i], glm::dquat(1, 0, 0, 0)};
            plain.render(display.views(head), plainTargets);
            culled.render(display.views(head), culledTargets);
            const scenes::Image a = display::gl::readFrame(display, plainTargets).at(0).pixels;
            const scenes::Image b = display::gl::readFrame(display, culledTargets).at(0).pixels;
            EXPECT_EQ(a.rgba, b.rgba) << "eye " << i << " at x " << eyes[i].x;
            counts.push_back(*culled.readOcclusionCounts());
        }
        EXPECT_FALSE(plain.readOcclusionCounts().has_value());
    }
    std::vector<OcclusionCounts> counts;
    bool withWall = true;
    double minSavedShare = 0.1;
};

TEST_F(OcclusionTest, DrawsTheSameImagesWithFewerTriangles) {
    expectSameImages({{0, 0, 0}, {0, 0, 0}, {0.02, 0, 0}, {0.04, 0.01, 0}});
    ASSERT_EQ(counts.size(), 4u);
    // 364 boxes and three more objects. A view's first frame saw nothing before and tests
    // everything against empty depth, so it draws everything and remembers everything as seen;
    // its second frame draws that first and finds the boxes behind the wall hidden; from the
    // third on it draws what the wall does not hide.
    EXPECT_EQ(counts[0].trianglesDrawn, counts[0].trianglesSubmitted);
    for (std::size_t i = 2; i < counts.size(); ++i) {
        const OcclusionCounts& c = counts[i];
        EXPECT_GT(c.drawsSubmitted, 300u);
        EXPECT_LT(c.trianglesDrawn * 2, c.trianglesSubmitted) << "frame " << i << ": most boxes are behind the wall";
        EXPECT_GT(c.drawsDrawn, 3u) << "frame " << i << ": the boxes beside the wall are drawn";
    }
}

TEST_F(OcclusionTest, ObjectsComingIntoViewAreDrawnInTheirFirstFrame) {
    // The eye steps left, so the view turns past the wall's edge: boxes hidden a frame before
    // come into view and must appear at once (phase 2); then it steps back and beyond.
    const glm::dvec3 centre(0, 0, 0), left(-1.6, 0, 0);
    expectSameImages({centre, centre, centre, {-0.8, 0, 0}, left, left, left, centre, {1.0, 0.5, 0}});
    ASSERT_EQ(counts.size(), 9u);
    // From the left the wall hides less of the view: a larger share of the draws is drawn.
    auto share = [&](std::size_t i) { return double(counts[i].drawsDrawn) / double(counts[i].drawsSubmitted); };
    EXPECT_GT(share(6), 1.5 * share(2)) << counts[6].drawsDrawn << " of " << counts[6].drawsSubmitted << " against "
                                        << counts[2].drawsDrawn << " of " << counts[2].drawsSubmitted;
}

TEST_F(OcclusionTest, ListsBelowTheThresholdsAreDrawnWhole) {
    // The scene submits about 4,400 triangles: under a threshold of 5,000 nothing goes through
    // the culler (no draws counted), at 4,000 everything does.
    expectSameImages({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, 5000);
    for (const OcclusionCounts& c : counts) EXPECT_EQ(c.drawsSubmitted, 0u);
    counts.clear();
    expectSameImages({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, 4000);
    EXPECT_GT(counts.back().drawsSubmitted, 300u);
    EXPECT_LT(counts.back().trianglesDrawn * 2, counts.back().trianglesSubmitted);
    // Its 367 draws: under a threshold of 400 draws nothing is culled, at 300 everything is.
    counts.clear();
    expectSameImages({{0, 0, 0}, {0, 0, 0}}, 0, 400);
    for (const OcclusionCounts& c : counts) EXPECT_EQ(c.drawsSubmitted, 0u);
    counts.clear();
    expectSameImages({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, 0, 300);
    EXPECT_GT(counts.back().drawsSubmitted, 300u);
}

TEST_F(OcclusionTest, ViewsWhereCullingSavesLittlePauseAndAreMeasuredAgain) {
    // Without the wall nearly every box is in view: culling saves little. A view's first two culled
    // frames are not measured (the first finds everything visible against empty depth, the
    // second draws all that first), the third (2) is; frame 3 reads that measure and draws
    // whole, as do the next 15; frames 19 and 20 cull again unmeasured, 21 is measured, 22
    // pauses.
    withWall = false;
    expectSameImages(std::vector<glm::dvec3>(24, glm::dvec3(0.0)));
    ASSERT_EQ(counts.size(), 24u);
    auto culled = [&](std::size_t i) { return counts[i].drawsSubmitted > 0; };
    for (std::size_t i : {0u, 1u, 2u, 19u, 20u, 21u}) EXPECT_TRUE(culled(i)) << "frame " << i << " is culled";
    EXPECT_GT(counts[2].trianglesDrawn * 10, counts[2].trianglesSubmitted * 9) << "under a tenth is hidden";
    for (std::size_t i = 3; i < 19; ++i) EXPECT_FALSE(culled(i)) << "frame " << i << " is paused";
    EXPECT_FALSE(culled(22));
    EXPECT_FALSE(culled(23));
    // With no least share, culling never pauses.
    counts.clear();
    minSavedShare = 0.0;
    expectSameImages(std::vector<glm::dvec3>(4, glm::dvec3(0.0)));
    for (std::size_t i = 0; i < counts.size(); ++i) EXPECT_TRUE(culled(i)) << "frame " << i;
    // Where the wall hides most boxes, every frame is culled.
    counts.clear();
    withWall = true;
    minSavedShare = 0.1;
    expectSameImages(std::vector<glm::dvec3>(20, glm::dvec3(0.0)));
    for (std::size_t i = 0; i < counts.size(); ++i) EXPECT_TRUE(culled(i)) << "frame " << i;
}

TEST_F(OcclusionTest, AFrameAfterAJumpDecidesNothing) {
    // From 1 m right of the centre the wall fills most of the view: culling leaves out over 90 %
    // of the triangles, and the boxes right of the wall's edge are not even in the list. Frame 3
    // jumps 2.6 m left, past the wall's edge: phase 1 redraws the wall, all this view saw of
    // what it now draws, and phase 2 reveals the boxes, so that frame decides nothing although
    // it leaves out only about 40 %. Frame 4, the same view steady, leaves out as much and
    // decides: under a least share of 60 % frame 5 pauses.
    minSavedShare = 0.6;
    const glm::dvec3 right(1, 0, 0), left(-1.6, 0, 0);
    expectSameImages({right, right, right, left, left, left});
    ASSERT_EQ(counts.size(), 6u);
    auto culled = [&](std::size_t i) { return counts[i].drawsSubmitted > 0; };
    EXPECT_LT(counts[2].trianglesDrawn * 10, counts[2].trianglesSubmitted) << "over 90 % left out";
    for (std::size_t i : {3u, 4u}) {
        SCOPED_TRACE(i);
        EXPECT_TRUE(culled(i));
        EXPECT_GT(counts[i].trianglesDrawn * 10, counts[i].trianglesSubmitted * 4) << "under 60 % left out";
    }
    EXPECT_FALSE(culled(5)) << "the steady frame 4 pauses frame 5";
}

}  // namespace
}  // namespace cavewall::render::gl
