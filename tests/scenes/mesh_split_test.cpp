// Cutting large objects into chunks (scenes/mesh_split.h).
#include "scenes/mesh_split.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>

namespace cavewall::scenes {
namespace {

// A floor of n x n unit quads (2 triangles each) from (0, 0) to (n, n) in x, z at y = 0, with
// normals, one texture-coordinate set (u = x / n, v = z / n) and vertex colours.
Mesh floorGrid(int n, const std::string& name) {
    Mesh m;
    m.name = name;
    m.material = 0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            m.positions.push_back({float(i), 0.0f, float(j)});
            m.normals.push_back({0.0f, 1.0f, 0.0f});
            m.texCoords0.push_back({float(i) / n, float(j) / n});
            m.colors.push_back({float(i) / n, float(j) / n, 0.5f, 1.0f});
            m.bounds.add(glm::dvec3(i, 0, j));
        }
    auto v = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            m.indices.insert(m.indices.end(),
                             {v(i, j), v(i, j + 1), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i + 1, j)});
    return m;
}

Scene sceneOf(std::vector<Mesh> meshes) {
    Scene s;
    s.meshes = std::move(meshes);
    s.materials.resize(1);
    return s;
}

TEST(MeshSplit, CutsAWideObjectIntoColumnsKeepingEveryTriangleAndAttribute) {
    Scene s = sceneOf({floorGrid(10, "floor")});
    addObject(s, 0, glm::dmat4(1.0), "floor", Role::Content);
    const SplitStats stats = splitLargeObjects(s, 0, 1, 4.0, 1);
    EXPECT_EQ(stats.objectsCut, 1);
    EXPECT_EQ(stats.chunks, 9);  // columns [0,4), [4,8), [8,10] along x and z
    ASSERT_EQ(s.objects.size(), 9u);
    ASSERT_EQ(s.meshes.size(), 9u);  // the cut mesh is gone
    std::size_t triangles = 0;
    std::set<std::string> names;
    for (const Object& o : s.objects) {
        const Mesh& m = s.meshes[o.mesh];
        triangles += m.triangleCount();
        names.insert(o.name);
        EXPECT_EQ(o.role, Role::Content);
        EXPECT_EQ(m.material, 0);
        ASSERT_EQ(m.normals.size(), m.positions.size());
        ASSERT_EQ(m.texCoords0.size(), m.positions.size());
        ASSERT_EQ(m.colors.size(), m.positions.size());
        EXPECT_TRUE(m.texCoords1.empty());
        // Every triangle's centroid lies in one 4 m column; attributes travel with positions.
        const Bounds& b = o.worldBounds;
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            glm::dvec3 c(0.0);
            for (int k = 0; k < 3; ++k) c += glm::dvec3(m.positions[m.indices[3 * t + k]]);
            c /= 3.0;
            EXPECT_EQ(std::floor(c.x / 4.0), std::floor((b.min.x + 0.5) / 4.0));
            EXPECT_EQ(std::floor(c.z / 4.0), std::floor((b.min.z + 0.5) / 4.0));
        }
        for (std::size_t v = 0; v < m.positions.size(); ++v) {
            EXPECT_FLOAT_EQ(m.texCoords0[v].x, m.positions[v].x / 10.0f);
            EXPECT_FLOAT_EQ(m.colors[v].y, m.positions[v].z / 10.0f);
        }
        EXPECT_LE(b.size().x, 4.0 + 1e-9);
    }
    EXPECT_EQ(triangles, 200u);
    EXPECT_EQ(names.size(), 9u);
    EXPECT_TRUE(names.count("floor [chunk 0,0]"));
    EXPECT_TRUE(names.count("floor [chunk 2,2]"));
}

TEST(MeshSplit, ColumnsAreInTheWorldFrameOfAPlacedObject) {
    // Scaled by 0.5: the 10 m grid covers 5 m; chunks of 4 m make two columns per axis.
    Scene s = sceneOf({floorGrid(10, "floor")});
    addObject(s, 0, glm::scale(glm::translate(glm::dmat4(1.0), {100, 0, 0}), glm::dvec3(0.5)), "floor", Role::Content);
    addObject(s, 0, glm::dmat4(1.0), "hall floor", Role::Structure);  // always drawn: stays whole
    const SplitStats stats = splitLargeObjects(s, 0, 2, 4.0, 1);
    EXPECT_EQ(stats.chunks, 4);
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(s.objects[1].name, "hall floor");
    EXPECT_EQ(s.meshes[s.objects[1].mesh].triangleCount(), 200u);
    for (std::size_t i : {0u, 2u, 3u, 4u}) {
        const Object& o = s.objects[i];
        EXPECT_EQ(o.role, Role::Content);
        EXPECT_GE(o.worldBounds.min.x, 100.0);
        EXPECT_LE(o.worldBounds.max.x, 105.0);
    }
}

