// Render lists (render/render_list.h): what a view draws, in which order and batches.
#include "display/display.h"
#include "render/portal_cull.h"
#include "render/render_list.h"
#include "scenes/bvh.h"
#include "tests/render/render_test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace cavewall::render {
namespace {

using testing::addCube;
using testing::Look;

// The one-screen display's view from an eye at the origin looking down -Z.
display::ScreenView frontView() {
    static const display::Display d(testing::oneScreen());
    return d.views({{0, 0, 0}, glm::dquat(1, 0, 0, 0)}).at(0);
}

std::vector<int> objectsOf(const RenderList& list) {
    std::vector<int> out;
    for (const Draw& d : list.draws) out.push_back(d.object);
    return out;
}

// Squared distance of the eye from an object's bounds (0 inside): the front-to-back key.
double distance2(const scenes::Object& o, glm::dvec3 eye) {
    const glm::dvec3 outside = glm::max(glm::max(o.worldBounds.min - eye, eye - o.worldBounds.max), glm::dvec3(0.0));
    return glm::dot(outside, outside);
}

// 400 cubes of 0.1 m to 2 m scattered over a 40 m cube around the origin (fixed seed).
scenes::Scene scattered() {
    std::mt19937 random(7);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (random() / 4294967296.0); };
    scenes::Scene scene;
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 centre(uniform(-20, 20), uniform(-20, 20), uniform(-20, 20));
        addCube(scene, centre, uniform(0.1, 2.0));
    }
    return scene;
}

TEST(RenderList, CullingKeepsExactlyTheObjectsWhoseBoundsMeetTheFrustumByBruteForce) {
    const scenes::Scene scene = scattered();
    const RenderScene rs(scene, false);
    ListBuilder builder(rs);
    const display::ScreenView view = frontView();
    // Six directions and a tilted one; the frame is moved through the world by frameFromWorld.
    const glm::dmat4 turns[] = {
        glm::dmat4(1.0),
        glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0, 1, 0)),
        glm::rotate(glm::dmat4(1.0), glm::radians(180.0), glm::dvec3(0, 1, 0)),
        glm::rotate(glm::dmat4(1.0), glm::radians(-90.0), glm::dvec3(0, 1, 0)),
        glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0)),
        glm::rotate(glm::dmat4(1.0), glm::radians(-90.0), glm::dvec3(1, 0, 0)),
        glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(3, -2, 5)), glm::radians(33.0), glm::dvec3(1, 2, 0.5)),
    };
    std::size_t total = 0;
    for (const glm::dmat4& frameFromWorld : turns) {
        const RenderList& list = builder.build(view.frustum, frameFromWorld, {});
        const scenes::Frustum frustum(view.frustum.clipFromView * view.frustum.viewFromFrame * frameFromWorld);
        std::set<int> expected;
        for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i)
            if (frustum.intersects(scene.objects[i].worldBounds)) expected.insert(i);
        const std::vector<int> drawn = objectsOf(list);
        EXPECT_EQ(std::set<int>(drawn.begin(), drawn.end()), expected);
        EXPECT_EQ(drawn.size(), expected.size());  // each once
        EXPECT_EQ(list.triangles, 12 * expected.size());
        total += expected.size();
    }
    // The views see some of the cubes, not none and not all (else culling proves nothing).
    EXPECT_GT(total, 7u * 10u);
    EXPECT_LT(total, 7u * 400u);
}

// Red (content), green (structure), blue (content) at x = -1, 0, 1, 3 m in front of the eye.
scenes::Scene threeCubes() {
    scenes::Scene scene;
    addCube(scene, {-1, 0, -3});
    Look structure;
    structure.role = scenes::Role::Structure;
    addCube(scene, {0, 0, -3}, 0.5, structure);
    addCube(scene, {1, 0, -3});
    return scene;
}

