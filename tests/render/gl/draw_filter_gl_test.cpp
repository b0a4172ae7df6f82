// The single-view API of the scene renderer (what the walkthrough and the wall baker call):
// what a render list selects is what shows in pixels. (Filter semantics, culling, order and
// batches are unit-tested without GL in tests/render/.) Scene: three unlit 0.5 m squares 2 m in front of an eye at the origin, at
// x = -1, 0, +1 m, red, green and blue; one 2 m x 2 m screen 1 m away, 64 x 64 pixels. At 2 m a
// point at x maps to x / 2 on the screen, so the squares' centres fall on pixel columns 16, 32
// and 48 of row 32, each covering 8 x 8 pixels.
#include "display/display.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace cavewall::render::gl {
namespace {

const glm::ivec4 kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255};
const int kColumns[3] = {16, 32, 48};

config::DisplayConfig oneScreen() { return testing::oneScreenDisplay(); }

void addSquare(scenes::Scene& scene, glm::dvec3 centre, glm::vec4 color, scenes::Role role = scenes::Role::Content,
               scenes::AlphaMode mode = scenes::AlphaMode::Opaque) {
    scenes::Material material;
    material.baseColorFactor = color;
    material.alphaMode = mode;
    scene.materials.push_back(material);
    scenes::Mesh m =
        scenes::makeTiledQuad({-0.25f, -0.25f, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}, 1, 1, glm::vec4(1.0f), glm::vec4(1.0f));
    m.material = static_cast<int>(scene.materials.size()) - 1;
    scene.meshes.push_back(std::move(m));
    scenes::addObject(scene, static_cast<int>(scene.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), centre),
                      "square", role);
}

// Red (content), green (structure), blue (content).
scenes::Scene threeSquares() {
    scenes::Scene scene;
    addSquare(scene, {-1, 0, -2}, {1, 0, 0, 1});
    addSquare(scene, {0, 0, -2}, {0, 1, 0, 1}, scenes::Role::Structure);
    addSquare(scene, {1, 0, -2}, {0, 0, 1, 1});
    return scene;
}

