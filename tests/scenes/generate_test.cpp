// Generated plant and house: promised sizes, cells, walls, determinism, and clear walk paths.
#include "scenes/generate.h"
#include "scenes/glb_writer.h"
#include "scenes/loader.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "tests/scenes/gltf_builder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace cavewall::scenes {
namespace {

std::size_t countRole(const Scene& s, Role role) {
    std::size_t n = 0;
    for (const Object& o : s.objects) n += o.role == role ? 1 : 0;
    return n;
}

// True when the segment a-b passes through the box (sampled every 5 cm).
bool segmentHits(glm::dvec3 a, glm::dvec3 b, const Bounds& box) {
    const int steps = static_cast<int>(glm::length(b - a) / 0.05) + 1;
    for (int i = 0; i <= steps; ++i) {
        const glm::dvec3 p = a + (b - a) * (static_cast<double>(i) / steps);
        if (glm::all(glm::greaterThan(p, box.min)) && glm::all(glm::lessThan(p, box.max))) return true;
    }
    return false;
}

void expectWalkPathClear(const GeneratedScene& g) {
    const auto& path = g.description.walkPath;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        for (const Object& o : g.scene.objects)
            if (o.role == Role::Content) {
                EXPECT_FALSE(segmentHits(path[i], path[i + 1], o.worldBounds)) << o.name << " on leg " << i;
            }
}

TEST(GeneratePlant, DefaultHasTwoMillionTriangles24CellsAndSharedMeshes) {
    const GeneratedScene g = generatePlant({});
    EXPECT_GE(g.scene.triangleCount(), 2'000'000u);
    std::size_t stored = 0;
    for (const Mesh& m : g.scene.meshes) stored += m.triangleCount();
    EXPECT_LT(stored * 5, g.scene.triangleCount());  // instancing: far fewer stored than drawn
    EXPECT_EQ(g.description.cells.size(), 24u);      // rows N, M, S of 8 cells, 10 m wide
    EXPECT_EQ(g.description.walls.size(), 37u);
    for (const VirtualWall& w : g.description.walls) EXPECT_EQ(w.kind, WallKind::Virtual);
    const Bounds b = g.scene.bounds();
    EXPECT_GE(b.size().x, 60.0);
    EXPECT_GE(b.size().z, 30.0);
    EXPECT_GE(countRole(g.scene, Role::Structure), 6u + 6u);  // floor, roof, 4 walls, columns, beams
    // The walk path runs through every aisle cell (N1-N8, S1-S8) and the cross-aisle cells M1, M8.
    std::vector<bool> visited(g.description.cells.size(), false);
    const auto& path = g.description.walkPath;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        for (double t = 0.0; t <= 1.0; t += 0.005)
            if (const int c = findCell(g.description.cells, glm::mix(path[i], path[i + 1], t)); c >= 0)
                visited[c] = true;
    EXPECT_EQ(std::count(visited.begin(), visited.end(), true), 18);
    for (const char* name : {"N1", "N8", "S1", "S8", "M1", "M8"}) {
        const auto it = std::find_if(g.description.cells.begin(), g.description.cells.end(),
                                     [&](const Cell& c) { return c.name == name; });
        ASSERT_NE(it, g.description.cells.end()) << name;
        EXPECT_TRUE(visited[it - g.description.cells.begin()]) << name;
    }
    for (glm::dvec3 p : g.description.walkPath) EXPECT_EQ(p.y, g.description.eyeHeight);
    expectWalkPathClear(g);
}

// No content object crosses a cell boundary (so none crosses a virtual wall) and the walk
// path never runs through content, whatever the seed.
// Distance (metres) from floor point p to the footprint of wall w (a segment in x, z).
double toFootprint(glm::dvec2 p, const VirtualWall& w) {
    const glm::dvec2 a(w.lowerLeft.x, w.lowerLeft.z), b(w.lowerRight.x, w.lowerRight.z);
    const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
    return glm::length(p - (a + t * (b - a)));
}

TEST(GeneratePlant, TheWallPathHugsTheVirtualWallsAndCrossesThem) {
    const GeneratedScene g = generatePlant({1, 20000});
    const auto& path = g.description.wallPath;
    ASSERT_GE(path.size(), 2u);
    std::set<int> cells;
    int crossings = 0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        int previous = -1;
        for (double t = 0.0; t <= 1.0; t += 0.001) {
            const glm::dvec3 p = glm::mix(path[i], path[i + 1], t);
            const int c = findCell(g.description.cells, p);
            ASSERT_GE(c, 0) << "leg " << i << " leaves the cells at t = " << t;
            crossings += previous >= 0 && c != previous;
            previous = c;
            cells.insert(c);
            double nearest = 1e9;
            for (const VirtualWall& w : g.description.walls) nearest = std::min(nearest, toFootprint({p.x, p.z}, w));
            // The path is laid 0.3 m from the walls (generate_plant.cpp).
            ASSERT_LE(nearest, 0.3 + 1e-9) << "leg " << i << " at t = " << t;
        }
    }
    // N1-N8 along N|M, M1-M8 both ways, S1-S8 along M|S (each row's 7 walls crossed), the
    // N8|M8, M1|M2 and M8|S8 walls and S2|S3 twice: at least 7 + 7 + 7 + 4 crossings.
    EXPECT_GE(crossings, 25);
    EXPECT_EQ(cells.size(), 24u);
}

