// Levels of detail in the scene renderer, in pixels: a finely tessellated white cylinder on
// black, drawn at full detail and at the levels render::chooseLods picks for a tolerance, must
// differ only where the full image has a silhouette within that tolerance. (The choice itself,
// budgets and predicted triangles included, is unit-tested in tests/render/lod_choice_test.cpp.)
//
// Scene: a cylinder of radius 0.5 m and height 1 m with 720 segments (its chords deviate
// 0.5 (1 - cos(pi / 720)) = 5e-6 m from the circle: far below a pixel), welded as the loader
// welds, standing 4 m in front of a one-screen display (2 m screen 1 m from the eye, 256 x 256
// pixels: 1 px = 7.8 mm on the screen, so 3.1 cm at 4 m).
#include "display/display.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "render/lod_choice.h"
#include "scenes/mesh_optimize.h"
#include "scenes/primitives.h"
#include "tests/support/gl/gl_test_support.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace cavewall::render::gl {
namespace {

constexpr int kPixels = 256;

scenes::Scene cylinderScene(double distance) {
    scenes::Scene scene;
    scenes::Mesh m = scenes::makeCylinder(0.5f, 1.0f, 720, glm::vec4(1.0f));
    scenes::weldVertices(m);
    scenes::optimizeVertexOrder(m);
    scene.meshes.push_back(std::move(m));
    scenes::addObject(scene, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0.1, -0.6, -distance)), "cylinder");
    return scene;
}

RenderSettings flatWhite(double lodPixels) {
    RenderSettings s;
    s.ambient = 1.0f;  // unlit: the image is the coverage mask
    s.clearColor = {0, 0, 0, 1};
    s.lodPixels = lodPixels;
    return s;
}

struct Frame {
    scenes::Image image;
    FrameStats stats;
    render::FrameLod lod;
};

bool covered(const scenes::Image& image, int x, int y) {
    return image.rgba[(std::size_t(y) * image.width + x) * 4] > 127;
}

// Pixels where the coverage differs and no pixel within `radius` (Chebyshev) of it in the
// reference has the other coverage, i.e. differences away from the reference's silhouette.
int differencesAwayFromSilhouette(const scenes::Image& reference, const scenes::Image& image, int radius) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const bool here = covered(reference, x, y);
            if (here == covered(image, x, y)) continue;
            bool edge = false;
            for (int dy = -radius; dy <= radius && !edge; ++dy)
                for (int dx = -radius; dx <= radius && !edge; ++dx) {
                    const int u = std::clamp(x + dx, 0, image.width - 1), v = std::clamp(y + dy, 0, image.height - 1);
                    edge = covered(reference, u, v) != here;
                }
            count += edge ? 0 : 1;
        }
    return count;
}

class LodTest : public testing::GlTest {
protected:
    Frame render(const scenes::Scene& scene, double lodPixels, std::size_t budget = 0) {
        const display::Display d(testing::oneScreenDisplay(kPixels));
        const display::gl::RenderTargets targets(d, *context);
        SceneRenderer renderer(scene, flatWhite(lodPixels));
        const std::vector<display::ScreenView> views = d.views({{0, 0, 0}, glm::dquat(1, 0, 0, 0)});
        Frame f;
        render::DrawFilter filter;
        f.lod = render::chooseLods(renderer.renderScene(), views, glm::dmat4(1.0), filter, lodPixels, budget);
        filter.lodLevels = &f.lod.levels;
        f.stats = renderer.render(views, targets, glm::dmat4(1.0), filter);
        f.image = targets.read(0, 0);
        return f;
    }
};

TEST_F(LodTest, SilhouettesMoveByAtMostTheTolerance) {
    for (double distance : {2.0, 4.0, 12.0}) {
        const scenes::Scene scene = cylinderScene(distance);
        const Frame full = render(scene, 0.0);
        for (double tolerance : {0.5, 1.0, 3.0}) {
            SCOPED_TRACE("distance " + std::to_string(distance) + " m, tolerance " + std::to_string(tolerance) + " px");
            const Frame lod = render(scene, tolerance);
            EXPECT_LE(lod.lod.maxErrorPx, tolerance);
            // A silhouette moved by t pixels flips only pixels whose centres lie within t of the
            // true edge: within ceil(t) + 1 pixels of a pixel of the other coverage (the +1 for
            // the pixel-centre sampling of the rasteriser).
            const int radius = static_cast<int>(std::ceil(tolerance)) + 1;
            EXPECT_EQ(differencesAwayFromSilhouette(full.image, lod.image, radius), 0);
            // The cylinder's 2880 triangles are far finer than a pixel here: levels save most.
            EXPECT_LT(lod.stats.triangles, full.stats.triangles / 4);
        }
    }
}

}  // namespace
}  // namespace cavewall::render::gl
