// Renderer behaviour checked on single pixels of tiny scenes: one 2 m x 2 m screen 1 m in front
// of an eye at the origin (a symmetric 90° frustum), 64 x 64 pixels. The centre pixel looks
// straight down -Z, where the headlight falls perpendicularly on a facing quad, so lighting is 1
// and the pixel shows the material colour itself (sRGB-encoded).
#include "config/error.h"
#include "display/display.h"
#include "display/gl/shader.h"
#include "render/gl/snapshot.h"
#include "render/gl/view_loop.h"
#include "render/render_list.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>

namespace cavewall::render::gl {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

config::DisplayConfig oneScreen() { return testing::oneScreenDisplay(); }

const display::HeadPose kEyeAtOrigin{{0, 0, 0}, glm::dquat(1, 0, 0, 0)};

// A square of `size` metres facing +Z (towards the eye) centred at `centre`, with `material`.
void addQuad(scenes::Scene& scene, glm::dvec3 centre, float size, int material, glm::dmat4 extra = glm::dmat4(1.0)) {
    scenes::Mesh m = scenes::makeTiledQuad({-size / 2, -size / 2, 0}, {size, 0, 0}, {0, size, 0}, 1, 1, glm::vec4(1.0f),
                                           glm::vec4(1.0f));
    m.material = material;
    scene.meshes.push_back(std::move(m));
    scenes::addObject(scene, static_cast<int>(scene.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre) * extra,
                      "quad");
}

int addMaterial(scenes::Scene& scene, glm::vec4 color, scenes::AlphaMode mode = scenes::AlphaMode::Opaque,
                bool doubleSided = false) {
    scenes::Material m;
    m.baseColorFactor = color;
    m.alphaMode = mode;
    m.doubleSided = doubleSided;
    scene.materials.push_back(m);
    return static_cast<int>(scene.materials.size()) - 1;
}

glm::ivec4 pixel(const scenes::Image& image, int x, int y) {
    const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

// sRGB encoding of a linear value, in 8-bit levels.
int srgb(double linear) {
    const double e = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(255.0 * e));
}

class SceneRendererTest : public testing::GlTest {
protected:
    scenes::Image render(const scenes::Scene& scene, const glm::dmat4& worldFromCave = glm::dmat4(1.0),
                         RenderSettings settings = {}) {
        const display::Display d(oneScreen());
        Snapshotter s(d, scene, *context, settings);
        return s.render(kEyeAtOrigin, worldFromCave).images.at(0).pixels;
    }
    // All light ambient: pixels away from the centre show exact material colours.
    static RenderSettings unlit() {
        RenderSettings s;
        s.ambient = 1.0f;
        return s;
    }
    // The clear colour as read back.
    glm::ivec4 background() const {
        const glm::vec4 c = RenderSettings{}.clearColor;
        return {srgb(c.r), srgb(c.g), srgb(c.b), 255};
    }
};

TEST_F(SceneRendererTest, LinearShadingIsStoredSrgbEncoded) {
    scenes::Scene scene;
    addQuad(scene, {0, 0, -2}, 1.0f, addMaterial(scene, {0.5f, 0.2f, 0.05f, 1.0f}));
    const glm::ivec4 c = pixel(render(scene), 32, 32);
    // Linear 0.5 is sRGB 188, 0.2 is 124, 0.05 is 63 (the sRGB curve, not 128/51/13).
    EXPECT_NEAR(c.r, srgb(0.5), 1);
    EXPECT_NEAR(c.g, srgb(0.2), 1);
    EXPECT_NEAR(c.b, srgb(0.05), 1);
    EXPECT_EQ(c.a, 255);
    EXPECT_EQ(pixel(render(scene), 0, 0), background());  // the quad covers only the middle
}

TEST_F(SceneRendererTest, ReversedZSeparatesSurfacesOneMetreApartTenKilometresAway) {
    // A green square 10 km away in front of a wider red one 1 m behind it. The frustum is 90°,
    // so at 10 km the centre pixel spans about 300 m: the green square (4 km) covers it.
    scenes::Scene scene;
    addQuad(scene, {0, 0, -10001}, 40000.0f, addMaterial(scene, {1, 0, 0, 1}));
    addQuad(scene, {0, 0, -10000}, 4000.0f, addMaterial(scene, {0, 1, 0, 1}));
    const glm::ivec4 centre = pixel(render(scene), 32, 32);
    EXPECT_GT(centre.g, 200);
    EXPECT_EQ(centre.r, 0);
    EXPECT_GT(pixel(render(scene), 2, 2).r, 150);  // the red square shows around it
}

TEST_F(SceneRendererTest, CullingHonoursDoubleSidedAndFlippedWinding) {
    const glm::dmat4 turned = glm::rotate(glm::dmat4(1.0), glm::radians(180.0), glm::dvec3(0, 1, 0));
    const glm::dmat4 mirrored = glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1));
    struct Case {
        const char* name;
        glm::dmat4 transform;
        bool doubleSided;
        bool visible;
    };
    const Case cases[] = {
        {"facing the eye", glm::dmat4(1.0), false, true},
        {"turned away, single-sided: culled", turned, false, false},
        {"turned away, double-sided: drawn", turned, true, true},
        // Mirroring reverses the winding but the quad still faces the eye: flipWinding keeps it.
        {"mirrored, single-sided: drawn", mirrored, false, true},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        scenes::Scene scene;
        addQuad(scene, {0, 0, -2}, 1.0f, addMaterial(scene, {1, 1, 1, 1}, scenes::AlphaMode::Opaque, c.doubleSided),
                c.transform);
        const glm::ivec4 centre = pixel(render(scene), 32, 32);
        if (c.visible) {
            // Lit by the headlight on whichever side faces the eye: full white, not dark.
            EXPECT_GE(centre.r, 250);
        } else {
            EXPECT_EQ(centre, background());
        }
    }
}

