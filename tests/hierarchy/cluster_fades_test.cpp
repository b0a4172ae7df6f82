// Cross-faded transitions between cluster representations (hierarchy/cluster_fades.h), without GL:
// plans are written by hand, frame after frame, as the selection would return them.
#include "hierarchy/cluster_fades.h"
#include "tests/render/render_test_scenes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::hierarchy {
namespace {

using render::testing::box;

// Four objects 1 m wide along x at x = 0, 2, 4, 6; clusters 4 = {0, 1}, 5 = {2, 3}; root 6.
// Objects cost 0.01 + triangles * 1e-4 ms (100 triangles: 0.02 ms); boxes 0.05 / 0.04 ms.
ClusterModel fourObjects() {
    ClusterModel m;
    for (int i = 0; i < 4; ++i) {
        ClusterNode leaf;
        leaf.bounds = box({2.0 * i, 0, 0}, {2.0 * i + 1, 1, 1});
        leaf.objects = {i};
        leaf.object = i;
        m.tree.nodes.push_back(leaf);
        m.objectTriangles.push_back(100);
    }
    auto cluster = [&](std::vector<int> children, int level) {
        ClusterNode c;
        c.children = children;
        c.level = level;
        for (int child : children) {
            c.bounds.add(m.tree.nodes[child].bounds.min);
            c.bounds.add(m.tree.nodes[child].bounds.max);
            for (int o : m.tree.nodes[child].objects) c.objects.push_back(o);
        }
        m.tree.nodes.push_back(c);
    };
    cluster({0, 1}, 1);
    cluster({2, 3}, 1);
    cluster({4, 5}, 2);
    m.tree.root = 6;
    m.accuracy.resize(7);
    m.hasImpostors = {false, false, false, false, true, true, true};
    m.costs = {1e-4, 0.01, 0.05, 0.04};
    return m;
}

ClusterFramePlan plan(std::vector<int> objects, std::vector<ClusterBoxDraw> boxes, double ms = 1.0) {
    ClusterFramePlan p;
    p.objects = std::move(objects);
    p.boxes = std::move(boxes);
    p.predictedMs = ms;
    return p;
}

const glm::dvec3 kEye{3.5, 0.5, 10.0};

TEST(ClusterFades, ARefinedBoxFadesOutOverItsChildrenAndIsGoneAfterTheFade) {
    const ClusterModel m = fourObjects();
    ClusterFades fades(4);
    ClusterFramePlan p = plan({2, 3}, {{4, ClusterRep::Textured}});
    fades.apply(m, kEye, p);  // the first frame: nothing to fade from
    EXPECT_EQ(p.boxes.size(), 1u);
    EXPECT_EQ(p.fades, 0);
    // Cluster 4 refined: its box stays, fading out over objects 0 and 1, 1 - k/4 at k = 1..3.
    for (int k = 1; k <= 4; ++k) {
        SCOPED_TRACE(k);
        p = plan({0, 1, 2, 3}, {});
        fades.apply(m, kEye, p);
        if (k == 4) {
            EXPECT_TRUE(p.boxes.empty());
            EXPECT_EQ(p.fades, 0);
            EXPECT_DOUBLE_EQ(p.predictedMs, 1.0);
            continue;
        }
        ASSERT_EQ(p.boxes.size(), 1u);
        EXPECT_EQ(p.boxes[0].node, 4);
        EXPECT_EQ(p.boxes[0].rep, ClusterRep::Textured);
        EXPECT_FLOAT_EQ(p.boxes[0].weight, 1.0f - k / 4.0f);
        EXPECT_EQ(p.fades, 1);
        EXPECT_DOUBLE_EQ(p.predictedMs, 1.0 + 0.05);  // the box's cost on top
        EXPECT_THAT(p.objects, ::testing::ElementsAre(0, 1, 2, 3));
    }
}

TEST(ClusterFades, ACoarsenedBoxFadesInOverWhatWasDrawnBelowIt) {
    const ClusterModel m = fourObjects();
    ClusterFades fades(4);
    ClusterFramePlan p = plan({0, 1}, {{5, ClusterRep::Average}});
    fades.apply(m, kEye, p);
    // Everything coarsened into the root: objects 0, 1 and box 5 stay (opaque, "ghosts") and
    // the root's box fades in over them, drawn after box 5, which lies below it.
    p = plan({}, {{6, ClusterRep::Textured}});
    fades.apply(m, kEye, p);
    EXPECT_THAT(p.objects, ::testing::ElementsAre(0, 1));
    EXPECT_EQ(p.ghostObjects, 2);
    ASSERT_EQ(p.boxes.size(), 2u);
    EXPECT_EQ(p.boxes[0].node, 5);
    EXPECT_EQ(p.boxes[0].rep, ClusterRep::Average);
    EXPECT_FLOAT_EQ(p.boxes[0].weight, 1.0f);
    EXPECT_EQ(p.boxes[1].node, 6);
    EXPECT_FLOAT_EQ(p.boxes[1].weight, 0.25f);
    EXPECT_DOUBLE_EQ(p.predictedMs, 1.0 + 2 * 0.02 + 0.04);
    // Two frames later the weight is 3/4 and the ghosts are the same; then the fade ends.
    p = plan({}, {{6, ClusterRep::Textured}});
    fades.apply(m, kEye, p);
    p = plan({}, {{6, ClusterRep::Textured}});
    fades.apply(m, kEye, p);
    ASSERT_EQ(p.boxes.size(), 2u);
    EXPECT_FLOAT_EQ(p.boxes[1].weight, 0.75f);
    p = plan({}, {{6, ClusterRep::Textured}});
    fades.apply(m, kEye, p);
    EXPECT_TRUE(p.objects.empty());
    ASSERT_EQ(p.boxes.size(), 1u);
    EXPECT_FLOAT_EQ(p.boxes[0].weight, 1.0f);
}

TEST(ClusterFades, AWeightedBoxIsDrawnAfterTheBoxesBelowItWhateverTheirDistance) {
    const ClusterModel m = fourObjects();
    ClusterFades fades(4);
    // From x = 9 box 5 (centre x 5.5) is nearer than the root (3.5) and box 4 (1.5) farther:
    // by distance alone the root would come before box 5.
    const glm::dvec3 eye{9.0, 0.5, 0.5};
    ClusterFramePlan p = plan({}, {{4, ClusterRep::Textured}, {5, ClusterRep::Textured}});
    fades.apply(m, eye, p);
    p = plan({}, {{6, ClusterRep::Textured}});
    fades.apply(m, eye, p);
    ASSERT_EQ(p.boxes.size(), 3u);
    EXPECT_EQ(p.boxes[0].node, 4);  // farthest first
    EXPECT_EQ(p.boxes[1].node, 5);  // nearer than the root, still before it
    EXPECT_EQ(p.boxes[2].node, 6);
}

TEST(ClusterFades, ASwapDrawsTheOldBoxOpaqueAndTheNewOneOverIt) {
    const ClusterModel m = fourObjects();
    ClusterFades fades(2);
    ClusterFramePlan p = plan({}, {{6, ClusterRep::Textured}});
    fades.apply(m, kEye, p);
    p = plan({}, {{6, ClusterRep::Average}});
    fades.apply(m, kEye, p);
    ASSERT_EQ(p.boxes.size(), 2u);
    EXPECT_EQ(p.boxes[0].rep, ClusterRep::Textured);
    EXPECT_FLOAT_EQ(p.boxes[0].weight, 1.0f);
    EXPECT_EQ(p.boxes[1].rep, ClusterRep::Average);
    EXPECT_FLOAT_EQ(p.boxes[1].weight, 0.5f);
    p = plan({}, {{6, ClusterRep::Average}});
    fades.apply(m, kEye, p);
    ASSERT_EQ(p.boxes.size(), 1u);  // two frames: done
    EXPECT_FLOAT_EQ(p.boxes[0].weight, 1.0f);
}

TEST(ClusterFades, AnUndoneSwitchEndsItsFadeAndABackSwitchFadesTheOtherWay) {
    const ClusterModel m = fourObjects();
    ClusterFades fades(8);
    ClusterFramePlan p = plan({}, {{4, ClusterRep::Textured}, {5, ClusterRep::Textured}});
    fades.apply(m, kEye, p);
    p = plan({0, 1}, {{5, ClusterRep::Textured}});  // 4 refined: fades out
    fades.apply(m, kEye, p);
    EXPECT_EQ(p.fades, 1);
    p = plan({}, {{4, ClusterRep::Textured}, {5, ClusterRep::Textured}});  // and back
    fades.apply(m, kEye, p);
    EXPECT_EQ(p.fades, 1);  // the refine fade ended, a coarsen began
    EXPECT_THAT(p.objects, ::testing::ElementsAre(0, 1));
    ASSERT_EQ(p.boxes.size(), 2u);
    const auto four = std::find_if(p.boxes.begin(), p.boxes.end(), [](const ClusterBoxDraw& b) { return b.node == 4; });
    ASSERT_NE(four, p.boxes.end());
    EXPECT_FLOAT_EQ(four->weight, 1.0f / 8.0f);
}

TEST(ClusterFades, OneFrameOrLessLeavesThePlanAsSelected) {
    const ClusterModel m = fourObjects();
    for (int frames : {0, 1}) {
        ClusterFades fades(frames);
        ClusterFramePlan p = plan({}, {{4, ClusterRep::Textured}, {5, ClusterRep::Textured}});
        fades.apply(m, kEye, p);
        p = plan({0, 1, 2, 3}, {});
        fades.apply(m, kEye, p);
        EXPECT_TRUE(p.boxes.empty());
        EXPECT_EQ(p.fades, 0);
        EXPECT_DOUBLE_EQ(p.predictedMs, 1.0);
    }
}

}  // namespace
}  // namespace cavewall::hierarchy
