// Every third-party model of ../shared/scenes-real loads and renders (see its README for what
// each one stresses). One 2 m x 2 m screen 1 m in front of an eye at the origin (90°), 128 x 128
// pixels; the CAVE is placed with viewAll so the whole model is in view.
#include "display/display.h"
#include "render/gl/snapshot.h"
#include "render/view_all.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "tests/support/gl/gl_test_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace cavewall::render::gl {
namespace {

const std::filesystem::path kReal = std::filesystem::path(CAVEWALL_REAL_SCENES);
const display::HeadPose kEye{{0, 0, 0}, glm::dquat(1, 0, 0, 0)};

config::DisplayConfig oneScreen() { return testing::oneScreenDisplay(128, 0.01); }

glm::ivec4 pixel(const scenes::Image& image, std::size_t i) {
    const std::uint8_t* p = &image.rgba[i * 4];
    return {p[0], p[1], p[2], p[3]};
}

int srgb(double linear) {
    const double e = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(255.0 * e));
}

class RealScenes : public testing::GlTest {
protected:
    struct Frame {
        scenes::Image image;
        FrameStats stats;
    };
    // Renders `scene`; `worldFromCave` defaults to viewAll of the scene's bounds.
    Frame render(const scenes::Scene& scene, RenderSettings settings = {}, const glm::dmat4* worldFromCave = nullptr) {
        const glm::dmat4 place =
            worldFromCave ? *worldFromCave : render::viewAll(display, kEye, scene.bounds()).worldFromCave;
        Snapshotter s(display, scene, *context, settings);
        Snapshot shot = s.render(kEye, place);
        return {std::move(shot.images.at(0).pixels), shot.stats};
    }
    glm::ivec4 background() const {
        const glm::vec4 c = RenderSettings{}.clearColor;
        return {srgb(c.r), srgb(c.g), srgb(c.b), 255};
    }
    // Share of pixels that are not the clear colour.
    double coverage(const scenes::Image& image) const {
        std::size_t covered = 0, n = image.rgba.size() / 4;
        for (std::size_t i = 0; i < n; ++i) covered += pixel(image, i) != background();
        return double(covered) / double(n);
    }
    const display::Display display{oneScreen()};
};