// Portal culling from the view's eye in the world: what the frustum keeps less what no chain
// shows, the structure and unlisted objects untouched.
TEST(RenderList, PortalsCullFromTheViewsEyeInTheWorld) {
    const scenes::Scene scene = scattered();
    const RenderScene rs(scene, false);
    ListBuilder builder(rs);
    const display::ScreenView view = frontView();
    PortalSets portals;
    portals.portals = {{{-2.0, -2.0, -5.0}, {2.0, -2.0, -5.0}, {-2.0, 2.0, -5.0}}};  // 4 m, 5 m ahead
    portals.chains = {{0}};
    portals.sets = {{0}};
    portals.objectSet.assign(scene.objects.size(), 0);
    portals.objectSet[0] = -1;
    DrawFilter filter;
    filter.portals = &portals;
    for (const glm::dvec3 shift : {glm::dvec3(0.0), glm::dvec3(0.5, -0.3, 2.0)}) {
        const glm::dmat4 frameFromWorld = glm::translate(glm::dmat4(1.0), -shift);  // the eye at `shift`
        const std::vector<int> all = objectsOf(builder.build(view.frustum, frameFromWorld, {}));
        const std::vector<int> drawn = objectsOf(builder.build(view.frustum, frameFromWorld, filter));
        const PortalView portalView(portals, shift);
        std::set<int> expected;
        for (int i : all)
            if (portalView.visible(i, scene.objects[i].worldBounds)) expected.insert(i);
        EXPECT_EQ(std::set<int>(drawn.begin(), drawn.end()), expected);
        EXPECT_LT(drawn.size(), all.size() / 2);  // a 4 m portal 5 m away hides most of the view
        EXPECT_GT(drawn.size(), 3u);
    }
}

TEST(RenderList, FilterSelectsByListAndRoleAndCullingCanBeTurnedOff) {
    scenes::Scene scene = threeCubes();
    addCube(scene, {0, 0, 3});  // behind the eye: culled unless culling is off
    const RenderScene rs(scene, false);
    ListBuilder builder(rs);
    const std::vector<int> list{2, 0, 0, 7, -1, 3};  // order, duplicates and bad indices do not matter
    const std::vector<int> middle{1};
    struct Case {
        const char* name;
        DrawFilter filter;
        std::set<int> expected;
    };
    DrawFilter byList, noStructure, middleNoStructure, noCulling, listNoCulling;
    byList.objects = &list;
    noStructure.skipStructure = true;
    middleNoStructure.objects = &middle;
    middleNoStructure.skipStructure = true;
    noCulling.frustumCull = false;
    listNoCulling.objects = &list;
    listNoCulling.frustumCull = false;
    const Case cases[] = {
        {"no filter: everything in view", {}, {0, 1, 2}},
        {"object list (3 is behind the eye)", byList, {0, 2}},
        {"skip structure", noStructure, {0, 2}},
        {"list and role intersect: nothing", middleNoStructure, {}},
        {"no culling: all", noCulling, {0, 1, 2, 3}},
        {"no culling: the list's valid indices", listNoCulling, {0, 2, 3}},
    };
    const display::ScreenView view = frontView();
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::vector<int> drawn = objectsOf(builder.build(view.frustum, glm::dmat4(1.0), c.filter));
        EXPECT_EQ(std::set<int>(drawn.begin(), drawn.end()), c.expected);
        EXPECT_EQ(drawn.size(), c.expected.size());
    }
}