glm::ivec4 pixel(const scenes::Image& image, int x, int y) {
    const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

RenderSettings unlit() {
    RenderSettings s;
    s.ambient = 1.0f;  // colours exactly as given
    s.clearColor = {0, 0, 0, 1};
    return s;
}

class DrawFilterTest : public testing::GlTest {
protected:
    struct Result {
        scenes::Image image;
        ViewStats stats;
    };
    // Renders the single view through beginFrame + renderView, the walkthrough's path.
    Result render(const scenes::Scene& scene, const render::DrawFilter& filter) {
        const display::Display d(oneScreen());
        const display::gl::RenderTargets targets(d, *context);
        SceneRenderer renderer(scene, unlit());
        const display::ScreenView view = d.views({{0, 0, 0}, glm::dquat(1, 0, 0, 0)}).at(0);
        renderer.beginFrame(targets);
        targets.bind(view.screen, display::gl::RenderTargets::imageOf(view.pass));
        const ViewStats stats = renderer.renderView(view, glm::dmat4(1.0), filter);
        return {targets.read(0, 0), stats};
    }
    // Which of the three squares show, as a string like "R-B".
    static std::string shown(const scenes::Image& image) {
        std::string s;
        const glm::ivec4 colors[3] = {kRed, kGreen, kBlue};
        for (int i = 0; i < 3; ++i) s += pixel(image, kColumns[i], 32) == colors[i] ? "RGB"[i] : '-';
        return s;
    }
};

TEST_F(DrawFilterTest, OnlySelectedObjectsAreSubmitted) {
    const scenes::Scene scene = threeSquares();
    const std::vector<int> firstAndLast{2, 0, 0, 7, -1};  // order, duplicates and bad indices do not matter
    const std::vector<int> middle{1};
    struct Case {
        const char* name;
        render::DrawFilter filter;
        const char* expected;
    };
    render::DrawFilter list, noStructure, middleWithoutStructure;
    list.objects = &firstAndLast;
    noStructure.skipStructure = true;
    middleWithoutStructure.objects = &middle;
    middleWithoutStructure.skipStructure = true;
    const Case cases[] = {
        {"no filter draws all", {}, "RGB"},
        {"object list", list, "R-B"},
        {"skip structure (green)", noStructure, "R-B"},
        {"list and skip structure intersect: nothing", middleWithoutStructure, "---"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const Result r = render(scene, c.filter);
        EXPECT_EQ(shown(r.image), c.expected);
        // Each square is one object with two triangles, drawn with nothing else.
        const int drawn = static_cast<int>(std::string(c.expected).find_first_not_of('-') == std::string::npos
                                               ? 0
                                               : 3 - std::count(c.expected, c.expected + 3, '-'));
        EXPECT_EQ(r.stats.objectsDrawn, drawn);
        EXPECT_EQ(r.stats.triangles, std::size_t(2 * drawn));
    }
}

TEST_F(DrawFilterTest, FrustumCullingLeavesOutObjectsOutsideAndChangesNoPixel) {
    scenes::Scene scene = threeSquares();
    addSquare(scene, {0, 0, 2}, {1, 1, 1, 1});    // behind the eye
    addSquare(scene, {50, 0, -2}, {1, 1, 1, 1});  // far to the right of the 90° frustum
    render::DrawFilter noCulling;
    noCulling.frustumCull = false;
    const Result culled = render(scene, {}), all = render(scene, noCulling);
    EXPECT_EQ(culled.stats.objectsDrawn, 3);  // the two outside squares are not submitted
    EXPECT_EQ(all.stats.objectsDrawn, 5);
    EXPECT_EQ(culled.image.rgba, all.image.rgba);  // and they could not have shown anyway
}

TEST_F(DrawFilterTest, EachGlStateIsOneMultiDrawAndMirroredObjectsGetTheirOwn) {
    scenes::Scene scene = threeSquares();
    // A white square mirrored in x (det < 0: clockwise front faces) above the green one; it
    // still faces the eye. At y = 0.75 m, 2 m away, its centre is on pixel row 32 - 0.375 * 32 = 20.
    addSquare(scene, {0, 0.75, -2}, {1, 1, 1, 1});
    scene.objects.back().worldFromModel = scene.objects.back().worldFromModel * glm::scale(glm::dmat4(1.0), {-1, 1, 1});
    scene.updateObjectBounds();
    ASSERT_TRUE(scene.objects.back().flipWinding);
    const Result r = render(scene, {});
    EXPECT_EQ(shown(r.image), "RGB");
    EXPECT_EQ(pixel(r.image, 32, 20), glm::ivec4(255, 255, 255, 255));  // not culled as a back face
    EXPECT_EQ(r.stats.objectsDrawn, 4);
    // Counter-clockwise (3 squares) and clockwise (1): two states, two multi-draws.
    EXPECT_EQ(r.stats.drawCalls, 2);
}

// The wall baker's path: a frustum in the world frame into the caller's RGBA framebuffer,
// cleared to alpha 0.
class RenderFrustumTest : public DrawFilterTest {
protected:
    void SetUp() override {
        DrawFilterTest::SetUp();
        if (!context) return;
        color = display::gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(color.id(), 1, GL_SRGB8_ALPHA8, 64, 64);
        depth = display::gl::createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, 64, 64);
        framebuffer = display::gl::createFramebuffer();
        glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
        glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    }
    void TearDown() override {
        color.reset();  // before the context goes
        depth.reset();
        framebuffer.reset();
        DrawFilterTest::TearDown();
    }
    scenes::Image bake(const scenes::Scene& scene, const glm::dmat4& worldFromFrame,
                       const render::DrawFilter& filter = {}) {
        // The wall: the display's screen quad, seen from the origin of the frame.
        const display::OffAxisFrustum frustum =
            display::offAxisFrustum({{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}}, {0, 0, 0}, {0.05, INFINITY});
        SceneRenderer renderer(scene, unlit());
        ViewTarget target{framebuffer.id(), {0, 0, 64, 64}, glm::vec4(0.0f), glm::bvec4(true)};
        last = renderer.renderFrustum(frustum, worldFromFrame, target, filter);
        return display::gl::readFramebuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0, {64, 64}, "bake");
    }
    display::gl::GlObject color, depth, framebuffer;
    ViewStats last;
};

