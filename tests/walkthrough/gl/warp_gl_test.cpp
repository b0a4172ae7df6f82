// The geometry-warp transition (walls/gl/warp_pass.h): structure crossing a textured wall lines
// up with the texture, measured in pixels, and the guard near the wall plane.
//
// Scene "warp-stripes": two cells A (x < 0) and B (x > 0) split by the virtual wall A|B on x = 0
// (facing A). Structure: a grey floor and a blue stripe on it along x (z in [0.9, 1.3]) that
// crosses the wall plane. Content: a red stripe (z in [1.0, 1.2], x in [0.5, 6]) lying on the blue
// one behind the wall, so the texture of A|B shows red exactly centred on where the (unbaked)
// blue stripe is, as seen from the sampling point.
#include "tests/support/gl/gl_test_support.h"
#include "tests/walkthrough/gl/runtime_fixture.h"

#include "display/warp.h"
#include "scenes/generate.h"
#include "scenes/loader.h"
#include "scenes/primitives.h"
#include "walls/gl/baker.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace cavewall::testing {
namespace {

constexpr double kStripeZ = 1.1;  // centre line of both stripes

scenes::GeneratedScene stripesScene() {
    using scenes::Role;
    scenes::GeneratedScene g;
    scenes::Scene& s = g.scene;
    s.name = "warp-stripes";
    auto add = [&](scenes::Mesh mesh, std::string name, Role role) {
        s.meshes.push_back(std::move(mesh));
        scenes::addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::dmat4(1.0), name, role);
    };
    const glm::vec4 grey(0.5f, 0.5f, 0.5f, 1), blue(0.02f, 0.05f, 0.9f, 1), red(0.9f, 0.02f, 0.02f, 1);
    add(scenes::makeTiledQuad({-10, 0, 5}, {20, 0, 0}, {0, 0, -10}, 20, 10, grey, grey), "structure/floor",
        Role::Structure);
    add(scenes::makeTiledQuad({-10, 0.002f, 1.3f}, {20, 0, 0}, {0, 0, -0.4f}, 40, 1, blue, blue), "structure/stripe",
        Role::Structure);
    add(scenes::makeTiledQuad({0.5f, 0.004f, 1.2f}, {5.5f, 0, 0}, {0, 0, -0.2f}, 11, 1, red, red), "red stripe",
        Role::Content);
    scenes::SceneDescription& d = g.description;
    d.name = "warp-stripes";
    d.models.push_back({"warp-stripes.glb", glm::dmat4(1.0), 1.0, scenes::UpAxis::Y, false, {"structure/*"}});
    d.cells.push_back({"A", {{-10, 5}, {0, 5}, {0, -5}, {-10, -5}}, 0.0});
    d.cells.push_back({"B", {{0, 5}, {10, 5}, {10, -5}, {0, -5}}, 0.0});
    d.walls.push_back({"A|B", {0, 0, -5}, {0, 0, 5}, {0, 4, -5}, {0, 1}, scenes::WallKind::Virtual});
    return g;
}

// Generated, planned with `alphaDeg` and baked once per alpha (as runtime_fixture.cpp does).
const SmallPlant& stripes(double alphaDeg) {
    static std::map<double, std::unique_ptr<SmallPlant>> baked;
    std::unique_ptr<SmallPlant>& p = baked[alphaDeg];
    if (p) return *p;
    p = std::make_unique<SmallPlant>();
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    const std::filesystem::path out = std::filesystem::path(dir ? dir : "/tmp") / "runtime";
    const std::filesystem::path folder = out / "warp-stripes";
    if (!std::filesystem::exists(folder / "scene.json")) {
        scenes::GeneratedScene g = stripesScene();
        scenes::writeGenerated(g, folder);
    }
    p->sceneFile = folder / "scene.json";
    p->scene = scenes::loadSceneFile(p->sceneFile, &p->description);
    walls::PlanOptions plan;
    plan.alphaDeg = alphaDeg;
    plan.minZoneSize = 2.0;
    plan.pixelsPerDegree = 4.0;
    p->walls = walls::prepareWalls(p->scene, p->description, plan);
    walls::gl::BakeRequest request;
    request.scene = p->sceneFile;
    request.cache = out / "cache";
    const walls::gl::BakeResult result = walls::gl::bakeWalls(p->scene, p->description, p->walls, request);
    p->walls.folder = result.folder;
    p->walls.manifest = result.manifest;
    return *p;
}

bool isRed(const std::uint8_t* px) { return px[0] > 80 && px[0] > 2 * px[1] && px[0] > 2 * px[2]; }
bool isBlue(const std::uint8_t* px) { return px[2] > 80 && px[2] > 2 * px[0] && px[2] > 2 * px[1]; }

