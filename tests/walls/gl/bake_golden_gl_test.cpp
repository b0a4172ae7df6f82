// Bake golden test: seen from its sampling point, a baked wall texture drawn as a quad on its
// wall must look like the geometry it replaces. Reference: the scene renderer drawing the
// content behind the wall (listed here by construction, not by the classifier under test) into a
// target of the texture's resolution through the same off-axis frustum (screen = the wall).
// Candidate: the baked file, read back with readMipLevels, uploaded and drawn with
// WallQuadDrawer over the same clear colour. With screen = wall and viewport = texture size,
// texel centres fall on pixel centres, so the only differences are rounding (STYLE.md §5
// tolerances). The clear colour is an opaque grey, so a texel that wrongly holds structure,
// the intersecting box or opaque black where nothing is shows up as a bad pixel.
#include "render/gl/scene_renderer.h"
#include "metrics/image_compare.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/walls/gl/bake_test_scene.h"
#include "walls/bake_key.h"
#include "walls/gl/baker.h"
#include "walls/gl/wall_quad.h"
#include "walls/gl/offscreen_target.h"

#include <gmock/gmock.h>

#include <limits>

namespace cavewall::walls::gl {
namespace {

int objectNamed(const scenes::Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == name) return static_cast<int>(i);
    ADD_FAILURE() << "no object named " << name;
    return -1;
}

class BakeGoldenTest : public cavewall::testing::GlTest {
protected:
    std::filesystem::path folder(const std::string& name) {
        const std::filesystem::path f = cavewall::testing::testOutputFolder("bake_golden") / name;
        std::filesystem::remove_all(f);
        return f;
    }
};

constexpr glm::vec4 kClear{0.18f, 0.18f, 0.18f, 1.0f};  // linear grey, opaque

TEST_F(BakeGoldenTest, BakedTextureMatchesGeometryFromItsSamplingPoint) {
    const std::filesystem::path root = folder("golden");
    BakeRequest request;
    request.scene = gl::testing::writeBakeTestScene(root / "scene");
    request.cache = root / "cache";
    request.settings.maxResolution = 128;
    request.context = context.get();
    const BakeResult result = bakeScene(request);
    ASSERT_GT(result.manifest.textures.size(), 0u);

    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(request.scene, &description);
    const walls::Plan plan = walls::planZones(description, request.plan);
    // What each side shows, by construction (bake_test_scene.h): the back cell's boxes from the
    // front (side 0), the yellow box from the back (side 1).
    const std::vector<int> shown[2] = {
        {objectNamed(scene, "red"), objectNamed(scene, "green"), objectNamed(scene, "blue")},
        {objectNamed(scene, "yellow")}};
    render::gl::SceneRenderer renderer(scene, render::gl::RenderSettings{kClear, BakeSettings{}.ambient});
    WallQuadDrawer drawer;
    int checked[2] = {0, 0};
    for (const walls::BakedTexture& baked : result.manifest.textures) {
        const int side = description.walls[baked.wall].cells[0] == baked.cell ? 0 : 1;
        if (checked[side] >= 2) continue;  // two textures per side keep the test short
        ++checked[side];
        SCOPED_TRACE("texture " + std::to_string(baked.id) + " side " + std::to_string(side));
        const display::ScreenQuad quad = walls::quadSeenFrom(plan.walls[baked.wall].quad, side);
        const display::OffAxisFrustum frustum =
            display::offAxisFrustum(quad, baked.samplingPoint, {0.05, std::numeric_limits<double>::infinity()});
        ASSERT_EQ(frustum.guard, display::EyeGuard::None);  // the sampling point is in front of its side

        const OffscreenTarget target(baked.resolution);
        render::gl::ViewTarget view{
            target.framebuffer(), {0, 0, baked.resolution.x, baked.resolution.y}, kClear, glm::bvec4(true)};
        render::DrawFilter filter;
        filter.objects = &shown[side];
        renderer.renderFrustum(frustum, glm::dmat4(1.0), view, filter);
        const scenes::Image geometry = target.read("geometry");

        const std::vector<scenes::Image> levels =
            scenes::readMipLevels(request.cache / walls::hex64(result.key) / baked.file);
        ASSERT_EQ(levels[0].width, baked.resolution.x);
        const display::gl::GlObject texture = uploadWallTexture(levels);
        target.bindAndClear(kClear);
        drawer.draw(frustum, quad, texture.id());
        const scenes::Image wall = target.read("baked wall");

        const metrics::ImageComparison c = metrics::compareImages(wall, geometry);
        EXPECT_TRUE(c.passes()) << c.describe();
        if (!c.passes()) {
            const std::filesystem::path out =
                cavewall::testing::testOutputFolder("bake_golden/texture_" + std::to_string(baked.id));
            scenes::writeImage(out / "actual.png", wall);
            scenes::writeImage(out / "expected.png", geometry);
            scenes::writeImage(out / "diff.png", metrics::differenceImage(wall, geometry));
        }
        // Not vacuous: the texture shows something and leaves something transparent.
        int opaque = 0, clear = 0;
        for (std::size_t p = 3; p < levels[0].rgba.size(); p += 4) {
            opaque += levels[0].rgba[p] == 255;
            clear += levels[0].rgba[p] == 0;
        }
        EXPECT_GT(opaque, 0);
        EXPECT_GT(clear, 0);
    }
    EXPECT_GT(checked[0], 0);
    EXPECT_GT(checked[1], 0);
}

}  // namespace
}  // namespace cavewall::walls::gl
