// Welding triangle soups and ordering meshes for the vertex cache (scenes/mesh_optimize.h).
#include "scenes/mesh_optimize.h"
#include "scenes/generate_parts.h"
#include "scenes/mesh_tools.h"
#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace cavewall::scenes {
namespace {

constexpr glm::vec4 kGrey(0.5f, 0.5f, 0.5f, 1.0f);

// The position tolerance the header promises: 1e-6 of the largest extent, at least 4 float
// ulps of the largest coordinate (epsilon * magnitude is one ulp or a little more).
double positionTolerance(const Mesh& m) {
    Bounds b;
    for (const glm::vec3& p : m.positions) b.add(glm::dvec3(p));
    const glm::dvec3 size = b.size();
    const double magnitude = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z), std::abs(b.max.x),
                                       std::abs(b.max.y), std::abs(b.max.z)});
    return std::max(1e-6 * std::max({size.x, size.y, size.z}), 4.0 * std::numeric_limits<float>::epsilon() * magnitude);
}

// Largest per-component difference (the header's Chebyshev distance).
template <typename V>
double chebyshev(const V& a, const V& b) {
    double d = 0.0;
    for (int c = 0; c < V::length(); ++c) d = std::max(d, std::abs(double(a[c]) - double(b[c])));
    return d;
}

bool bitIdentical(glm::vec3 a, glm::vec3 b) {
    return std::bit_cast<std::array<std::uint32_t, 3>>(a) == std::bit_cast<std::array<std::uint32_t, 3>>(b);
}