// Centre column of the pixels of `row` that pass `test` (NaN when none).
using PixelTest = bool (*)(const std::uint8_t*);
double centreOf(const scenes::Image& image, int row, PixelTest test, PixelTest orTest = nullptr) {
    int lo = image.width, hi = -1;
    for (int x = 0; x < image.width; ++x) {
        const std::uint8_t* px = &image.rgba[(std::size_t(row) * image.width + x) * 4];
        if (test(px) || (orTest && orTest(px))) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
    }
    return hi < 0 ? std::nan("") : 0.5 * (lo + hi);
}

class WarpTest : public GlTest {
protected:
    // Baked before GlTest::SetUp makes the test's context current (the bake uses its own).
    // alpha 30°: A|B is textured from 2.5 m off the wall; alpha 90°: from 0.5 m.
    const SmallPlant& stripes30 = stripes(30.0);
    const SmallPlant& stripes90 = stripes(90.0);
    const display::Display display = testDisplay(256);
    int frontScreen() const {
        for (int s = 0; s < static_cast<int>(display.screens().size()); ++s)
            if (display.screens()[s].name == "front") return s;
        return 0;
    }
    // The image row (from the top, fractional) of world point `p` on the front screen.
    double rowOf(glm::dvec3 eye, glm::dvec3 p) const {
        for (const display::ScreenView& v : display.views({glm::dvec3(0, 1.7, 0)}))
            if (v.screen == frontScreen()) {
                const glm::dvec4 c = walls::clipFromWorldOf(v, glm::inverse(cavePlacedAt(eye))) * glm::dvec4(p, 1.0);
                return (1.0 - c.y / c.w) * 0.5 * display.screens()[v.screen].resolution.y;
            }
        return std::nan("");
    }
    // An eye in cell A where A|B shows exactly one texture (weight 1, no geometry) and stands
    // `lateral` metres (along z) from its sampling point, 2 to 4.5 m from the wall.
    std::optional<std::pair<glm::dvec3, glm::dvec3>> eyeOffPoint(const SmallPlant& s, double lateral) const {
        walls::FrameSelector selector(s.walls.plan, s.walls.table, s.description);
        for (const walls::Texture& t : s.walls.plan.textures)
            for (double dz : {lateral, -lateral})
                for (double x = -2.0; x > -4.5; x -= 0.25) {
                    const glm::dvec3 eye(x, t.samplingPoint.y, t.samplingPoint.z + dz);
                    if (t.cell != 0 || std::abs(eye.z - kStripeZ) > 1.2) continue;
                    const walls::FrameSelection sel = selector.select(eye);
                    const bool one = sel.walls.size() == 1 && sel.walls[0].textures.size() == 1;
                    if (one && sel.walls[0].geometryWeight == 0.0 && sel.walls[0].textures[0].first == t.id)
                        return std::make_pair(eye, t.samplingPoint);
                }
        return std::nullopt;
    }
    walkthrough::FrameResult render(const SmallPlant& s, glm::dvec3 eye, walkthrough::Transition transition) {
        return render(s, s.walls, eye, transition);
    }
    walkthrough::FrameResult render(const SmallPlant& s, const walls::WallSetup& walls, glm::dvec3 eye,
                                    walkthrough::Transition transition) {
        walkthrough::gl::WalkthroughOptions options;
        options.synchronousPaging = true;
        options.transition = transition;
        walkthrough::gl::Walkthrough walkthrough(s.scene, s.description, display, *context, walls, options);
        walkthrough::FrameInput in;
        in.worldFromCave = cavePlacedAt(eye);
        in.readImages = true;
        return walkthrough.renderFrame(in);
    }
    const scenes::Image& front(const walkthrough::FrameResult& r) const {
        for (const scenes::ScreenImage& i : r.images)
            if (i.screen == frontScreen()) return i.pixels;
        return r.images.front().pixels;
    }
};

// Largest |centre of red - centre of (red or blue)| over the rows where the red stripe shows.
double textureMismatch(const scenes::Image& image, int firstRow, int lastRow, int& rowsMeasured) {
    double worst = 0.0;
    rowsMeasured = 0;
    for (int row = firstRow; row <= lastRow; ++row) {
        const double red = centreOf(image, row, isRed), stripe = centreOf(image, row, isRed, isBlue);
        if (std::isnan(red)) continue;
        worst = std::max(worst, std::abs(red - stripe));
        ++rowsMeasured;
    }
    return worst;
}