TEST_F(SceneRendererTest, AlphaMaskDiscardsAndBlendMixesOverOpaque) {
    scenes::Scene scene;
    addQuad(scene, {0, 0, -3}, 4.0f, addMaterial(scene, {0, 0, 1, 1}));  // blue, opaque, behind
    // Drawn first in object order but blended after all opaque objects: over the blue.
    addQuad(scene, {0.5, 0, -2}, 1.0f, addMaterial(scene, {1, 0, 0, 0.5f}, scenes::AlphaMode::Blend));
    addQuad(scene, {-0.5, 0, -2}, 1.0f, addMaterial(scene, {1, 0, 0, 0.3f}, scenes::AlphaMode::Mask));
    const scenes::Image image = render(scene, glm::dmat4(1.0), unlit());
    // Mask: alpha 0.3 is below the 0.5 cutoff, so the blue shows through unchanged (the left quad
    // covers x in [-1, 0] m at 2 m, i.e. pixels 16 to 31 of the 64 on the screen plane).
    EXPECT_EQ(pixel(image, 20, 32), glm::ivec4(0, 0, 255, 255));
    // Blend: half red over blue in linear light (unlit: colours as given), then encoded: both 0.5 -> 188; alpha stays 1.
    const glm::ivec4 mixed = pixel(image, 44, 32);
    EXPECT_NEAR(mixed.r, srgb(0.5), 2);
    EXPECT_NEAR(mixed.b, srgb(0.5), 2);
    EXPECT_EQ(mixed.a, 255);
}