// A triangle as its corner positions, rotated so the smallest corner comes first (the winding,
// and so the facing, is kept): equal for the same triangle whatever its vertex indices.
using Corners = std::array<std::tuple<float, float, float>, 3>;
std::vector<Corners> canonicalTriangles(const Mesh& m) {
    std::vector<Corners> out;
    for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        Corners c;
        for (int i = 0; i < 3; ++i) {
            const glm::vec3 p = m.positions[m.indices[k + i]];
            c[i] = {p.x, p.y, p.z};
        }
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// A triangle soup: corners given, one normal per triangle, one colour.
Mesh soup(const std::vector<std::array<glm::vec3, 3>>& triangles, const std::vector<glm::vec3>& normals) {
    Mesh m;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (const glm::vec3& p : triangles[t]) {
            m.indices.push_back(static_cast<std::uint32_t>(m.positions.size()));
            m.positions.push_back(p);
            m.normals.push_back(normals[t]);
            m.colors.push_back(kGrey);
        }
    updateBounds(m);
    return m;
}

// Every corner its own vertex: a true triangle soup of `m`.
Mesh deindexed(const Mesh& m) {
    Mesh out;
    out.name = m.name;
    for (std::uint32_t i : m.indices) {
        out.indices.push_back(static_cast<std::uint32_t>(out.positions.size()));
        out.positions.push_back(m.positions[i]);
        if (!m.normals.empty()) out.normals.push_back(m.normals[i]);
        if (!m.texCoords0.empty()) out.texCoords0.push_back(m.texCoords0[i]);
        if (!m.colors.empty()) out.colors.push_back(m.colors[i]);
    }
    updateBounds(out);
    return out;
}

// A flat sheet of tiles x tiles quads in one colour and without texture coordinates
// (makeTiledQuad's per-tile uvs would keep every tile apart): it welds completely.
Mesh flatGrid(int tiles) {
    Mesh m = makeTiledQuad({0, 0, 0}, {1, 0, 0}, {0, 0, -1}, tiles, tiles, kGrey, kGrey);
    m.texCoords0.clear();
    return m;
}

TEST(MeshWeld, CylinderSoupWeldsToItsDistinctVertices) {
    // makeCylinder stores per segment 4 side vertices (smooth normal (x, 0, z)) and two cap
    // triangles (centre, p0, p1) with normal -Y or +Y, all with uv (0, 0) and one colour.
    // Welded, every rim point keeps two vertices (the side normal and the cap normal differ),
    // on both rims: 4N; plus the two cap centres shared by all N fans: 4N + 2. Neighbouring
    // segments compute their shared rim point as a0 + step and as step * i, and the last one
    // closes the ring at 2 * 3.14159265358979f rather than exactly at angle 0: both differ by
    // float rounding only, far below the tolerance (2e-6 for an extent of 2).
    for (int segments : {3, 12, 256}) {
        SCOPED_TRACE(segments);
        Mesh m = makeCylinder(1.0f, 2.0f, segments, kGrey);
        const std::size_t before = m.positions.size();
        ASSERT_EQ(before, 10u * segments);  // 4 side + 2 * 3 cap vertices per segment
        const WeldResult r = weldVertices(m);
        EXPECT_EQ(r.verticesBefore, before);
        EXPECT_EQ(r.verticesAfter, 4u * segments + 2u);
        EXPECT_EQ(m.positions.size(), 4u * segments + 2u);
        EXPECT_EQ(m.normals.size(), m.positions.size());
        EXPECT_EQ(m.texCoords0.size(), m.positions.size());
        EXPECT_EQ(m.colors.size(), m.positions.size());
        // The closing point at 2pi_f has z = -sin(2pi_f) ~ -1.7e-7 instead of -0: snapped.
        EXPECT_GT(r.positionsSnapped, 0u);
        EXPECT_EQ(m.triangleCount(), 4u * segments);
    }
}

TEST(MeshWeld, FlatGridWeldsToItsLatticePoints) {
    // 32 x 32 quads with 4 own vertices each; welded, the (32 + 1)^2 lattice points, one normal.
    Mesh m = flatGrid(32);
    ASSERT_EQ(m.positions.size(), 4u * 32 * 32);
    const WeldResult r = weldVertices(m);
    EXPECT_EQ(r.verticesAfter, 33u * 33u);
}

TEST(MeshWeld, TrianglesKeepTheirCornersAndAttributes) {
    const WeldTolerance tol;
    const Mesh meshes[] = {makeCylinder(0.3f, 1.5f, 48, kGrey), makeBox({1, 2, 3}, kGrey), makeMachineTool(0, 4)};
    for (const Mesh& original : meshes) {
        SCOPED_TRACE(original.name);
        Mesh m = original;
        const WeldResult r = weldVertices(m);
        // A box's 8 corners carry 3 face normals each: its 24 vertices stay. The others lose some.
        if (original.name == "box") {
            EXPECT_EQ(r.verticesAfter, 24u);
        } else {
            EXPECT_LT(r.verticesAfter, r.verticesBefore);
        }
        const double posTol = positionTolerance(original);
        ASSERT_EQ(m.indices.size(), original.indices.size());  // the same triangles in the same order
        ASSERT_EQ(m.normals.empty(), original.normals.empty());
        ASSERT_EQ(m.texCoords0.empty(), original.texCoords0.empty());
        ASSERT_EQ(m.colors.empty(), original.colors.empty());
        for (std::size_t k = 0; k < m.indices.size(); ++k) {
            const std::uint32_t a = original.indices[k], b = m.indices[k];
            ASSERT_LT(b, m.positions.size()) << "corner " << k;
            EXPECT_LE(chebyshev(original.positions[a], m.positions[b]), posTol) << "corner " << k;
            if (!m.normals.empty()) {
                EXPECT_LE(chebyshev(original.normals[a], m.normals[b]), tol.normal) << "corner " << k;
            }
            if (!m.texCoords0.empty()) {
                EXPECT_LE(chebyshev(original.texCoords0[a], m.texCoords0[b]), tol.texCoord) << "corner " << k;
            }
            if (!m.colors.empty()) {
                EXPECT_LE(chebyshev(original.colors[a], m.colors[b]), tol.color) << "corner " << k;
            }
        }
        // Bounds are recomputed from the welded positions.
        Bounds b;
        for (const glm::vec3& p : m.positions) b.add(glm::dvec3(p));
        EXPECT_EQ(m.bounds.min, b.min);
        EXPECT_EQ(m.bounds.max, b.max);
    }
}

TEST(MeshWeld, SeamVerticesStaySeparateWithBitIdenticalPositions) {
    // The cylinder's rims: side and cap vertices share positions but not normals. After welding,
    // any two vertices within the tolerance of each other stand on exactly the same bits (that
    // is how the simplifier recognises the seam); each of the 2N rim points carries exactly two
    // vertices (one close pair), the cap centres one each.
    const int n = 64;
    Mesh m = makeCylinder(1.0f, 2.0f, n, kGrey);
    weldVertices(m);
    const double tol = positionTolerance(m);
    std::size_t pairs = 0;
    for (std::uint32_t i = 0; i < m.positions.size(); ++i)
        for (std::uint32_t j = i + 1; j < m.positions.size(); ++j) {
            if (chebyshev(m.positions[i], m.positions[j]) > tol) continue;
            ++pairs;
            EXPECT_TRUE(bitIdentical(m.positions[i], m.positions[j])) << "vertices " << i << " and " << j;
            EXPECT_GT(chebyshev(m.normals[i], m.normals[j]), 0.5)
                << "vertices " << i << " and " << j << " have the same normal but were not merged";
        }
    EXPECT_EQ(pairs, 2u * n);  // one side/cap pair per rim point

    // The same with positions that differ (by 0.3x the tolerance) before welding: a hard edge
    // between two triangles at right angles, the shared edge written slightly apart.
    const float t = 1e-6f;  // the tolerance: the mesh's extent is 1
    Mesh edge = soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0.3f * t, 0, 0}, {0, 0, 1}, {0, 0.3f * t + 1, 0}}}},
                     {{0, 0, 1}, {1, 0, 0}});
    weldVertices(edge);
    EXPECT_EQ(edge.positions.size(), 6u);  // no vertex merged: the normals differ
    EXPECT_TRUE(bitIdentical(edge.positions[edge.indices[0]], edge.positions[edge.indices[3]]));
    EXPECT_TRUE(bitIdentical(edge.positions[edge.indices[2]], edge.positions[edge.indices[5]]));
}