TEST_F(WarpTest, StructureCrossingTheWallLinesUpWithTheTextureWithinOnePixel) {
    const SmallPlant& s = stripes30;
    const auto found = eyeOffPoint(s, 0.5);
    ASSERT_TRUE(found) << "no eye 0.5 m beside a sampling point with one texture on A|B";
    const auto [eye, samplingPoint] = *found;
    SCOPED_TRACE("eye " + std::to_string(eye.x) + " " + std::to_string(eye.z));
    const walkthrough::FrameResult warped = render(s, eye, walkthrough::Transition::Warp);
    const walkthrough::FrameResult blended = render(s, eye, walkthrough::Transition::Blend);
    EXPECT_EQ(warped.warpFallbacks, 0);
    std::cout << "eye " << eye.x << " " << eye.y << " " << eye.z << ", sampling point " << samplingPoint.x << " "
              << samplingPoint.y << " " << samplingPoint.z << "\n";
    ASSERT_EQ(warped.walls.size(), 1u);
    ASSERT_EQ(warped.walls[0].textures.size(), 1u);
    // Rows of the red stripe (x from 0.5 to 6 m), one pixel inside each end against filtering.
    const int first = static_cast<int>(std::ceil(rowOf(eye, {6.0, 0.0, kStripeZ}))) + 1;
    const int last = static_cast<int>(std::floor(rowOf(eye, {0.5, 0.0, kStripeZ}))) - 1;
    ASSERT_LT(first + 5, last);
    int rowsWarped = 0, rowsBlended = 0;
    const double warpedPx = textureMismatch(front(warped), first, last, rowsWarped);
    const double blendedPx = textureMismatch(front(blended), first, last, rowsBlended);
    std::cout << "texture vs structure, max over rows: warp " << warpedPx << " px (" << rowsWarped << " rows), blend "
              << blendedPx << " px (" << rowsBlended << " rows)\n";
    EXPECT_GE(rowsWarped, (last - first) / 2);
    // The red stripe lies centred on the blue one in the texture's view; the warp draws the blue
    // one as that view sees it, so the centres agree up to rasterisation (half a pixel each).
    EXPECT_LE(warpedPx, 1.0);
    // Unwarped, the blue stripe is where the eye sees it and the red one where the sampling point
    // did: a 0.5 m sideways step shifts them apart by several pixels (the test can fail).
    EXPECT_GT(blendedPx, 2.0);
    EXPECT_GT(blendedPx, 3.0 * warpedPx);

    // C0 at the wall's bottom edge: the blue stripe's centre just below the edge (unwarped, in
    // front of the plane) and just above it (warped) extrapolate to the same column.
    const scenes::Image& image = front(warped);
    const double edge = rowOf(eye, {0.0, 0.0, kStripeZ});
    const int below = static_cast<int>(std::ceil(edge)) + 1, above = static_cast<int>(std::floor(edge)) - 1;
    const double b0 = centreOf(image, below, isBlue), b1 = centreOf(image, below + 2, isBlue);
    const double a0 = centreOf(image, above, isBlue), a1 = centreOf(image, above - 2, isBlue);
    ASSERT_FALSE(std::isnan(b0) || std::isnan(b1) || std::isnan(a0) || std::isnan(a1));
    const double fromBelow = b0 + (b0 - b1) / 2.0 * (below - edge);
    const double fromAbove = a0 + (a0 - a1) / 2.0 * (edge - above);
    std::cout << "blue stripe at the wall edge: from below " << fromBelow << ", from above " << fromAbove << "\n";
    EXPECT_LE(std::abs(fromBelow - fromAbove), 1.0);
}