// The frame's clear is deferred to the first view drawn into each image (beginFrame marks,
// renderView clears with its drawing, endFrame clears the rest): whatever path clears, no pixel
// of the last frame may survive into the next.
TEST_F(SceneRendererTest, EveryFrameStartsFromTheClearColourWhicheverViewsAreDrawn) {
    scenes::Scene scene;
    addQuad(scene, {0, 0, -2}, 40.0f, addMaterial(scene, {1, 0, 0, 1}));  // fills the screen
    const display::Display d(oneScreen());
    const display::gl::RenderTargets targets(d, *context);
    SceneRenderer renderer(scene, unlit());
    const std::vector<display::ScreenView> views = d.views(kEyeAtOrigin);
    const auto covered = [&](glm::ivec4 colour) {
        const scenes::Image image = targets.read(0, 0);
        int n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) n += pixel(image, x, y) == colour;
        return n;
    };
    const int all = 64 * 64;
    const glm::ivec4 red(255, 0, 0, 255);
    renderer.render(views, targets);
    ASSERT_EQ(covered(red), all);
    // The view turned away from the quad: the view's own clear leaves no red.
    renderer.render(views, targets, glm::rotate(glm::dmat4(1.0), glm::pi<double>(), glm::dvec3(0, 1, 0)));
    EXPECT_EQ(covered(background()), all);
    renderer.render(views, targets);
    ASSERT_EQ(covered(red), all);
    // A frame in which no view draws into the image: endFrame clears it.
    renderer.beginFrame(targets);
    forEachView({}, targets, [](const display::ScreenView&) { return ViewStats{}; });
    renderer.endFrame(targets);
    EXPECT_EQ(covered(background()), all);
}

TEST_F(SceneRendererTest, BaseColourTextureIsSampledWithItsTransform) {
    scenes::Scene scene;
    // 2 x 2 texels, rows top to bottom: red, green / blue, white.
    scene.images.push_back({"checker", 2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}});
    int material = addMaterial(scene, {1, 1, 1, 1});
    scene.materials[material].baseColorTexture.image = 0;
    scene.materials[material].baseColorTexture.wrapS = scenes::Wrap::Repeat;
    addQuad(scene, {0, 0, -1.0001}, 2.0f, material);  // fills the screen
    // makeTiledQuad puts texture coordinate (0, 0) at the quad's lower-left corner, and (0, 0)
    // is the image's top-left texel (glTF), so the lower-left quadrant is red.
    const scenes::Image plain = render(scene, glm::dmat4(1.0), unlit());
    EXPECT_GT(pixel(plain, 16, 48).r, 240);  // lower-left: red
    EXPECT_GT(pixel(plain, 48, 48).g, 240);  // lower-right: green
    EXPECT_GT(pixel(plain, 16, 16).b, 240);  // upper-left: blue
    // Shifting u by half the texture swaps the columns.
    scene.materials[material].baseColorTexture.transform = glm::mat3(1, 0, 0, 0, 1, 0, 0.5f, 0, 1);
    const scenes::Image shifted = render(scene, glm::dmat4(1.0), unlit());
    EXPECT_GT(pixel(shifted, 16, 48).g, 240);
    EXPECT_GT(pixel(shifted, 48, 48).r, 240);
}

