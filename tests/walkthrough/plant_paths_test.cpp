// No texture drawn over alpha, without GL: on the generated plant (alpha 10°, zones of at least
// 1 m, as `cavewall plan` and the demo plan it), the frame planner draws no texture over alpha
// along the scene's walk path nor along its wall path, which hugs the virtual walls and crosses
// their geometry zones and blend strips. Every texture is resident, so nothing falls back; the
// errors are the exact ones the frame planner reports (walkthrough/frame_planner.h, step 5).
#include "config/display_config.h"
#include "scenes/generate.h"
#include "walkthrough/frame_planner.h"
#include "walls/wall_setup.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::walkthrough {
namespace {

using namespace walls;

struct Walked {
    int frames = 0, overAlpha = 0, beyondTextured = 0;
    double maxErrorDeg = 0.0, maxBeyondErrorDeg = 0.0;
};

class PlantPaths : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        generated = new scenes::GeneratedScene(scenes::generatePlant({1, 20000}));
        PlanOptions options;
        options.alphaDeg = 10.0;
        options.minZoneSize = 1.0;
        setup = new WallSetup(prepareWalls(generated->scene, generated->description, options));
    }
    static void TearDownTestSuite() {
        delete setup;
        delete generated;
    }

    // Walks `path` in steps of 5 cm; the head moves through the whole head height range (the
    // planner's promise covers 1.2-2 m) and turns once every 10 m, so every wall comes into
    // view of cave4's screens.
    Walked walk(const std::vector<glm::dvec3>& path) const {
        config::DisplayConfig cave4 = config::loadDisplayConfig("cave4");
        cave4.stereo = config::StereoMode::Mono;  // one view per screen: the zones are the same per eye
        const display::Display display(cave4);
        FramePlanner planner(generated->scene, generated->description, display, setup, Transition::Blend, 0.5);
        Walked w;
        double travelled = 0.0;
        for (std::size_t i = 0; i + 1 < path.size(); ++i) {
            const double length = glm::length(path[i + 1] - path[i]);
            for (double s = 0.0; s < length; s += 0.05, travelled += 0.05) {
                const glm::dvec3 p = glm::mix(path[i], path[i + 1], s / length);
                FrameInput in;
                in.frame = w.frames;
                in.time = w.frames / 60.0;
                in.head.position = {0.0, 1.6 + 0.4 * std::sin(travelled * 1.3), 0.0};
                in.worldFromCave = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(p.x, 0.0, p.z)),
                                               travelled * 2.0 * M_PI / 10.0, glm::dvec3(0, 1, 0));
                planner.requests(in, display.views(in.head));
                const FramePlan plan = planner.plan([](int) { return true; });
                ++w.frames;
                w.overAlpha += plan.texturesOverAlpha;
                w.maxErrorDeg = std::max(w.maxErrorDeg, plan.maxErrorDeg);
                for (const WallState& s : plan.walls)
                    if (s.beyond && !s.textures.empty()) {
                        ++w.beyondTextured;
                        w.maxBeyondErrorDeg = std::max(w.maxBeyondErrorDeg, s.errorDeg);
                    }
            }
        }
        return w;
    }
    static void report(const char* name, const Walked& w) {
        std::printf("%s: %d frames, max error %.3f deg (beyond walls %.3f deg over %d textured rows), %d over alpha\n",
                    name, w.frames, w.maxErrorDeg, w.maxBeyondErrorDeg, w.beyondTextured, w.overAlpha);
    }

    static scenes::GeneratedScene* generated;
    static WallSetup* setup;
};

scenes::GeneratedScene* PlantPaths::generated = nullptr;
WallSetup* PlantPaths::setup = nullptr;

// Near a cell's corner the far wall of a neighbour can itself be drawn as geometry (its plane
// runs along the eye's cell); the cell behind it then has far walls of its own, planned at the
// second level.
TEST_F(PlantPaths, ThePlantHasBothLevelsOfBeyondSides) {
    int first = 0, second = 0;
    for (const BeyondSide& b : setup->plan.beyond) (b.parent < 0 ? first : second) += 1;
    EXPECT_GT(first, 0);
    EXPECT_GT(second, 0);
}

TEST_F(PlantPaths, NoTextureOverAlphaAlongTheWalkPath) {
    const Walked w = walk(generated->description.walkPath);
    report("walk path", w);
    EXPECT_GT(w.frames, 3000);       // 188 m in 5 cm steps
    EXPECT_GT(w.beyondTextured, 0);  // the walk does draw walls beyond a neighbour
    EXPECT_EQ(w.overAlpha, 0);
    EXPECT_LE(w.maxErrorDeg, 10.0 + 1e-6);
}

TEST_F(PlantPaths, NoTextureOverAlphaAlongTheWallPath) {
    const Walked w = walk(generated->description.wallPath);
    report("wall path", w);
    EXPECT_GT(w.frames, 6000);  // about 340 m in 5 cm steps
    EXPECT_GT(w.beyondTextured, 1000);
    EXPECT_EQ(w.overAlpha, 0);
    EXPECT_LE(w.maxErrorDeg, 10.0 + 1e-6);
}

}  // namespace
}  // namespace cavewall::walkthrough