TEST_F(WarpTest, AnEyeAtTheWallPlaneFallsBackToGeometryWithoutNaNOrBlackPixels) {
    // Even at alpha 90° the plan keeps a 0.5 m geometry zone in front of A|B. Without it (every
    // side's geometry zone removed), the texture zone reaches the wall plane, as for a wall seen
    // edge-on from afar, and only the guard stands between the eye and a singular warp.
    walls::WallSetup walls = stripes90.walls;
    for (walls::WallSide& side : walls.plan.sides) side.hasGeometry = false;
    struct Case {
        const char* name;
        double distance;  // eye in front of the wall plane, metres
        walkthrough::Transition transition;
        int fallbacks;
    };
    // The warp's condition grows like 3 m / distance (display/warp.h): about 3e4 at 0.1 mm, over
    // kMaxWarpCondition = 1e4; about 60 at 5 cm, well under it. Blend never warps.
    const Case cases[] = {{"warp at 0.1 mm", 1e-4, walkthrough::Transition::Warp, 1},
                          {"warp at 5 cm", 0.05, walkthrough::Transition::Warp, 0},
                          {"blend at 0.1 mm", 1e-4, walkthrough::Transition::Blend, 0}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const walkthrough::FrameResult r = render(stripes90, walls, {-c.distance, 1.6, kStripeZ}, c.transition);
        EXPECT_EQ(r.warpFallbacks, c.fallbacks);
        ASSERT_EQ(r.walls.size(), 1u);
        // The fallback draws the cell behind as geometry instead of the texture.
        EXPECT_EQ(r.walls[0].textures.empty(), c.fallbacks > 0);
        EXPECT_EQ(r.walls[0].geometryWeight, c.fallbacks > 0 ? 1.0 : 0.0);
        EXPECT_EQ(r.walls[0].fallback, c.fallbacks > 0);
        // No NaN and nothing black anywhere: every pixel is at least as bright as the clear
        // colour (linear 0.02 is sRGB level 39).
        for (const scenes::ScreenImage& image : r.images) {
            int dark = 0;
            for (std::size_t i = 0; i < image.pixels.rgba.size(); i += 4)
                dark += std::max({image.pixels.rgba[i], image.pixels.rgba[i + 1], image.pixels.rgba[i + 2]}) < 30;
            EXPECT_EQ(dark, 0) << image.stem;
        }
        // With the cell behind drawn as geometry, its red stripe shows on the front screen. (The
        // texture cases see only the few centimetres of wall in front of the eye: no stripe.)
        int redRows = 0;
        const scenes::Image& f = front(r);
        for (int row = 0; row < f.height; ++row) redRows += std::isnan(centreOf(f, row, isRed)) ? 0 : 1;
        if (c.fallbacks > 0) {
            EXPECT_GT(redRows, 5);
        }
    }
}

// Mean column of the red pixels (NaN when none).
double redCentroid(const scenes::Image& image) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (isRed(&image.rgba[(std::size_t(y) * image.width + x) * 4])) {
                sum += x;
                ++count;
            }
    return count > 0 ? sum / count : std::nan("");
}

TEST_F(WarpTest, WarpMorphMovesTheViewpointFromTheSamplingPointToTheEyeAndEndsExact) {
    // Alpha 30°: A|B is one texture (sampling point (-2.78, 1.6, 2)) at x = -3 and geometry from
    // x = -2 on. Walking from x = -3 to x = -1.5 switches it to geometry at t = 0.1 s.
    const SmallPlant& s = stripes30;
    const glm::dvec3 textured(-3.0, 1.6, 1.5), geometry(-1.5, 1.6, 1.5);
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    options.transition = walkthrough::Transition::Warp;
    options.morphSeconds = 0.5;
    walkthrough::gl::Walkthrough walkthrough(s.scene, s.description, display, *context, s.walls, options);
    auto frame = [&](double t, glm::dvec3 eye) {
        walkthrough::FrameInput in;
        in.time = t;
        in.worldFromCave = cavePlacedAt(eye);
        in.readImages = true;
        return walkthrough.renderFrame(in);
    };
    const walkthrough::FrameResult before = frame(0.0, textured);
    ASSERT_EQ(before.walls.size(), 1u);
    ASSERT_EQ(before.walls[0].textures.size(), 1u);
    const walkthrough::FrameResult start = frame(0.1, geometry), middle = frame(0.35, geometry),
                                   end = frame(0.7, geometry);
    for (const walkthrough::FrameResult* r : {&start, &middle, &end}) {
        EXPECT_EQ(r->warpFallbacks, 0);
        EXPECT_TRUE(r->walls[0].textures.empty());
        EXPECT_EQ(r->walls[0].geometryWeight, 1.0);
    }
    // After morphSeconds the wall is plain geometry: exactly what Blend draws in a geometry zone.
    const walkthrough::FrameResult reference = render(s, geometry, walkthrough::Transition::Blend);
    EXPECT_EQ(front(end).rgba, front(reference).rgba);
    // The red stripe (behind the wall) moves from where the sampling point sees it to where the
    // eye does, and is in between halfway (s = 0.5).
    const double c0 = redCentroid(front(start)), c1 = redCentroid(front(middle)), c2 = redCentroid(front(end));
    std::cout << "red stripe centroid column: start " << c0 << ", middle " << c1 << ", end " << c2 << "\n";
    ASSERT_FALSE(std::isnan(c0) || std::isnan(c1) || std::isnan(c2));
    EXPECT_GT(std::abs(c2 - c0), 4.0);
    EXPECT_GT(std::min(c1 - std::min(c0, c2), std::max(c0, c2) - c1), 1.0);

    // Back into the texture zone: a morph from the eye to the sampling point, then the texture.
    const walkthrough::FrameResult back = frame(1.0, textured), after = frame(1.6, textured);
    EXPECT_TRUE(back.walls[0].textures.empty());
    EXPECT_EQ(after.walls[0].textures, before.walls[0].textures);
}

}  // namespace
}  // namespace cavewall::testing