TEST(MeshWeld, MergesWithinTheToleranceAndNotBeyond) {
    // Two triangles inside the unit cube, extent 1 (so the tolerance is 1e-6; 4 ulps of 1 are
    // only 4.8e-7), the second's first corner offset from the first's first corner (the origin)
    // by `offset`; same normal and colour.
    struct Case {
        const char* name;
        glm::vec3 offset;
        std::size_t vertices;
    };
    const float t = 1e-6f;
    const Case cases[] = {
        {"0.5x along x", {0.5f * t, 0, 0}, 5},
        {"0.5x along y and z", {0, 0.5f * t, 0.5f * t}, 5},
        {"0.5x on every axis (0.87x Euclidean, still within Chebyshev)", {0.5f * t, 0.5f * t, 0.5f * t}, 5},
        {"3x along x", {3 * t, 0, 0}, 6},
        {"3x along z", {0, 0, 3 * t}, 6},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Mesh m =
            soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{c.offset, {1, 1, 1}, {0, 1, 1}}}}, {{0, 0, 1}, {0, 0, 1}});
        const Mesh original = m;
        const WeldResult r = weldVertices(m);
        EXPECT_EQ(r.verticesAfter, c.vertices);
        EXPECT_EQ(r.positionsSnapped, c.vertices == 5 ? 1u : 0u);
        // Merged: both corners are one vertex. Apart: each keeps its own position exactly.
        EXPECT_EQ(m.indices[0] == m.indices[3], c.vertices == 5);
        if (c.vertices == 6) {
            EXPECT_EQ(m.positions[m.indices[3]], original.positions[3]);
        }
    }
}

TEST(MeshWeld, ToleranceIsAtLeastFourUlpsFarFromTheOrigin) {
    // Triangles of extent 2 at x = 1e4: the relative tolerance is 2e-6, but a float ulp there is
    // 2^-10 ~ 9.8e-4, so coordinates 2 ulps apart (1.95e-3) must still merge. 6 ulps must not:
    // 4 ulps estimated as 4 epsilon x 1e4 are 4.9 real ulps here, still below 6.
    const float x0 = 1e4f, ulp = std::nextafter(x0, 2e4f) - x0;
    ASSERT_EQ(ulp, 1.0f / 1024.0f);
    for (int ulps : {2, 6}) {
        SCOPED_TRACE(ulps);
        const float x1 = x0 + static_cast<float>(ulps) * ulp;
        Mesh m = soup({{{{x0, 0, 0}, {x0 + 1, 0, 0}, {x0, 1, 0}}}, {{{x1, 0, 0}, {x0, -1, 0}, {x0 - 1, 0, 0}}}},
                      {{0, 0, 1}, {0, 0, 1}});
        EXPECT_EQ(weldVertices(m).verticesAfter, ulps == 2 ? 5u : 6u);
    }
}

