// Maciel & Shirley's (1995) model hierarchy and its two-pass selection under a frame budget
// (hierarchy/cluster_tree.h).
#include "hierarchy/cluster_tree.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

namespace cavewall::hierarchy {
namespace {

using ::testing::ElementsAre;

scenes::Bounds box(double x0, double x1, double y0 = 0.0, double y1 = 1.0) {
    scenes::Bounds b;
    b.add(glm::dvec3(x0, y0, 0.0));
    b.add(glm::dvec3(x1, y1, 1.0));
    return b;
}

// The leaves below node n, by walking its children (not its objects list).
// `count` 1 m cubes on the floor at random places in a 20 m x 20 m square.
std::vector<scenes::Bounds> scatteredCubes(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> u(0.0, 20.0);
    std::vector<scenes::Bounds> objects;
    for (int i = 0; i < count; ++i) {
        const double x = u(rng), z = u(rng);
        scenes::Bounds b;
        b.add(glm::dvec3(x, 0, z));
        b.add(glm::dvec3(x + 1, 1, z + 1));
        objects.push_back(b);
    }
    return objects;
}

std::vector<int> leavesBelow(const ClusterTree& t, int n) {
    if (t.nodes[n].leaf()) return {t.nodes[n].object};
    std::vector<int> out;
    for (int c : t.nodes[n].children) {
        const auto below = leavesBelow(t, c);
        out.insert(out.end(), below.begin(), below.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Maciel & Shirley's (1995) figure 4 in one dimension: a model 4 m long in 4 finest cells
// along x.
//   A [0, 0.4] and B [0.5, 0.9] share cell 0 -> a cluster at level 1;
//   C [1.1, 1.9] is alone in cell 1 -> nothing at level 1;
//   D [1.9, 2.1] straddles the border of cells 1 | 2, which is also the border of the two
//     level-2 cells -> only the root takes it;
//   E [2.2, 2.5] and F [3.5, 3.9] are in cells 2 and 3 -> together in the level-2 cell [2, 4].
// Level 2: cell [0, 2] holds the cluster AB and C -> a cluster; level 3: the root.
std::vector<scenes::Bounds> figure4() {
    return {box(0.0, 0.4), box(0.5, 0.9), box(1.1, 1.9), box(1.9, 2.1), box(2.2, 2.5), box(3.5, 4.0)};
}

TEST(ClusterTree, BuildsBottomUpAndLeavesBorderObjectsForHigherLevels) {
    const ClusterTree t = buildClusterTree(figure4(), {4, 1, 1});
    ASSERT_EQ(t.nodes.size(), 6u + 4u);  // 6 leaves, clusters AB, ABC, EF, root
    for (int i = 0; i < 6; ++i) EXPECT_TRUE(t.nodes[i].leaf());
    const ClusterNode& ab = t.nodes[6];
    EXPECT_THAT(ab.children, ElementsAre(0, 1));
    EXPECT_EQ(ab.level, 1);
    // Level 2 makes ABC (cell [0, 2]) and EF (cell [2, 4]), in cell order.
    const ClusterNode& abc = t.nodes[7];
    EXPECT_THAT(abc.children, ElementsAre(2, 6));  // C and the cluster AB
    EXPECT_THAT(abc.objects, ElementsAre(0, 1, 2));
    EXPECT_EQ(abc.level, 2);
    const ClusterNode& ef = t.nodes[8];
    EXPECT_THAT(ef.children, ElementsAre(4, 5));
    EXPECT_EQ(t.root, 9);
    EXPECT_THAT(t.nodes[9].children, ElementsAre(3, 7, 8));  // D joins only at the root
    EXPECT_EQ(t.nodes[9].level, 3);
    EXPECT_THAT(t.nodes[9].objects, ElementsAre(0, 1, 2, 3, 4, 5));
    EXPECT_DOUBLE_EQ(abc.bounds.min.x, 0.0);
    EXPECT_DOUBLE_EQ(abc.bounds.max.x, 1.9);
}

TEST(ClusterTree, EveryObjectOnceUnderTheRootAndDeterministic) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 50.0), w(0.01, 4.0);
    std::vector<scenes::Bounds> objects;
    for (int i = 0; i < 400; ++i) {
        const double x = u(rng), z = u(rng);
        scenes::Bounds b;
        b.add(glm::dvec3(x, 0.0, z));
        b.add(glm::dvec3(x + w(rng), w(rng), z + w(rng)));
        objects.push_back(b);
    }
    objects.push_back(scenes::Bounds{});  // empty: under no cluster
    const ClusterTree t = buildClusterTree(objects, {8, 2, 8});
    std::vector<int> all(400);
    for (int i = 0; i < 400; ++i) all[i] = i;
    EXPECT_EQ(leavesBelow(t, t.root), all);
    EXPECT_EQ(t.nodes[t.root].objects, all);
    for (const ClusterNode& n : t.nodes) {
        if (n.leaf()) continue;
        EXPECT_GE(n.children.size(), 2u);
        for (int c : n.children) {  // a node's bounds hold its children's; children come first
            EXPECT_LT(c, &n - t.nodes.data());
            EXPECT_TRUE(glm::all(glm::lessThanEqual(n.bounds.min, t.nodes[c].bounds.min)));
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(n.bounds.max, t.nodes[c].bounds.max)));
        }
    }
    const ClusterTree again = buildClusterTree(objects, {8, 2, 8});
    ASSERT_EQ(again.nodes.size(), t.nodes.size());
    for (std::size_t i = 0; i < t.nodes.size(); ++i) EXPECT_EQ(again.nodes[i].children, t.nodes[i].children);
}

TEST(ClusterTree, SmallModels) {
    EXPECT_EQ(buildClusterTree({}, {4, 4, 4}).root, -1);
    EXPECT_EQ(buildClusterTree({scenes::Bounds{}}, {4, 4, 4}).root, -1);
    EXPECT_EQ(buildClusterTree({box(0, 1)}, {4, 4, 4}).root, 0);
    const ClusterTree flat =
        buildClusterTree({box(0, 1, 0, 0), box(2, 3, 0, 0)}, {0, -3, 2});  // flat in y; divisions clamped
    EXPECT_EQ(flat.divisions, glm::ivec3(1, 1, 2));
    EXPECT_THAT(flat.nodes[flat.root].children, ElementsAre(0, 1));
}

// Per node: a cluster has one representation (a textured box); a leaf has a coarse level
// (cost 1, accuracy 0.5) and full detail (cost 4, accuracy 1).
std::vector<NodeFrame> figure4Frame(const ClusterTree& t, const std::vector<double>& benefit) {
    std::vector<NodeFrame> f(t.nodes.size());
    for (std::size_t n = 0; n < t.nodes.size(); ++n) {
        if (t.nodes[n].leaf()) {
            f[n].benefit = benefit[n];
            f[n].visible = true;
            f[n].representations = {{0, 1.0, 0.5}, {1, 4.0, 1.0}};
        } else {
            f[n].representations = {{2, 1.0, 0.4}};
        }
    }
    return f;
}

std::vector<int> drawnNodes(const ClusterSelection& s) {
    std::vector<int> out;
    for (const ClusterChoice& c : s.drawn) out.push_back(c.node);
    std::sort(out.begin(), out.end());
    return out;
}

TEST(ClusterSelect, BudgetDecidesHowDeepTheTraversalGoes) {
    const ClusterTree t = buildClusterTree(figure4(), {4, 1, 1});
    const auto frame = figure4Frame(t, {1, 1, 1, 1, 5, 5});  // E and F matter most
    // Tiny budget: the root alone (a complete picture at the least cost).
    ClusterSelection s = selectClusters(t, frame, 0.5);
    EXPECT_THAT(drawnNodes(s), ElementsAre(t.root));
    EXPECT_EQ(s.clusters, 1);
    // 3 ms: the root's children (D, ABC, EF: 3 x 1 ms). 4 ms: also EF refined (the highest
    // benefit first), into E and F at their coarse level.
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0)), ElementsAre(3, 7, 8));
    s = selectClusters(t, frame, 4.0);
    EXPECT_THAT(drawnNodes(s), ElementsAre(3, 4, 5, 7));
    EXPECT_DOUBLE_EQ(s.costMs, 4.0);
    // Everything at full detail: 6 leaves x 4 ms.
    s = selectClusters(t, frame, 24.0);
    EXPECT_THAT(drawnNodes(s), ElementsAre(0, 1, 2, 3, 4, 5));
    for (const ClusterChoice& c : s.drawn) EXPECT_EQ(c.representation, 1);
    EXPECT_DOUBLE_EQ(s.costMs, 24.0);
    // The benefit orders the upgrades: 9 ms over six coarse leaves (6 ms) upgrades one leaf
    // (+3 ms), and it is E or F.
    s = selectClusters(t, frame, 9.0);
    int upgraded = -1;
    for (const ClusterChoice& c : s.drawn)
        if (c.representation == 1) upgraded = c.node;
    EXPECT_TRUE(upgraded == 4 || upgraded == 5) << upgraded;
}