TEST(GeneratePlant, ContentStaysInsideOneCellForManySeeds) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        SCOPED_TRACE(seed);
        const GeneratedScene g = generatePlant({seed, 20000});
        expectWalkPathClear(g);
        expectWalkPathClear(generateHouse({seed, 20000}));
        for (const Object& o : g.scene.objects) {
            if (o.role != Role::Content) continue;
            SCOPED_TRACE(o.name);
            const Bounds& b = o.worldBounds;
            const int c = findCell(g.description.cells, {b.min.x, 0, b.min.z});
            EXPECT_GE(c, 0);
            EXPECT_EQ(findCell(g.description.cells, {b.max.x, 0, b.min.z}), c);
            EXPECT_EQ(findCell(g.description.cells, {b.min.x, 0, b.max.z}), c);
            EXPECT_EQ(findCell(g.description.cells, {b.max.x, 0, b.max.z}), c);
        }
    }
}

// Larger targets make the hall longer (8 bays of 10 m per 2 M triangles), so each cell holds
// about the same geometry at every size, and parts stay shared meshes.
TEST(GeneratePlant, LargerTargetsMakeALongerHallWithCellsOfTheSameWeight) {
    const GeneratedScene small = generatePlant({1, 2'000'000});
    const GeneratedScene large = generatePlant({1, 6'000'000});
    EXPECT_GE(large.scene.triangleCount(), 6'000'000u);
    EXPECT_EQ(large.description.cells.size(), 3u * 24u);             // 24 bays of 3 cells
    EXPECT_EQ(large.description.walls.size(), 3u * 23u + 2u * 24u);  // 69 cross walls, 48 along
    EXPECT_NEAR(large.scene.bounds().size().x, 3.0 * small.scene.bounds().size().x, 1.0);
    const double perCellSmall = double(small.scene.triangleCount()) / double(small.description.cells.size());
    const double perCellLarge = double(large.scene.triangleCount()) / double(large.description.cells.size());
    EXPECT_NEAR(perCellLarge / perCellSmall, 1.0, 0.15);
    std::size_t stored = 0;
    for (const Mesh& m : large.scene.meshes) stored += m.triangleCount();
    EXPECT_LT(stored * 20, large.scene.triangleCount());
    // The walk path reaches the end bays, and content still stays inside one cell.
    EXPECT_NEAR(large.description.walkPath[1].x, 0.5 * large.scene.bounds().size().x - 3.0, 1.0);
    expectWalkPathClear(large);
    for (const Object& o : large.scene.objects) {
        if (o.role != Role::Content) continue;
        const Bounds& b = o.worldBounds;
        const int c = findCell(large.description.cells, {b.min.x, 0, b.min.z});
        EXPECT_GE(c, 0) << o.name;
        EXPECT_EQ(findCell(large.description.cells, {b.max.x, 0, b.max.z}), c) << o.name;
    }
}

