// Lighting per vertex (render/vertex_lighting.h): the bound on its difference from the per-pixel
// headlight holds on random flat triangles seen from random eyes and is not loose by 2x, and the
// render list uses it only where it is within the tolerance.
#include "display/display.h"
#include "render/render_list.h"
#include "render/vertex_lighting.h"
#include "scenes/primitives.h"
#include "tests/render/render_test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace cavewall::render {
namespace {

// The per-pixel diffuse term of a flat triangle with unit normal n at point x (eye at the origin).
double diffuse(const glm::dvec3& n, const glm::dvec3& x) { return std::abs(glm::dot(n, -glm::normalize(x))); }

struct Worst {
    double error = 0.0;  // the largest |per pixel - per vertex| found
    double ratio = 0.0;  // the largest error / bound found
};

// Samples barycentric points of the triangle p[0..2] (eye at the origin) and compares the
// per-pixel term with the barycentric interpolation of the vertex terms (what perspective-correct
// Gouraud shading draws), against vertexLightingError at the distance of the triangle's box.
Worst compare(const glm::dvec3 p[3], int steps = 24) {
    const glm::dvec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    const double edge = std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    const glm::dvec3 lo = glm::min(glm::min(p[0], p[1]), p[2]), hi = glm::max(glm::max(p[0], p[1]), p[2]);
    const double distance = glm::length(glm::max(glm::max(lo, -hi), glm::dvec3(0.0)));
    const double bound = vertexLightingError(edge, distance) - 2.0 * kFlatNormalSlack;  // exact normals here
    const double f[3] = {diffuse(n, p[0]), diffuse(n, p[1]), diffuse(n, p[2])};
    Worst w;
    for (int i = 0; i <= steps; ++i)
        for (int j = 0; i + j <= steps; ++j) {
            const double a = double(i) / steps, b = double(j) / steps, c = 1.0 - a - b;
            const glm::dvec3 x = a * p[0] + b * p[1] + c * p[2];
            const double error = std::abs(diffuse(n, x) - (a * f[0] + b * f[1] + c * f[2]));
            w.error = std::max(w.error, error);
            w.ratio = std::max(w.ratio, error / bound);
        }
    return w;
}

TEST(VertexLighting, BoundHoldsOnRandomFlatTrianglesFromRandomEyes) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), scale(0.01, 1.0);
    double worstRatio = 0.0;
    for (int t = 0; t < 3000; ++t) {
        // A triangle of size up to a few metres 1-20 m away in a random direction.
        const glm::dvec3 centre =
            glm::normalize(glm::dvec3(unit(random), unit(random), unit(random))) * (1.0 + 19.0 * scale(random));
        const double size = 3.0 * scale(random);
        glm::dvec3 p[3];
        for (glm::dvec3& v : p) v = centre + size * glm::dvec3(unit(random), unit(random), unit(random));
        if (glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) < 1e-6) continue;
        worstRatio = std::max(worstRatio, compare(p).ratio);
    }
    EXPECT_LE(worstRatio, 1.0);
    EXPECT_GT(worstRatio, 0.5) << "the bound would be loose by " << 1.0 / worstRatio;
}

TEST(VertexLighting, FlatMeshesHaveTheirLongestEdgeSmoothOnesNone) {
    const scenes::Mesh box = scenes::makeBox({1.0f, 2.0f, 3.0f}, glm::vec4(1.0f));
    EXPECT_NEAR(flatMaxEdge(box, box.indices), std::sqrt(2.0 * 2.0 + 3.0 * 3.0), 1e-5);
    const scenes::Mesh cylinder = scenes::makeCylinder(0.5f, 1.0f, 16, glm::vec4(1.0f));
    EXPECT_LT(flatMaxEdge(cylinder, cylinder.indices), 0.0);  // smooth normals around the side
    scenes::Mesh coloured = box;
    coloured.colors.assign(box.positions.size(), glm::vec4(1.0f));
    EXPECT_GT(flatMaxEdge(coloured, coloured.indices), 0.0);
    coloured.colors[coloured.indices[1]] = glm::vec4(0.5f, 1.0f, 1.0f, 1.0f);
    EXPECT_LT(flatMaxEdge(coloured, coloured.indices), 0.0);  // colour varies within a triangle
    scenes::Mesh broken = box;
    broken.indices[4] = static_cast<std::uint32_t>(box.positions.size());
    EXPECT_LT(flatMaxEdge(broken, broken.indices), 0.0);
    scenes::Mesh tilted = box;
    tilted.normals[tilted.indices[0]] = glm::normalize(tilted.normals[tilted.indices[0]] + glm::vec3(0.01f));
    EXPECT_LT(flatMaxEdge(tilted, tilted.indices), 0.0);
}

TEST(VertexLighting, LitPerVertexOnlyWithinTheTolerance) {
    // Edge 1 m: (1/d)^2 / 6 + 2e-4 <= 1/512 needs d >= 9.7 m.
    EXPECT_FALSE(litPerVertex(1.0, 1.0, 9.5, kVertexLightingTolerance));
    EXPECT_TRUE(litPerVertex(1.0, 1.0, 10.0, kVertexLightingTolerance));
    EXPECT_FALSE(litPerVertex(1.0, 2.0, 10.0, kVertexLightingTolerance));  // the object is scaled up
    EXPECT_FALSE(litPerVertex(-1.0, 1.0, 1e6, kVertexLightingTolerance));  // not flat
    EXPECT_FALSE(litPerVertex(1.0, 1.0, 40.0, 0.0));                       // switched off
    EXPECT_FALSE(litPerVertex(1.0, 1.0, 0.0, kVertexLightingTolerance));   // eye inside its bounds
}

TEST(VertexLighting, RenderListsLightFarFlatDrawsPerVertexInTheirOwnBatch) {
    scenes::Scene scene;
    const int nearCube = testing::addCube(scene, {0, 0, -2}, 0.5);
    const int farCube = testing::addCube(scene, {0, 0, -30}, 0.5);
    const RenderScene rs(scene, false);
    const display::Display d(testing::oneScreen());
    const display::ScreenView view = d.views({{0, 0, 0}, glm::dquat(1, 0, 0, 0)}).at(0);
    ListBuilder builder(rs);
    const RenderList& list = builder.build(view.frustum, glm::dmat4(1.0), {});
    ASSERT_EQ(list.draws.size(), 2u);
    ASSERT_EQ(list.batches.size(), 2u);
    for (const Draw& draw : list.draws) EXPECT_EQ(draw.vertexLit, draw.object == farCube) << draw.object;
    for (const Batch& b : list.batches)
        for (int i = b.first; i < b.first + b.count; ++i) EXPECT_EQ(drawKey(rs, list.draws[i]), b.key);
    builder.setVertexLightingTolerance(0.0);
    const RenderList& perPixel = builder.build(view.frustum, glm::dmat4(1.0), {});
    for (const Draw& draw : perPixel.draws) EXPECT_FALSE(draw.vertexLit) << draw.object;
    EXPECT_NE(nearCube, farCube);
}

}  // namespace
}  // namespace cavewall::render
