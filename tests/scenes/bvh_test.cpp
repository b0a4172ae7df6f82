// Frustum planes from reversed-Z projections, and the BVH against brute force.
#include "scenes/bvh.h"
#include "scenes/generate_parts.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <limits>

namespace cavewall::scenes {
namespace {

// Reversed-Z perspective for an eye looking down -Z (rows as written, set column-major):
// depth = near / -z for an infinite far plane, else 1 at near and 0 at far.
glm::dmat4 reversedZ(double fovyDeg, double aspect, double nearZ, double farZ) {
    const double f = 1.0 / std::tan(glm::radians(fovyDeg) / 2.0);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = f;
    p[2][3] = -1.0;  // w = -z
    if (std::isinf(farZ)) {
        p[3][2] = nearZ;
    } else {
        p[2][2] = nearZ / (farZ - nearZ);
        p[3][2] = nearZ * farZ / (farZ - nearZ);
    }
    return p;
}

Bounds box(glm::dvec3 centre, double half) { return {centre - glm::dvec3(half), centre + glm::dvec3(half)}; }

TEST(Frustum, InFrontBehindBesideInsideAndFar) {
    const glm::dmat4 infinite = reversedZ(90.0, 1.0, 0.1, std::numeric_limits<double>::infinity());
    const glm::dmat4 finite = reversedZ(90.0, 1.0, 0.1, 100.0);
    struct Case {
        const char* name;
        Bounds b;
        bool infiniteVisible, finiteVisible;
    };
    const Case cases[] = {
        {"in front", box({0, 0, -5}, 0.5), true, true},
        {"behind the eye", box({0, 0, 5}, 0.5), false, false},
        // 90° fov: at distance 5 the frustum spans |x| <= 5; a box at x = 7 +- 0.5 is outside.
        {"beside", box({7, 0, -5}, 0.5), false, false},
        {"straddling the side plane", box({5.2, 0, -5}, 0.5), true, true},
        {"around the eye", box({0, 0, 0}, 1.0), true, true},
        {"between the eye and the near plane", box({0, 0, -0.05}, 0.01), false, false},
        // Far beyond a finite far plane, still in view with an infinite one.
        {"very far", box({0, 0, -1e6}, 1.0), true, false},
        {"above", box({0, 9, -5}, 0.5), false, false},
    };
    const Frustum inf(infinite), fin(finite);
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_EQ(inf.intersects(c.b), c.infiniteVisible);
        EXPECT_EQ(fin.intersects(c.b), c.finiteVisible);
    }
    EXPECT_FALSE(inf.intersects(Bounds{}));  // empty boxes are never drawn
    EXPECT_TRUE(inf.contains(box({0, 0, -5}, 0.5)));
    EXPECT_FALSE(inf.contains(box({5.2, 0, -5}, 0.5)));
}

TEST(Bvh, MatchesBruteForceOnRandomBoxesAndViews) {
    Rng rng(7);
    std::vector<Bounds> bounds;
    std::vector<int> cells;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 c(rng.uniform(-100, 100), rng.uniform(-5, 20), rng.uniform(-100, 100));
        const glm::dvec3 h(rng.uniform(0.05, 3), rng.uniform(0.05, 3), rng.uniform(0.05, 3));
        bounds.push_back({c - h, c + h});
        cells.push_back(rng.below(6) - 1);  // -1 .. 4
    }
    bounds.push_back({});  // an object with an empty mesh
    cells.push_back(0);
    const Bvh bvh(bounds, cells);
    EXPECT_EQ(bvh.objectCount(), bounds.size());
    std::vector<bool> mask = {true, false, true, false};  // cell 4 is beyond the mask: left out
    std::size_t keptTotal = 0;
    for (int v = 0; v < 60; ++v) {
        SCOPED_TRACE(v);
        const glm::dvec3 eye(rng.uniform(-80, 80), rng.uniform(0, 10), rng.uniform(-80, 80));
        const glm::dvec3 target(rng.uniform(-80, 80), rng.uniform(0, 10), rng.uniform(-80, 80));
        const double farZ = v % 2 ? std::numeric_limits<double>::infinity() : rng.uniform(20, 200);
        const glm::dmat4 clip = reversedZ(rng.uniform(30, 110), rng.uniform(0.5, 2), 0.05, farZ) *
                                glm::lookAt(eye, target, glm::dvec3(0, 1, 0));
        const Frustum f(clip);
        const std::vector<bool>* filters[] = {nullptr, &mask};
        for (const std::vector<bool>* filter : filters) {
            std::vector<int> expected;
            for (std::size_t i = 0; i < bounds.size(); ++i) {
                const int c = cells[i];
                if (filter && c >= 0 && (c >= 4 || !(*filter)[c])) continue;
                if (f.intersects(bounds[i])) expected.push_back(static_cast<int>(i));
            }
            std::vector<int> got = bvh.cull(clip, filter);
            std::sort(got.begin(), got.end());
            ASSERT_EQ(got, expected);
            keptTotal += got.size();
        }
        // Independent check: every box whose centre projects inside the NDC cube is kept.
        const std::vector<int> all = bvh.cull(clip);
        for (std::size_t i = 0; i + 1 < bounds.size(); ++i) {
            const glm::dvec4 p = clip * glm::dvec4(bounds[i].centre(), 1.0);
            if (p.w > 0 && std::abs(p.x) < p.w && std::abs(p.y) < p.w && p.z > 0 && p.z < p.w) {
                ASSERT_NE(std::find(all.begin(), all.end(), static_cast<int>(i)), all.end()) << i;
            }
        }
    }
    // Not a trivial pass: across the views some objects were kept and most were culled.
    EXPECT_GT(keptTotal, 0u);
    EXPECT_LT(keptTotal, 60u * 2u * bounds.size() / 2u);
}