TEST_F(RenderFrustumTest, NothingDrawnIsAlphaZeroAndTheFrameIsPlacedByWorldFromFrame) {
    const scenes::Scene scene = threeSquares();
    const scenes::Image image = bake(scene, glm::dmat4(1.0));
    EXPECT_EQ(shown(image), "RGB");
    EXPECT_EQ(pixel(image, 2, 2), glm::ivec4(0, 0, 0, 0));  // cleared to transparent black
    EXPECT_EQ(last.objectsDrawn, 3);
    // Moving the frame 1 m to the right in the world puts the eye in front of the blue square:
    // blue now sits in the middle column, green in the left one, red leaves the 8 x 8 spots.
    const scenes::Image moved = bake(scene, glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, 0)));
    EXPECT_EQ(pixel(moved, 32, 32), kBlue);
    EXPECT_EQ(pixel(moved, 16, 32), kGreen);
    EXPECT_EQ(pixel(moved, 48, 32).a, 0);
}

TEST_F(RenderFrustumTest, BlendedObjectsLeaveTheirCoverageInAlpha) {
    scenes::Scene scene;
    addSquare(scene, {0, 0, -2}, {1, 0, 0, 0.5f}, scenes::Role::Content, scenes::AlphaMode::Blend);
    const scenes::Image image = bake(scene, glm::dmat4(1.0));
    const glm::ivec4 c = pixel(image, 32, 32);
    // Alpha: 0.5 * 1 + (1 - 0.5) * 0 = 0.5 coverage (alpha is stored linearly: 128 of 255).
    EXPECT_NEAR(c.a, 128, 1);
    // Colour: 0.5 * red over black, sRGB-encoded: linear 0.5 -> 188.
    EXPECT_NEAR(c.r, 188, 1);
    EXPECT_EQ(pixel(image, 2, 2).a, 0);
}

TEST_F(DrawFilterTest, RenderSumsViewsAndReportsGpuTimeOnceAvailable) {
    const scenes::Scene scene = threeSquares();
    const display::Display d(oneScreen());
    const display::gl::RenderTargets targets(d, *context);
    SceneRenderer renderer(scene, unlit());
    const auto views = d.views({{0, 0, 0}, glm::dquat(1, 0, 0, 0)});
    FrameStats stats = renderer.render(views, targets);
    EXPECT_EQ(stats.views, 1);
    EXPECT_EQ(stats.objectsDrawn, 3);
    EXPECT_EQ(stats.triangles, 6u);
    // Three materials but one GL state (untextured, single-sided, counter-clockwise): one multi-draw.
    EXPECT_EQ(stats.drawCalls, 1);
    ASSERT_EQ(stats.perView.size(), 1u);
    EXPECT_GE(stats.cpuMs, stats.perView[0].cpuMs);
    // Timer results come back a frame or more later, never by waiting: render until one does.
    for (int frame = 0; frame < 100 && stats.gpuMs < 0.0; ++frame) {
        glFinish();
        stats = renderer.render(views, targets);
    }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    EXPECT_GT(stats.gpuMs, 0.0);
    // Three squares take microseconds; a raw timestamp taken for a duration (llvmpipe's first
    // GL_TIME_ELAPSED, gpu_timer.h) would read as ~1e6 ms.
    EXPECT_LT(stats.gpuMs, 1000.0);
}

}  // namespace
}  // namespace cavewall::render::gl