TEST(GenerateHouse, DefaultHasRoomsPortalsAndRealWalls) {
    const GeneratedScene g = generateHouse({});
    EXPECT_GE(g.scene.triangleCount(), 200'000u);
    EXPECT_EQ(g.description.cells.size(), 6u);
    EXPECT_EQ(g.description.walls.size(), 6u);  // one portal per doorway
    for (const VirtualWall& w : g.description.walls) {
        EXPECT_EQ(w.kind, WallKind::Portal);
        EXPECT_NEAR(glm::length(w.lowerRight - w.lowerLeft), 0.9, 1e-12);  // door width
    }
    // 4 outer walls + 7 interior walls of which 6 have a door (3 pieces each): 4 + 1 + 18 = 23.
    EXPECT_EQ(g.description.realWalls.size(), 23u);
    std::vector<bool> visited(6, false);
    for (glm::dvec3 p : g.description.walkPath) visited[findCell(g.description.cells, p)] = true;
    EXPECT_EQ(std::count(visited.begin(), visited.end(), true), 6);
    expectWalkPathClear(g);
}

TEST(Generate, SameSeedSameBytesOtherSeedOtherBytes) {
    const auto a = glbBytes(generatePlant({5, 30000}).scene), b = glbBytes(generatePlant({5, 30000}).scene);
    const auto c = glbBytes(generatePlant({6, 30000}).scene);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_EQ(glbBytes(generateHouse({5, 30000}).scene), glbBytes(generateHouse({5, 30000}).scene));
}

TEST(Generate, WrittenScenesValidateAndLoadBackWithTheirCells) {
    struct Case {
        const char* name;
        GeneratedScene (*make)(const GenerateOptions&);
        std::size_t cells, walls;
    };
    const Case cases[] = {{"plant", generatePlant, 24, 37}, {"house", generateHouse, 6, 6}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        GeneratedScene g = c.make({1, 20000});
        const auto json = writeGenerated(g, testing::testOutput("generate") / c.name);
        EXPECT_EQ(json.filename(), "scene.json");
        SceneDescription d;
        const Scene s = loadSceneFile(json, &d);
        EXPECT_EQ(d.cells.size(), c.cells);
        EXPECT_EQ(d.walls.size(), c.walls);
        EXPECT_EQ(d, g.description);  // the file says exactly what was generated
        EXPECT_TRUE(s.warnings.empty());
        EXPECT_EQ(s.triangleCount(), g.scene.triangleCount());
        EXPECT_EQ(countRole(s, Role::Content), countRole(g.scene, Role::Content));
        // Instancing survives the file: the content objects share as many meshes as generated.
        const auto contentMeshes = [](const Scene& scene) {
            std::set<int> m;
            for (const Object& o : scene.objects)
                if (o.role == Role::Content) m.insert(o.mesh);
            return m.size();
        };
        EXPECT_EQ(contentMeshes(s), contentMeshes(g.scene));
        // Structure is tagged through the "structure/*" node pattern; wide structure (the
        // plant's floor, roof and long walls) is cut into columns at load (kStructureChunkMetres),
        // so there are more structure objects than generated, with the same triangles.
        const auto structureTriangles = [](const Scene& scene) {
            std::size_t t = 0;
            for (const Object& o : scene.objects)
                if (o.role == Role::Structure) t += scene.meshes[o.mesh].triangleCount();
            return t;
        };
        EXPECT_EQ(structureTriangles(s), structureTriangles(g.scene));
        if (std::string(c.name) == "plant")
            EXPECT_GT(countRole(s, Role::Structure), countRole(g.scene, Role::Structure));
        else
            EXPECT_GE(countRole(s, Role::Structure), countRole(g.scene, Role::Structure));
        for (const Object& o : s.objects)
            if (o.role == Role::Structure && o.name.find(" [chunk ") == std::string::npos) {
                EXPECT_TRUE(std::max(o.worldBounds.size().x, o.worldBounds.size().z) <= kStructureChunkMetres ||
                            s.meshes[o.mesh].triangleCount() < 1024)
                    << o.name << " should have been cut";
            }
        for (const Object& o : s.objects)
            if (o.role == Role::Content) {
                EXPECT_GE(o.cell, 0) << o.name;
            }
    }
}

TEST(GenerateBoxHall, TwelveTrianglesPerBoxInsideTheHallWithFaceNormals) {
    const Scene s = generateBoxHall({3, 1000});
    // ceil(1000 / 12) = 84 boxes of 12 triangles: at least the target, less than one box over.
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.triangleCount(), 84u * 12u);
    const Mesh& m = s.meshes[0];
    EXPECT_EQ(m.positions.size(), 84u * 24u);
    EXPECT_TRUE(m.colors.empty());
    EXPECT_TRUE(m.texCoords0.empty());
    const Bounds b = s.bounds();
    EXPECT_GE(b.min.x, -30.0);
    EXPECT_LE(b.max.x, 30.0);
    EXPECT_GE(b.min.y, 0.0);
    EXPECT_LE(b.max.y, 8.0);
    EXPECT_GE(b.min.z, -15.0);
    EXPECT_LE(b.max.z, 15.0);
    // 84 boxes spread over the hall reach most of its width (a clustered generator would not).
    EXPECT_GT(b.size().x, 50.0);
    // Per-face normals: every triangle's three normals are equal, axis-aligned and agree with
    // its counter-clockwise winding.
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 n = m.normals[m.indices[t]];
        EXPECT_EQ(m.normals[m.indices[t + 1]], n);
        EXPECT_EQ(m.normals[m.indices[t + 2]], n);
        EXPECT_FLOAT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f);
        const glm::vec3 a = m.positions[m.indices[t]], c1 = m.positions[m.indices[t + 1]],
                        c2 = m.positions[m.indices[t + 2]];
        EXPECT_GT(glm::dot(glm::cross(c1 - a, c2 - a), n), 0.0f);
    }
}

TEST(GenerateBoxHall, SameSeedSameMeshOtherSeedOtherMesh) {
    const Scene a = generateBoxHall({5, 600}), b = generateBoxHall({5, 600}), c = generateBoxHall({6, 600});
    EXPECT_EQ(a.meshes[0].positions, b.meshes[0].positions);
    EXPECT_NE(a.meshes[0].positions, c.meshes[0].positions);
    // The default is a million triangles, the larger of the peer comparison's two sizes.
    EXPECT_EQ(kBoxHallDefaultTriangles, 1'000'000u);
}

}  // namespace
}  // namespace cavewall::scenes