TEST_F(RealScenes, EveryModelLoadsAndRendersSomethingThatIsNotUniform) {
    const char* files[] = {
        "BoxInterleaved/BoxInterleaved.glb",
        "MeshPrimitiveModes/MeshPrimitiveModes.gltf",
        "MultiUVTest/MultiUVTest.gltf",
        "NegativeScaleTest/NegativeScaleTest.gltf",
        "NodeMatrixVsTRS/Node_Attribute_07.gltf",
        "NodeMatrixVsTRS/Node_Attribute_08.gltf",
        "OcclusionRoom/room.glb",
        "OrientationTest/OrientationTest.gltf",
        "SheenChair/SheenChair.gltf",
        "SimpleSparseAccessor/SimpleSparseAccessor.gltf",
        "SponzaLOD4/sponza_s_lod4.glb",
        "TextureTransformTest/TextureTransformTest.gltf",
        "ToyCar/ToyCar.gltf",
        "WoodenBookshelf/wooden_bookshelf_worn_1k.gltf",
        "zdm2/zdm2.glb",
    };
    for (const char* file : files) {
        SCOPED_TRACE(file);
        scenes::Scene scene;
        ASSERT_NO_THROW(scene = scenes::loadSceneFile(kReal / file));
        const Frame f = render(scene);
        // viewAll frames the model's bounding sphere in the screen: it shows, but not everywhere
        // (a box inside its sphere covers well under the whole square).
        const double c = coverage(f.image);
        EXPECT_GT(c, 0.01);
        EXPECT_LT(c, 0.95);
        std::set<std::uint32_t> colours;
        for (std::size_t i = 0; i < f.image.rgba.size() / 4; ++i) {
            const glm::ivec4 p = pixel(f.image, i);
            colours.insert(p.r << 16 | p.g << 8 | p.b);
        }
        EXPECT_GE(colours.size(), 3u);  // background plus at least two shades of the model
        EXPECT_GT(f.stats.triangles, 0u);
        EXPECT_GE(f.stats.gpuMs, 0.0);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
}

TEST_F(RealScenes, GoldenImagesOfTwoModels) {
    for (const char* name : {"OcclusionRoom/room.glb", "NegativeScaleTest/NegativeScaleTest.gltf"}) {
        SCOPED_TRACE(name);
        const Frame f = render(scenes::loadSceneFile(kReal / name));
        testing::expectMatchesGolden(f.image, "real-" + std::filesystem::path(name).parent_path().string());
    }
}

TEST_F(RealScenes, NodeMatrixAndTrsRenderTheSameImage) {
    const scenes::Scene trs = scenes::loadSceneFile(kReal / "NodeMatrixVsTRS/Node_Attribute_07.gltf");
    const scenes::Scene matrix = scenes::loadSceneFile(kReal / "NodeMatrixVsTRS/Node_Attribute_08.gltf");
    // The same placement for both (their bounds agree to ~1e-7 m anyway).
    const glm::dmat4 place = render::viewAll(display, kEye, trs.bounds()).worldFromCave;
    const metrics::ImageComparison r =
        metrics::compareImages(render(matrix, {}, &place).image, render(trs, {}, &place).image);
    EXPECT_TRUE(r.passes()) << r.describe();
}

// A pixel tinted by the red "X" of the model's check-and-X texture (also where the X is
// minified into a few pinkish pixels).
bool redTinted(glm::ivec4 p) { return p.r - std::max(p.g, p.b) > 20; }

TEST_F(RealScenes, NegativeScaleShowsNoBackFaceHoles) {
    // The model (see its README) shows a green check on every front face and hides a red X on
    // a back face right behind it ("back" column), on mirrored and unmirrored nodes. Wrong
    // winding for a mirrored instance culls its front face: a hole, or the X showing. So, with
    // culling: no X tint anywhere, and no hole, i.e. no pixel showing the background where the
    // render without culling (which cannot lose a face) shows the model. That render does show
    // X tint (back faces win depth ties with their fronts), so the check can fail.
    const scenes::Scene scene = scenes::loadSceneFile(kReal / "NegativeScaleTest/NegativeScaleTest.gltf");
    RenderSettings noCulling;
    noCulling.cullBackFaces = false;
    const scenes::Image culled = render(scene).image, both = render(scene, noCulling).image;
    std::size_t redCulled = 0, redBoth = 0, holes = 0;
    for (std::size_t i = 0; i < culled.rgba.size() / 4; ++i) {
        const glm::ivec4 a = pixel(culled, i), b = pixel(both, i);
        redCulled += redTinted(a);
        redBoth += redTinted(b);
        holes += a == background() && b != background();
    }
    EXPECT_EQ(redCulled, 0u);
    EXPECT_EQ(holes, 0u);
    EXPECT_GT(redBoth, 0u);
    if (redCulled > 0 || holes > 0) {
        const std::filesystem::path out = testing::testOutputFolder("negative-scale");
        scenes::writeImage(out / "culled.png", culled);
        scenes::writeImage(out / "both-faces.png", both);
    }
}

TEST_F(RealScenes, SponzaWithoutNormalsIsLitSensibly) {
    const Frame f = render(scenes::loadSceneFile(kReal / "SponzaLOD4/sponza_s_lod4.glb"));
    // Default material (white): every lit pixel gets at least the ambient share 0.35 of white,
    // sRGB 160, whatever its normal; a NaN or zero normal from a degenerate triangle would
    // show as black or as a lone unlit value.
    const int floor = srgb(RenderSettings{}.ambient) - 1;
    double sum = 0.0;
    std::size_t covered = 0, dark = 0;
    for (std::size_t i = 0; i < f.image.rgba.size() / 4; ++i) {
        const glm::ivec4 p = pixel(f.image, i);
        if (p == background()) continue;
        ++covered;
        dark += std::min({p.r, p.g, p.b}) < floor;
        sum += (p.r + p.g + p.b) / 3.0;
    }
    ASSERT_GT(covered, 500u);
    EXPECT_EQ(dark, 0u);
    // Mean brightness between the ambient floor and pure white, and not a flat white: the
    // headlight shades surfaces by their angle.
    const double mean = sum / double(covered);
    EXPECT_GT(mean, floor + 10);
    EXPECT_LT(mean, 250.0);
}

}  // namespace
}  // namespace cavewall::render::gl