TEST(Bvh, EmptySceneAndSceneConstructor) {
    const Bvh empty{std::vector<Bounds>{}};
    EXPECT_TRUE(empty.cull(glm::dmat4(1.0)).empty());
    Scene s;
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    m.bounds = {{0, 0, 0}, {1, 1, 0}};
    s.meshes.push_back(m);
    addObject(s, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -5)), "front");
    addObject(s, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 5)), "back");
    s.objects[0].cell = 1;
    const Bvh bvh(s);
    const glm::dmat4 clip = reversedZ(90.0, 1.0, 0.1, std::numeric_limits<double>::infinity());
    EXPECT_EQ(bvh.cull(clip), std::vector<int>{0});
    const std::vector<bool> onlyCell0 = {true, false};
    EXPECT_TRUE(bvh.cull(clip, &onlyCell0).empty());  // object 0 is in cell 1
    s.objects[0].moreCells = {2};                     // and in cell 2: kept with either
    EXPECT_TRUE(Bvh(s).cull(clip, &onlyCell0).empty());
    const std::vector<bool> cell2 = {false, false, true}, cell1 = {false, true};
    EXPECT_EQ(Bvh(s).cull(clip, &cell2), std::vector<int>{0});
    EXPECT_EQ(Bvh(s).cull(clip, &cell1), std::vector<int>{0});
}

TEST(Bvh, CellSetsKeepAnObjectWhenAnyOfItsCellsIsDrawn) {
    // Six boxes in view, each with its cell set: none (always kept), one cell, a negative
    // cell, two cells, a cell beyond the mask, and the lowest int (as a negative cell).
    const std::vector<std::vector<int>> sets = {{}, {1}, {-3}, {0, 2}, {5}, {std::numeric_limits<int>::min()}};
    std::vector<Bounds> bounds;
    for (std::size_t i = 0; i < sets.size(); ++i) {
        const glm::dvec3 c(static_cast<double>(i) - 2.5, 0.0, -10.0);
        bounds.push_back({c - 0.1, c + 0.1});
    }
    const Bvh bvh(bounds, sets);
    const glm::dmat4 clip = reversedZ(90.0, 1.0, 0.1, std::numeric_limits<double>::infinity());
    auto sorted = [](std::vector<int> v) {
        std::sort(v.begin(), v.end());
        return v;
    };
    EXPECT_EQ(sorted(bvh.cull(clip)), (std::vector<int>{0, 1, 2, 3, 4, 5}));
    const std::vector<bool> cell1 = {false, true, false}, cells02 = {true, false, true};
    EXPECT_EQ(sorted(bvh.cull(clip, &cell1)), (std::vector<int>{0, 1}));
    EXPECT_EQ(sorted(bvh.cull(clip, &cells02)), (std::vector<int>{0, 3}));
}

}  // namespace
}  // namespace cavewall::scenes