TEST(RenderList, OpaqueDrawsGoFrontToBackWithinABatchAndBlendedOnesLastBackToFront) {
    scenes::Scene scene;
    // Opaque cubes at shuffled distances along -Z (two of them tied), then blended ones.
    const double opaqueZ[] = {-6, -2, -9, -4, -4, -3};
    for (double z : opaqueZ) addCube(scene, {0.3 * z, 0, z});
    Look glass;
    glass.alpha = scenes::AlphaMode::Blend;
    const double blendedZ[] = {-5, -8, -2.5};
    for (double z : blendedZ) addCube(scene, {-0.2 * z, 0.1, z}, 0.5, glass);
    const RenderScene rs(scene, false);
    ListBuilder builder(rs);
    builder.setVertexLightingTolerance(0.0);  // one lighting: far cubes would get their own batch
    const display::ScreenView view = frontView();
    const RenderList& list = builder.build(view.frustum, glm::dmat4(1.0), {});
    ASSERT_EQ(list.draws.size(), 9u);
    // All opaque cubes share one key (untextured, culled, counter-clockwise): one batch, then
    // the blended ones (same key, neighbours merged): one more.
    ASSERT_EQ(list.batches.size(), 2u);
    EXPECT_EQ(list.firstBlended, 1u);
    EXPECT_EQ(list.batches[0].count, 6);
    // Front to back by the distance of the bounds from the eye; the tie keeps scene order (3, 4).
    EXPECT_EQ(objectsOf(list), (std::vector<int>{1, 5, 3, 4, 0, 2, 7, 6, 8}));
    for (int d = 1; d < 6; ++d)
        EXPECT_LE(distance2(scene.objects[list.draws[d - 1].object], {0, 0, 0}),
                  distance2(scene.objects[list.draws[d].object], {0, 0, 0}));
}

TEST(RenderList, OpaqueBatchesFollowKeyOrderEachFrontToBack) {
    scenes::Scene scene;
    const int image = testing::addImage(scene);
    Look textured, mirrored;
    textured.image = image;
    mirrored.mirrored = true;
    addCube(scene, {0, 0, -7}, 0.5, textured);  // 0
    addCube(scene, {0, 0, -5});                 // 1
    addCube(scene, {0, 0, -2}, 0.5, textured);  // 2
    addCube(scene, {0, 0, -3}, 0.5, mirrored);  // 3
    addCube(scene, {0, 0, -9});                 // 4
    const RenderScene rs(scene, false);
    ListBuilder builder(rs);
    builder.setVertexLightingTolerance(0.0);  // one lighting: far cubes would get their own batch
    const display::ScreenView view = frontView();
    const RenderList& list = builder.build(view.frustum, glm::dmat4(1.0), {});
    // Keys: untextured CCW < untextured CW < textured CCW (texture -1 before 0).
    ASSERT_EQ(list.batches.size(), 3u);
    EXPECT_EQ(list.firstBlended, 3u);
    EXPECT_EQ(objectsOf(list), (std::vector<int>{1, 4, 3, 2, 0}));
    EXPECT_EQ(list.batches[0].count, 2);
    EXPECT_EQ(list.batches[1].first, 2);
    EXPECT_EQ(list.batches[1].key.faces, FaceMode::CullCw);
    EXPECT_EQ(list.batches[2].key.texture, image);
}

TEST(RenderList, LevelsAreClampedToTheMeshAndEmptyMeshesAreNotDrawn) {
    scenes::Scene scene = threeCubes();
    scene.meshes[1].indices.clear();  // the middle cube has nothing to draw
    const RenderScene rs(scene, false);
    ASSERT_EQ(rs.levelCount(0), 1);
    ListBuilder builder(rs);
    const std::vector<int> levels{5, -2};  // beyond the one level; object 2: beyond the vector
    DrawFilter filter;
    filter.lodLevels = &levels;
    const display::ScreenView view = frontView();
    const RenderList& list = builder.build(view.frustum, glm::dmat4(1.0), filter);
    EXPECT_EQ(objectsOf(list), (std::vector<int>{0, 2}));
    for (const Draw& d : list.draws) EXPECT_EQ(d.level, 0);
    EXPECT_EQ(list.triangles, 24u);
    ASSERT_EQ(list.batches.size(), 1u);
    EXPECT_EQ(list.batches[0].count, 2);
}

}  // namespace
}  // namespace cavewall::render