TEST(MeshSplit, LeavesSmallObjectsSharedMeshesOutsideTheRangeAndUnusedMeshesAlone) {
    // Mesh 0 (10 m) is used by objects 0 and 1; only object 1 is in the range; mesh 1 is small;
    // mesh 2 is used by nobody.
    Scene s = sceneOf({floorGrid(10, "big"), floorGrid(2, "small"), floorGrid(1, "unused")});
    addObject(s, 0, glm::dmat4(1.0), "outside", Role::Content);
    addObject(s, 0, glm::translate(glm::dmat4(1.0), {50, 0, 0}), "inside", Role::Content);
    addObject(s, 1, glm::dmat4(1.0), "small", Role::Content);
    const SplitStats stats = splitLargeObjects(s, 1, 3, 4.0, 1);
    EXPECT_EQ(stats.objectsCut, 1);
    ASSERT_EQ(s.objects.size(), 2u + 9u);
    EXPECT_EQ(s.objects[0].name, "outside");
    EXPECT_EQ(s.meshes[s.objects[0].mesh].name, "big");  // still whole
    EXPECT_EQ(s.meshes[s.objects[0].mesh].triangleCount(), 200u);
    EXPECT_EQ(s.objects[2].name, "small");  // order kept: chunks after the range
    EXPECT_EQ(s.meshes[s.objects[2].mesh].name, "small");
    EXPECT_EQ(s.meshes.size(), 3u + 9u);  // nothing removed: mesh 0 still used
    EXPECT_EQ(s.meshes[2].name, "unused");
}

TEST(MeshSplit, CutsOnlyObjectsOfTheRoleAsked) {
    Scene s = sceneOf({floorGrid(10, "floor"), floorGrid(10, "slab")});
    addObject(s, 0, glm::dmat4(1.0), "structure/floor", Role::Structure);
    addObject(s, 1, glm::translate(glm::dmat4(1.0), {20, 0, 0}), "slab", Role::Content);
    EXPECT_EQ(splitLargeObjects(s, 0, 2, 4.0, 1).objectsCut, 1);  // content by default
    ASSERT_EQ(s.objects.size(), 1u + 9u);
    EXPECT_EQ(s.objects[0].name, "structure/floor");  // structure left whole
    const SplitStats stats = splitLargeObjects(s, 0, s.objects.size(), 4.0, 1, Role::Structure);
    EXPECT_EQ(stats.objectsCut, 1);
    EXPECT_EQ(stats.chunks, 9);
    ASSERT_EQ(s.objects.size(), 9u + 9u);
    std::size_t structure = 0, triangles = 0;
    for (const Object& o : s.objects) {
        triangles += s.meshes[o.mesh].triangleCount();
        if (o.role != Role::Structure) continue;
        ++structure;  // the chunks keep their role and name their source
        EXPECT_THAT(o.name, ::testing::StartsWith("structure/floor [chunk "));
        EXPECT_LE(std::max(o.worldBounds.size().x, o.worldBounds.size().z), 4.0 + 1.0) << o.name;
    }
    EXPECT_EQ(structure, 9u);
    EXPECT_EQ(triangles, 2u * 200u);
}

TEST(MeshSplit, NeedsEnoughTrianglesAndAPositiveChunk) {
    Scene s = sceneOf({floorGrid(10, "floor")});
    addObject(s, 0, glm::dmat4(1.0), "floor", Role::Content);
    EXPECT_EQ(splitLargeObjects(s, 0, 1, 4.0, 201).objectsCut, 0);  // 200 triangles
    EXPECT_EQ(splitLargeObjects(s, 0, 1, 20.0, 1).objectsCut, 0);   // narrower than a chunk
    EXPECT_EQ(s.objects.size(), 1u);
    for (double bad : {0.0, -1.0, std::nan("")}) EXPECT_THROW(splitLargeObjects(s, 0, 1, bad, 1), Error) << bad;
}

}  // namespace
}  // namespace cavewall::scenes
