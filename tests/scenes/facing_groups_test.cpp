// Facing groups (scenes/facing_groups.h): grouping only reorders triangles, the groups cover the
// indices in order, and a group reported facing away holds only back faces from that eye —
// checked triangle by triangle from random eyes around a box hall, where many groups do face away.
#include "scenes/facing_groups.h"
#include "scenes/generate.h"
#include "scenes/primitives.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

namespace cavewall::scenes {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> trianglesOf(const Mesh& m) {
    std::vector<Triangle> t;
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) t.push_back({m.indices[i], m.indices[i + 1], m.indices[i + 2]});
    return t;
}

// Small groups, so that the 7,200 triangles below get a grid (2 x 2 x 2 cells per facing).
FacingOptions smallGroups() {
    FacingOptions o;
    o.minTriangles = 1000;
    o.trianglesPerGroup = 100;
    return o;
}

// A hall of 600 boxes (7,200 triangles) in one mesh, as generate boxes writes it.
Mesh hall() {
    GenerateOptions options;
    options.seed = 3;
    options.triangles = 7200;
    Scene s = generateBoxHall(options);
    return s.meshes.at(0);
}

TEST(FacingGroups, GroupingReordersTrianglesAndCoversTheIndicesInOrder) {
    Mesh m = hall();
    std::vector<Triangle> before = trianglesOf(m);
    const std::size_t groups = groupByFacing(m, smallGroups());
    EXPECT_EQ(groups, 48u);
    EXPECT_TRUE(facingGroupsValid(m));
    std::vector<Triangle> after = trianglesOf(m);
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(before, after);  // the same triangles, winding kept
    for (const FacingGroup& g : m.facingGroups) {
        for (std::uint32_t i = g.firstIndex; i < g.firstIndex + g.indexCount; i += 3) {
            const glm::dvec3 p0(m.positions[m.indices[i]]), p1(m.positions[m.indices[i + 1]]), p2(m.positions[m.indices[i + 2]]);
            const glm::dvec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
            // Every normal within the group's spread of its axis (boxes: one exact normal).
            EXPECT_GE(glm::dot(n, g.axis), std::sqrt(1.0 - g.sinSpread * g.sinSpread) - 1e-9);
            for (const glm::dvec3& p : {p0, p1, p2}) {
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, g.bounds.min)) && glm::all(glm::lessThanEqual(p, g.bounds.max)));
            }
        }
    }
    m.indices.pop_back();
    EXPECT_FALSE(facingGroupsValid(m));
}

// Back faces only, in every group reported facing away from random eyes; returns the share of
// triangles left out.
double checkFacingAway(const Mesh& m, double range, int eyes) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> coordinate(-range, range);
    std::size_t away = 0, total = 0;
    for (int e = 0; e < eyes; ++e) {
        const glm::dvec3 eye(coordinate(random), coordinate(random), coordinate(random));
        for (const FacingGroup& g : m.facingGroups) {
            total += g.indexCount / 3;
            if (!facesAway(g, eye)) continue;
            away += g.indexCount / 3;
            for (std::uint32_t i = g.firstIndex; i < g.firstIndex + g.indexCount; i += 3) {
                const glm::dvec3 p0(m.positions[m.indices[i]]), p1(m.positions[m.indices[i + 1]]), p2(m.positions[m.indices[i + 2]]);
                const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
                EXPECT_GT(glm::dot(n, p0 - eye), 0.0) << "eye " << e << ", triangle " << i / 3;
                if (glm::dot(n, p0 - eye) <= 0.0) return 0.0;
            }
        }
    }
    return static_cast<double>(away) / static_cast<double>(total);
}

TEST(FacingGroups, CurvedGroupsSpreadAndStillHoldOnlyBackFaces) {
    // A finely cut cylinder: each group's normals spread over tens of degrees.
    Mesh m = makeCylinder(1.0f, 2.0f, 2000, glm::vec4(1.0f));
    ASSERT_GT(groupByFacing(m, smallGroups()), 6u);
    const double spread = std::max_element(m.facingGroups.begin(), m.facingGroups.end(), [](const FacingGroup& a, const FacingGroup& b) {
                              return a.sinSpread < b.sinSpread;
                          })->sinSpread;
    EXPECT_GT(spread, 0.3);
    EXPECT_GT(checkFacingAway(m, 8.0, 60), 0.05);
}

TEST(FacingGroups, AGroupFacingAwayHoldsOnlyBackFacesFromThatEye) {
    Mesh m = hall();
    ASSERT_EQ(groupByFacing(m, smallGroups()), 48u);
    // Seen from around and inside the hall, a good share is left out.
    EXPECT_GT(checkFacingAway(m, 50.0, 40), 0.2);
}

TEST(FacingGroups, SmallMeshesAndWideSpreadsAreNeverLeftOut) {
    Mesh box = makeBox({1.0f, 1.0f, 1.0f}, glm::vec4(1.0f));
    const std::vector<std::uint32_t> indices = box.indices;
    EXPECT_EQ(groupByFacing(box), 0u);  // 12 triangles: below minTriangles
    EXPECT_EQ(box.indices, indices);
    FacingGroup wide;
    wide.axis = {0, 0, 1};
    wide.sinSpread = 1.0;
    wide.bounds.add({0, 0, 0});
    wide.bounds.add({1, 1, 1});
    EXPECT_FALSE(facesAway(wide, {0.5, 0.5, -100.0}));
    FacingGroup exact = wide;
    exact.sinSpread = 0.0;
    EXPECT_TRUE(facesAway(exact, {0.5, 0.5, -100.0}));  // +z faces seen from -z
    EXPECT_FALSE(facesAway(exact, {0.5, 0.5, 0.5}));    // the eye inside the bounds
    EXPECT_FALSE(facesAway(exact, {0.5, 0.5, 100.0}));
}

}  // namespace
}  // namespace cavewall::scenes