TEST(MeshWeld, UnusedVerticesAreDropped) {
    Mesh m = makeBox({1, 1, 1}, kGrey);
    // Three stray vertices no triangle uses, one of them a copy of a used vertex.
    for (std::uint32_t v : {0u, 5u, 17u}) {
        m.positions.push_back(m.positions[v] + glm::vec3(v == 0 ? 0.0f : 5.0f));
        m.normals.push_back(m.normals[v]);
        m.texCoords0.push_back(m.texCoords0[v]);
        m.colors.push_back(m.colors[v]);
    }
    const WeldResult r = weldVertices(m);
    EXPECT_EQ(r.verticesBefore, 27u);
    EXPECT_EQ(r.verticesAfter, 24u);
    EXPECT_EQ(m.positions.size(), 24u);
    EXPECT_EQ(m.texCoords0.size(), 24u);
    // The strays at +5 were beyond the box: the bounds no longer see them.
    EXPECT_EQ(m.bounds.max, glm::dvec3(0.5));

    Mesh noTriangles;
    noTriangles.positions = {{0, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(weldVertices(noTriangles).verticesAfter, 0u);
    EXPECT_TRUE(noTriangles.positions.empty());
}

TEST(MeshWeld, EmptyMeshIsFine) {
    Mesh m;
    const WeldResult r = weldVertices(m);
    EXPECT_EQ(r.verticesBefore, 0u);
    EXPECT_EQ(r.verticesAfter, 0u);
    optimizeVertexOrder(m);
    EXPECT_TRUE(m.positions.empty());
    EXPECT_TRUE(m.indices.empty());
    EXPECT_EQ(averageCacheMissRatio(m), 0.0);
}

TEST(MeshOptimize, KeepsTrianglesAndLowersCacheMisses) {
    // Measured with meshoptimizer 0.18 and a 16-entry FIFO (misses per triangle):
    //   grid 32 x 32: soup 3, welded in tile order 1.031, optimised 0.638; 1089 vertices for
    //     2048 triangles make 0.532 the least possible (every vertex shaded once);
    //   cylinder 256: soup 3, welded 1.129, optimised 1.033; least possible 1026 / 1024 = 1.002
    //     (a long ring of quads and two fans: almost every vertex serves only 2 triangles).
    // The bounds sit a little above the measurements, far below the soup's 3.
    struct Case {
        const char* name;
        Mesh mesh;
        double maxAcmr;
    };
    const Case cases[] = {
        {"grid 32 x 32", deindexed(flatGrid(32)), 0.7},
        {"cylinder 256", deindexed(makeCylinder(1.0f, 2.0f, 256, kGrey)), 1.1},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Mesh m = c.mesh;
        // A true soup shades every corner: exactly 3 misses per triangle.
        EXPECT_EQ(averageCacheMissRatio(m), 3.0);
        weldVertices(m);
        const double welded = averageCacheMissRatio(m);
        const std::vector<Corners> before = canonicalTriangles(m);
        const std::size_t vertices = m.positions.size();
        optimizeVertexOrder(m);
        const double optimized = averageCacheMissRatio(m);
        EXPECT_EQ(canonicalTriangles(m), before) << "the set of triangles changed";
        EXPECT_EQ(m.positions.size(), vertices);
        EXPECT_EQ(m.normals.size(), vertices);
        EXPECT_LT(optimized, welded);
        EXPECT_LT(optimized, c.maxAcmr) << "welded order: " << welded;
        // No order shades a vertex less than once.
        EXPECT_GE(optimized, static_cast<double>(vertices) / static_cast<double>(m.triangleCount()));
        // Vertices in first-use order: walking the indices meets vertex 0, 1, 2, ... in turn.
        std::uint32_t next = 0;
        for (std::size_t k = 0; k < m.indices.size(); ++k) {
            ASSERT_LE(m.indices[k], next) << "index " << k << " skips ahead";
            if (m.indices[k] == next) ++next;
        }
        EXPECT_EQ(next, vertices);
    }
}

TEST(MeshOptimize, PerFaceVerticesMissOncePerVertex) {
    // makeBox and makeCylinder share vertices only within a face (a side quad's two triangles),
    // so their "soups" miss once per vertex: 24 / 12 = 2 for a box, 10 / 4 = 2.5 per cylinder
    // segment (4 side vertices and 2 x 3 cap vertices for 4 triangles), not 3.
    EXPECT_EQ(averageCacheMissRatio(makeBox({1, 1, 1}, kGrey)), 2.0);
    EXPECT_EQ(averageCacheMissRatio(makeCylinder(1.0f, 1.0f, 32, kGrey)), 2.5);
}

}  // namespace
}  // namespace cavewall::scenes