TEST(ClusterSelect, InvisibleNodesCostNothing) {
    const ClusterTree t = buildClusterTree(figure4(), {4, 1, 1});
    auto frame = figure4Frame(t, {1, 1, 1, 1, 1, 1});
    for (int n : {4, 5}) frame[n].visible = false;  // EF out of view: the cluster too
    const ClusterSelection s = selectClusters(t, frame, 100.0);
    EXPECT_THAT(drawnNodes(s), ElementsAre(0, 1, 2, 3));
    EXPECT_DOUBLE_EQ(s.costMs, 16.0);
    for (auto& f : frame) f.visible = false;
    EXPECT_TRUE(selectClusters(t, frame, 100.0).drawn.empty());
}

TEST(ClusterSelect, NeverOverBudgetWhenTheRootFits) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> c(0.1, 3.0), a(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const std::vector<scenes::Bounds> objects = scatteredCubes(rng, 60);
        const ClusterTree t = buildClusterTree(objects, {4, 1, 4});
        std::vector<NodeFrame> frame(t.nodes.size());
        for (auto& f : frame) {
            f.benefit = a(rng);
            f.visible = a(rng) > 0.2;
            f.representations = {{0, c(rng), a(rng)}, {1, c(rng), a(rng)}};
        }
        frame[t.root].visible = true;
        const double budget = 3.0 + 30.0 * a(rng);  // the root costs at most 3
        const ClusterSelection s = selectClusters(t, frame, budget);
        EXPECT_LE(s.costMs, budget + 1e-9);
        // One node per root-to-leaf path: no drawn node lies below another.
        std::vector<int> covered;
        for (const ClusterChoice& ch : s.drawn) {
            const auto& objs = t.nodes[ch.node].objects;
            covered.insert(covered.end(), objs.begin(), objs.end());
        }
        std::sort(covered.begin(), covered.end());
        EXPECT_TRUE(std::adjacent_find(covered.begin(), covered.end()) == covered.end());
    }
}

