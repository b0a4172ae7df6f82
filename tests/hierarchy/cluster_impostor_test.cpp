// Maciel & Shirley's (1995) cluster impostors (hierarchy/cluster_impostor.h) and one frame's plan
// (hierarchy/cluster_frame.h), without GL.
#include "hierarchy/cluster_diagram.h"
#include "hierarchy/cluster_frame.h"
#include "hierarchy/cluster_impostor.h"
#include "tests/render/render_test_scenes.h"

#include "display/display.h"
#include "config/display_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace cavewall::hierarchy {
namespace {

// cave4 drawn mono, one view per screen from the head (the preset is stereo).
config::DisplayConfig monoCave4() {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    c.stereo = config::StereoMode::Mono;
    return c;
}

using render::testing::box;

TEST(ClusterImpostor, FacesAreSeenFromOutsideAndCoverTheBox) {
    const scenes::Bounds b = box({-1, 0, -2}, {3, 1, 2});
    for (int f = 0; f < kBoxFaces; ++f) {
        SCOPED_TRACE(f);
        const display::ScreenQuad q = boxFace(b, f);
        const display::ScreenBasis basis = display::screenBasis(q);
        // The projection's front side is right x up; it must be the outward normal.
        EXPECT_NEAR(glm::dot(basis.normal, faceNormal(f)), 1.0, 1e-12);
        // The quad's four corners are corners of the box.
        const glm::dvec3 upperRight = q.lowerRight + q.upperLeft - q.lowerLeft;
        for (glm::dvec3 p : {q.lowerLeft, q.lowerRight, q.upperLeft, upperRight})
            for (int a = 0; a < 3; ++a) EXPECT_TRUE(p[a] == b.min[a] || p[a] == b.max[a]) << a;
    }
}

TEST(ClusterImpostor, SamplingEyesLieInTheirOwnRegionOutsideTheFace) {
    const scenes::Bounds b = box({0, 0, 0}, {2, 1, 4});
    for (int f = 0; f < kBoxFaces; ++f)
        for (int r = 0; r < kFaceRegions; ++r) {
            SCOPED_TRACE(::testing::Message() << "face " << f << " region " << r);
            const glm::dvec3 eye = samplingEye(b, f, r);
            EXPECT_TRUE(faceTowards(b, f, eye));
            EXPECT_EQ(viewRegion(b, f, eye), r);
        }
}

TEST(ClusterImpostor, FlatBoundsGetAThicknessSoNoFaceIsDegenerate) {
    const scenes::Bounds b = impostorBox(box({0, 0, 0}, {10, 0, 4}));
    // 1 % of the largest extent (10 m).
    EXPECT_NEAR(b.size().y, 0.1, 1e-12);
    EXPECT_NEAR(b.centre().y, 0.0, 1e-12);
    EXPECT_EQ(faceResolution(b, 0, 64), glm::ivec2(64, 4));  // 4 m x 0.1 m: the thin side at least 4
}

TEST(ClusterImpostor, AverageColourIsLinearAndAlphaWeighted) {
    scenes::Image image{"t", 2, 2, {}};
    // One opaque texel of sRGB 188 (linear ~0.5), one half-covered white as the render target
    // holds it, premultiplied (linear 0.502: sRGB 188 too), two empty.
    image.rgba = {188, 188, 188, 255, 188, 188, 188, 128, 0, 0, 0, 0, 7, 7, 7, 0};
    const FaceAverage a = faceAverage(image);
    // Coverage (1 + 128/255) / 4; colour (0.5029 + 0.5029) / 1.502: the half-covered texel is
    // white (0.5029 / 0.502), not multiplied by its alpha again.
    EXPECT_NEAR(a.coverage, (1.0 + 128.0 / 255.0) / 4.0, 1e-6);
    const double lin188 = std::pow((188.0 / 255.0 + 0.055) / 1.055, 2.4);
    const double w = 128.0 / 255.0;
    EXPECT_NEAR(a.linearColour.r, (lin188 + lin188) / (1.0 + w), 1e-5);
    // An average quad of a quarter coverage is half as wide and tall, same centre.
    const display::ScreenQuad q = averageFaceQuad({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, 0.25f);
    EXPECT_NEAR(glm::length(q.lowerRight - q.lowerLeft), 1.0, 1e-12);
    EXPECT_NEAR(q.lowerLeft.x, 0.5, 1e-12);
}

TEST(ClusterImpostor, AccuracyDirectionsAreUnitAndTheNearestIsPicked) {
    const auto d = accuracyDirections();
    for (const glm::dvec3& v : d) EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
    const scenes::Bounds b = box({-1, -1, -1}, {1, 1, 1});
    EXPECT_EQ(nearestAccuracyDirection(b, {0, 10, 0}), 4);   // straight above
    EXPECT_EQ(nearestAccuracyDirection(b, {-10, 1, 0}), 1);  // -x, slightly above
    EXPECT_DOUBLE_EQ(accuracyFromFlip(0.2), 0.8);
}

// Two objects side by side under one cluster, seen from cave4's default head.
ClusterModel twoObjects(double x) {
    ClusterModel m;
    m.tree =
        buildClusterTree({box({x, 1, -5}, {x + 0.5, 1.5, -4.5}), box({x + 1, 1, -5}, {x + 1.5, 1.5, -4.5})}, {1, 1, 1});
    m.objectTriangles = {1000, 3000};
    m.accuracy.assign(m.tree.nodes.size(), {});
    m.accuracy[m.tree.root].textured.fill(0.9);
    m.accuracy[m.tree.root].average.fill(0.5);
    m.hasImpostors.assign(m.tree.nodes.size(), false);
    m.hasImpostors[m.tree.root] = true;
    m.costs = {1e-4, 0.01, 0.05, 0.04};
    return m;
}

TEST(ClusterFrame, DrawsTheClusterAsATexturedBoxUnderASmallBudgetAndItsObjectsUnderALargeOne) {
    const display::Display display(monoCave4());
    const auto views = display.views(display.defaultHead());
    const ClusterModel m = twoObjects(-0.75);
    ASSERT_EQ(m.tree.root, 2);
    const glm::dvec3 eye = display.defaultHead().position;
    // Objects: 0.01 + 1000 * 1e-4 = 0.11 ms and 0.31 ms; the boxes 0.05 and 0.04 ms. Textured
    // has accuracy per cost 18, average 12.5: textured is the initial representation.
    const ClusterFramePlan small = planClusterFrame(m, views, glm::dmat4(1.0), eye, 0.3, nullptr);
    EXPECT_TRUE(small.objects.empty());
    ASSERT_EQ(small.boxes.size(), 1u);
    EXPECT_EQ(small.boxes[0].rep, ClusterRep::Textured);
    EXPECT_EQ(small.textured, 1);
    EXPECT_DOUBLE_EQ(small.predictedMs, 0.05);
    const ClusterFramePlan large = planClusterFrame(m, views, glm::dmat4(1.0), eye, 0.42, nullptr);
    EXPECT_THAT(large.objects, ::testing::ElementsAre(0, 1));
    EXPECT_TRUE(large.boxes.empty());
    EXPECT_NEAR(large.predictedMs, 0.42, 1e-12);
    EXPECT_LE(large.predictedMs, large.budgetMs + 1e-12);
}

TEST(ClusterFrame, FullDetailIsTheMostAnySelectionCostsAndTheCheapestIsTheRootsBox) {
    const display::Display display(monoCave4());
    const auto views = display.views(display.defaultHead());
    const ClusterModel m = twoObjects(-0.75);
    // 0.01 + 1000 * 1e-4 and 0.01 + 3000 * 1e-4.
    EXPECT_NEAR(fullDetailCostMs(m), 0.42, 1e-12);
    const glm::dvec3 eye = display.defaultHead().position;
    for (double budget : {0.0, 0.05, 0.3, 0.42, 5.0}) {
        SCOPED_TRACE(budget);
        const ClusterFramePlan plan = planClusterFrame(m, views, glm::dmat4(1.0), eye, budget, nullptr);
        // The floor of every budget: the root's textured box (its initial representation).
        EXPECT_DOUBLE_EQ(plan.cheapestMs, 0.05);
        EXPECT_DOUBLE_EQ(plan.selectedMs, plan.predictedMs);  // no fades applied
        EXPECT_LE(plan.selectedMs, std::max(budget, plan.cheapestMs) + 1e-12);
        EXPECT_LE(plan.selectedMs, fullDetailCostMs(m) + 1e-12);
    }
}

TEST(ClusterFrame, ViewShareIsTheClippedRectangleOfTheProjectedCorners) {
    // A 2 m x 2 m screen 1 m in front of the eye (-Z): a 90 degree symmetric frustum, so a point
    // at depth d projects to x / d in NDC.
    const display::ScreenQuad screen{{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}};
    const glm::dmat4 clip = display::offAxisFrustum(screen, glm::dvec3(0.0), {0.05, 1000.0}).clipFromFrame();
    // x in [0, 10] at depths 2 to 3 projects to [0, 5]: clipped to [0, 1]; y covers [-1, 1]:
    // the right half of the view.
    EXPECT_NEAR(viewShare(box({0, -10, -3}, {10, 10, -2}), clip), 0.5, 1e-12);
    // x in [-0.5, 0.5] at depth 1 to 2: NDC [-0.5, 0.5] (the nearer depth), y [-1, 1] clipped:
    // a quarter of the width doubled in height -> 0.5 x 1.
    EXPECT_NEAR(viewShare(box({-0.5, -5, -2}, {0.5, 5, -1}), clip), 0.5, 1e-12);
    EXPECT_EQ(viewShare(box({50, 0, -3}, {51, 1, -2}), clip), 0.0);  // beside the view
    EXPECT_EQ(viewShare(box({-1, -1, 2}, {1, 1, 3}), clip), 0.0);    // behind the eye
    EXPECT_EQ(viewShare(box({-1, -1, -1}, {1, 1, 1}), clip), 1.0);   // around the eye
    EXPECT_EQ(viewShare(scenes::Bounds{}, clip), 0.0);
}

TEST(ClusterFrame, BoxCostsAreSolvedFromAllBoxesAndTheRootAlone) {
    // 40 boxes covering 3 views in all took 40 x 0.1 + 3 x 8 = 28 ms; the root alone, covering
    // 0.75 of the view, 0.1 + 0.75 x 8 = 6.1 ms: fixed 0.1 ms, fill 8 ms per whole view.
    const BoxCost c = solveBoxCost(40.0, 3.0, 28.0, 0.75, 6.1);
    EXPECT_NEAR(c.fixedMs, 0.1, 1e-9);
    EXPECT_NEAR(c.viewMs, 8.0, 1e-9);
    // Draws that do not tell the two apart (a negative solution): no fill, the mean per box.
    const BoxCost flat = solveBoxCost(40.0, 3.0, 28.0, 0.75, 0.2);
    EXPECT_NEAR(flat.fixedMs, 28.0 / 40.0, 1e-12);
    EXPECT_EQ(flat.viewMs, 0.0);
    EXPECT_EQ(solveBoxCost(0.0, 0.0, 0.0, 0.0, 0.0).fixedMs, 1e-6);  // no boxes: the least fixed part
    // The prediction adds the fill of the views' shares.
    ClusterCosts costs;
    costs.texturedBoxMs = 0.1;
    costs.texturedViewMs = 8.0;
    costs.averageBoxMs = 0.05;
    costs.averageViewMs = 2.0;
    EXPECT_NEAR(boxCostMs(costs, ClusterRep::Textured, 2.0), 16.1, 1e-12);
    EXPECT_NEAR(boxCostMs(costs, ClusterRep::Average, 0.5), 1.05, 1e-12);
}

// Two objects under one cluster, at x0 and x1 (0.5 m cubes, 4.5 m to 5 m in front of cave4's
// default head), costs as twoObjects' plus a fill per whole view.
ClusterModel pairAt(double x0, double x1) {
    ClusterModel m = twoObjects(-0.75);
    m.tree =
        buildClusterTree({box({x0, 1, -5}, {x0 + 0.5, 1.5, -4.5}), box({x1, 1, -5}, {x1 + 0.5, 1.5, -4.5})}, {1, 1, 1});
    m.costs.texturedViewMs = 8.0;
    m.costs.averageViewMs = 2.0;
    return m;
}

TEST(ClusterFrame, ABoxCostsItsFillAndTheSelectionPaysIt) {
    const display::Display display(monoCave4());
    const auto views = display.views(display.defaultHead());
    const glm::dvec3 head = display.defaultHead().position;
    auto rootBox = [&](const ClusterModel& m, glm::dvec3 eye) {
        const ClusterFramePlan p = planClusterFrame(m, views, glm::dmat4(1.0), eye, 0.0, nullptr);
        // A plan at a budget of 0 draws the root's box (the one with the most accuracy per
        // cost) at this frame's cost, fill included.
        EXPECT_EQ(p.boxes.size(), 1u);
        if (p.boxes.empty()) return std::array<double, 2>{};
        const auto& box = p.boxMs.at(static_cast<std::size_t>(m.tree.root));
        EXPECT_NEAR(p.selectedMs, box[p.boxes[0].rep == ClusterRep::Average ? 1 : 0], 1e-12);
        EXPECT_NEAR(p.cheapestMs, p.selectedMs, 1e-12);
        return box;
    };
    // A wider cluster at the same distance covers more of the front view: more fill, the same
    // fixed part (0.05 ms textured, 0.04 ms average).
    const auto narrow = rootBox(pairAt(-0.75, 0.25), head), wide = rootBox(pairAt(-1.5, 1.0), head);
    EXPECT_GT(wide[0], narrow[0]);
    EXPECT_GT(narrow[0], 0.05);
    EXPECT_GT(narrow[1], 0.04);
    EXPECT_LT(narrow[0], 0.05 + 8.0);  // far less than one whole view
    // A cluster around the eye may fill every view: its fill is one whole view per view. Its
    // box shows nothing from inside and its objects cost less (0.42 ms), so even a budget of
    // 0 draws them instead.
    ClusterModel around = pairAt(-0.75, 0.25);
    around.tree = buildClusterTree({box({-5, 0, -4}, {-4.5, 0.5, -3.5}), box({4.5, 2.5, 3.5}, {5, 3, 4})}, {1, 1, 1});
    const ClusterFramePlan p = planClusterFrame(around, views, glm::dmat4(1.0), head, 0.0, nullptr);
    const auto& inside = p.boxMs.at(static_cast<std::size_t>(around.tree.root));
    EXPECT_NEAR(inside[0], 0.05 + 8.0 * static_cast<double>(views.size()), 1e-9);
    EXPECT_NEAR(inside[1], 0.04 + 2.0 * static_cast<double>(views.size()), 1e-9);
    EXPECT_TRUE(p.boxes.empty());
    EXPECT_THAT(p.objects, ::testing::ElementsAre(0, 1));
    EXPECT_NEAR(p.cheapestMs, 0.42, 1e-12);
}

TEST(ClusterFrame, ABackAndForthPathSwitchesAtMostOnce) {
    // The eye walks back and forth along x in front of the cluster while the budget swings
    // between fitting its objects (0.42 ms) and not (0.3 ms) every other frame: the wish to
    // refine never lasts more than one frame, so the coherence counter (3 frames) keeps the box.
    // Then the budget stays large: the cluster is refined once, after 3 frames, and stays.
    const display::Display display(monoCave4());
    const ClusterModel m = twoObjects(-0.75);
    ClusterCoherence coherence(3);
    int switches = 0;
    bool refined = false;
    for (int frame = 0; frame < 40; ++frame) {
        const double x = 0.5 * std::sin(frame * 0.7);
        const display::HeadPose head{{x, 1.7, 0.0}, {1, 0, 0, 0}};
        const double budget = frame < 20 ? (frame % 2 == 0 ? 0.42 : 0.3) : 0.42;
        const ClusterFramePlan plan =
            planClusterFrame(m, display.views(head), glm::dmat4(1.0), head.position, budget, &coherence);
        const bool nowRefined = plan.boxes.empty();
        if (frame > 0 && nowRefined != refined) ++switches;
        refined = nowRefined;
        EXPECT_LE(plan.predictedMs, budget + 1e-12) << frame;
    }
    EXPECT_EQ(switches, 1);
    EXPECT_TRUE(refined);
}

TEST(ClusterFrame, NothingOutsideEveryFrustumIsDrawn) {
    const display::Display display(monoCave4());
    // Above the head: cave4 has no ceiling, and its walls' frusta end below 2.6 m within 1 m of
    // the centre (top edges at 3 m, 1.5 m away, from an eye at 1.7 m).
    ClusterModel m = twoObjects(-0.75);
    m.tree = buildClusterTree({box({-1, 8, -1}, {-0.5, 9, 1}), box({0.5, 8, -1}, {1, 9, 1})}, {1, 1, 1});
    const ClusterFramePlan plan =
        planClusterFrame(m, display.views(display.defaultHead()), glm::dmat4(1.0), {0, 1.7, 0}, 10.0, nullptr);
    EXPECT_TRUE(plan.objects.empty());
    EXPECT_TRUE(plan.boxes.empty());
}

TEST(ClusterDiagram, FillsWhatTheFrameDrewByKind) {
    const ClusterModel m = twoObjects(0.0);  // objects x in [0, 0.5] and [1, 1.5]
    auto pixel = [](const scenes::Image& image, double fx, double fz) {
        const int x = static_cast<int>(fx * (image.width - 1)), y = static_cast<int>(fz * (image.height - 1));
        const std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
        return std::vector<int>{p[0], p[1], p[2]};
    };
    ClusterFramePlan plan;
    plan.boxes = {{m.tree.root, ClusterRep::Textured}};
    scenes::Image image = clusterDiagram(m, plan, {10, 0, 10}, 200);
    // 200 px for 1.5 m (8 px margins): a 1.5 m x 0.5 m footprint is 184 x 61 + 16 px.
    EXPECT_EQ(image.height, 16 + static_cast<int>(std::ceil(0.5 * 184.0 / 1.5)));
    const std::vector<int> blue(kDiagramTextured, kDiagramTextured + 3), orange(kDiagramAverage, kDiagramAverage + 3),
        green(kDiagramObject, kDiagramObject + 3);
    EXPECT_EQ(pixel(image, 0.5, 0.5), blue);
    plan.boxes[0].rep = ClusterRep::Average;
    EXPECT_EQ(pixel(clusterDiagram(m, plan, {10, 0, 10}, 200), 0.5, 0.5), orange);
    plan.boxes.clear();
    plan.objects = {0, 1};
    image = clusterDiagram(m, plan, {10, 0, 10}, 200);
    EXPECT_EQ(pixel(image, 0.2, 0.5), green);                              // inside object 0
    EXPECT_EQ(pixel(image, 0.5, 0.5), (std::vector<int>{255, 255, 255}));  // the gap between them
}

}  // namespace
}  // namespace cavewall::hierarchy