TEST_F(SceneRendererTest, LightingPerVertexMatchesPerPixelWithinOneLevel) {
    // Boxes of 0.3-1 m, 3-42 m away, turned every way: the far ones are lit per vertex
    // (render/vertex_lighting.h proves a difference of at most 1/512 of the light, half an sRGB
    // level), the near ones per pixel. Drawn both ways, no channel of any pixel may differ by
    // more than one level (the bound plus rounding).
    scenes::Scene scene;
    const int material = addMaterial(scene, {0.9f, 0.6f, 0.3f, 1.0f});
    for (int i = 0; i < 40; ++i) {
        const double z = -3.0 - i;
        const float size = 0.3f + 0.7f * static_cast<float>(i % 5) / 4.0f;
        scenes::Mesh box = scenes::makeBox({size, size, size}, glm::vec4(1.0f));
        box.material = material;
        scene.meshes.push_back(std::move(box));
        const glm::dmat4 place =
            glm::rotate(glm::translate(glm::dmat4(1.0), {0.08 * z * std::sin(i), 0.08 * z * std::cos(i), z}), 0.7 * i,
                        glm::normalize(glm::dvec3(1.0, 0.5 * i, 0.3)));
        scenes::addObject(scene, static_cast<int>(scene.meshes.size()) - 1, place, "box");
    }
    // A floor of two big triangles 1.5 m under the eye: per vertex it would lose the light's
    // peak under the eye by far more than a level (that is what makes this test fail when the
    // bound is ignored).
    addQuad(scene, {0, -1.5, -10}, 20.0f, material,
            glm::rotate(glm::dmat4(1.0), -glm::half_pi<double>(), {1.0, 0.0, 0.0}));
    render::RenderScene rs(scene, false);
    render::ListBuilder lists(rs);
    const display::Display d(oneScreen());
    const render::RenderList& list = lists.build(d.views(kEyeAtOrigin).at(0).frustum, glm::dmat4(1.0), {});
    const auto perVertex =
        std::count_if(list.draws.begin(), list.draws.end(), [](const render::Draw& x) { return x.vertexLit; });
    EXPECT_GT(perVertex, 5);
    EXPECT_LT(perVertex, static_cast<long>(list.draws.size()));
    RenderSettings perPixelOnly;
    perPixelOnly.vertexLightingTolerance = 0.0;
    const scenes::Image mixed = render(scene), exact = render(scene, glm::dmat4(1.0), perPixelOnly);
    int worst = 0;
    for (std::size_t i = 0; i < mixed.rgba.size(); ++i)
        worst = std::max(worst, std::abs(mixed.rgba[i] - exact.rgba[i]));
    EXPECT_LE(worst, 1);
}

TEST_F(SceneRendererTest, MovingTheCaveAndTheSceneTogetherChangesNothingEvenFarAway) {
    // Everything 10 000 km from the world origin: in float, positions there are 1 m apart, but
    // the model-view composes in double first, so the picture matches the one at the origin.
    // The CAVE stands at a fractional offset in the scene, so float rounding of its placement
    // would shift the picture by decimetres instead of cancelling by luck.
    scenes::Scene nearScene = scenes::builtinTestScene(), farScene = nearScene;
    const glm::dmat4 far = glm::translate(glm::dmat4(1.0), glm::dvec3(1e7, 0, -1e7));
    for (scenes::Object& o : farScene.objects) o.worldFromModel = far * o.worldFromModel;
    farScene.updateObjectBounds();
    const glm::dmat4 stand = glm::translate(glm::dmat4(1.0), glm::dvec3(0.37, 1.6, -0.61));
    const metrics::ImageComparison r = metrics::compareImages(render(farScene, far * stand), render(nearScene, stand));
    EXPECT_TRUE(r.passes()) << r.describe();
}

TEST_F(SceneRendererTest, QuadBufferStereoWithoutStereoWindowsIsAClearError) {
    config::DisplayConfig c = oneScreen();
    c.stereo = config::StereoMode::QuadBuffer;
    const display::Display d(c);
    EXPECT_THAT([&] { display::gl::RenderTargets targets(d, *context); },
                ThrowsMessage<Error>(HasSubstr("stereo mode quad-buffer needs windows with quad-buffer stereo")));
}

TEST_F(SceneRendererTest, ShaderErrorsNameTheStageAndCarryTheLog) {
    const char* vertex = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    EXPECT_THAT(
        [&] { display::gl::buildProgram("broken", vertex, "#version 450 core\nvoid main() { undefined_thing; }\n"); },
        ThrowsMessage<Error>(HasSubstr("shader program 'broken': fragment stage failed to compile: ")));
    EXPECT_THAT(
        [&] {
            display::gl::buildProgram("broken", "#version 450 core\nvoid main() { x }\n",
                                      "#version 450 core\nvoid main() {}\n");
        },
        ThrowsMessage<Error>(HasSubstr("vertex stage failed to compile")));
    const display::gl::GlObject ok = display::gl::buildProgram("empty", vertex, "#version 450 core\nvoid main() {}\n");
    EXPECT_THAT([&] { display::gl::uniformLocation(ok.id(), "empty", "uMissing"); },
                ThrowsMessage<Error>(HasSubstr("expected an active uniform 'uMissing'")));
}

}  // namespace
}  // namespace cavewall::render::gl