TEST(ClusterSelect, NeverOverBudgetOrTheCheapestSelectionWhateverTheBudgetAndCoherence) {
    // The frame-time controller (hierarchy/cluster_budget.h) relies on this: a frame's selection
    // costs at most its budget, or, when the budget is below that, at most the selection at a
    // budget of 0 (the floor's part), also while the coherence counter holds clusters back over
    // a sequence of frames.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> c(0.1, 3.0), a(0.0, 1.0);
    const std::vector<scenes::Bounds> objects = scatteredCubes(rng, 80);
    const ClusterTree t = buildClusterTree(objects, {4, 1, 4});
    ClusterCoherence coherence(2);
    for (int frameIndex = 0; frameIndex < 60; ++frameIndex) {
        std::vector<NodeFrame> frame(t.nodes.size());
        for (auto& f : frame) {
            f.benefit = a(rng);
            f.visible = a(rng) > 0.2;
            f.representations = {{0, c(rng), a(rng)}, {1, c(rng), a(rng)}};
        }
        frame[t.root].visible = true;
        const double budget = 40.0 * a(rng) * a(rng);  // often below the root's cost (0.1 to 3)
        const double cheapest = selectClusters(t, frame, 0.0).costMs;
        const ClusterSelection s = selectClusters(t, frame, budget, &coherence);
        SCOPED_TRACE(frameIndex);
        EXPECT_LE(s.costMs, std::max(budget, cheapest) + 1e-9);
        EXPECT_GT(cheapest, 0.0);
    }
}

TEST(ClusterSelect, CoherenceDelaysRefiningButNotCollapsing) {
    const ClusterTree t = buildClusterTree(figure4(), {4, 1, 1});
    const auto frame = figure4Frame(t, {1, 1, 1, 1, 5, 5});
    ClusterCoherence coherence(2);  // refine after more than 2 consecutive frames of wanting to
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(t.root));
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(t.root));
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(3, 7, 8));
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(3, 7, 8));  // stays
    // The budget shrinks: back to the root at once.
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 1.0, &coherence)), ElementsAre(t.root));
    // A frame without the wish resets the count.
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(t.root));
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(t.root));
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(3, 7, 8));
}

TEST(ClusterSelect, ACoherentClusterThatShowsNothingIsRefinedAtOnce) {
    // The eye inside the root's box: its impostor shows nothing (accuracy 0), so waiting for the
    // counter would draw a hole; its children are taken in the first frame.
    const ClusterTree t = buildClusterTree(figure4(), {4, 1, 1});
    auto frame = figure4Frame(t, {1, 1, 1, 1, 5, 5});
    frame[t.root].representations = {{2, 1.0, 0.0}};
    ClusterCoherence coherence(2);
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 3.0, &coherence)), ElementsAre(3, 7, 8));
}

TEST(ClusterSelect, AClusterThatShowsNothingIsRefinedWhenItsChildrenCostLessWhateverTheBudget) {
    // The root's box around the eye shows nothing and fills every view (5 ms); its children
    // (D, ABC, EF) cost 1 ms each: refining lowers the frame's cost, so it happens even at a
    // budget of 0, and the cheapest selection is the children's 3 ms.
    const ClusterTree t = buildClusterTree(figure4(), {4, 1, 1});
    auto frame = figure4Frame(t, {1, 1, 1, 1, 5, 5});
    frame[t.root].representations = {{2, 5.0, 0.0}};
    const ClusterSelection s = selectClusters(t, frame, 0.0);
    EXPECT_THAT(drawnNodes(s), ElementsAre(3, 7, 8));
    EXPECT_DOUBLE_EQ(s.costMs, 3.0);
    // Children that cost more than the useless box: over the budget, the box stays.
    frame[t.root].representations = {{2, 2.0, 0.0}};
    EXPECT_THAT(drawnNodes(selectClusters(t, frame, 0.0)), ElementsAre(t.root));
}

}  // namespace
}  // namespace cavewall::hierarchy
