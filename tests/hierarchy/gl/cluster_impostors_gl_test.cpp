// Maciel & Shirley's (1995) cluster impostors on llvmpipe (hierarchy/gl/cluster_impostors.h,
// cluster_costs.h): a textured box seen from one of its sampling eyes shows what full detail
// shows; the average box is less accurate than the textured one; impostors and costs come back
// from the cache.
#include "render/gl/scene_renderer.h"
#include "hierarchy/cluster_tree.h"
#include "metrics/flip.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/walls/gl/bake_test_scene.h"
#include "hierarchy/gl/cluster_costs.h"
#include "hierarchy/gl/cluster_impostors.h"
#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <sys/resource.h>
#include <fstream>
#include <nlohmann/json.hpp>

namespace cavewall::testing {
namespace {

// Three boxes of three colours, 2 m apart at most: one cluster over them (a 1 x 1 x 1 grid).
scenes::Scene threeBoxes() {
    scenes::Scene s;
    s.name = "three-boxes";
    walls::gl::testing::addBox(s, {1.0f, 1.5f, 1.0f}, {0.9f, 0.1f, 0.1f, 1}, {0.0, 0.75, 0.0}, "red");
    walls::gl::testing::addBox(s, {0.6f, 0.6f, 0.6f}, {0.1f, 0.8f, 0.2f, 1}, {1.5, 0.3, 0.5}, "green");
    walls::gl::testing::addBox(s, {0.5f, 1.0f, 0.5f}, {0.1f, 0.2f, 0.9f, 1}, {0.5, 0.5, -1.5}, "blue");
    return s;
}

hierarchy::ClusterModel modelOf(const scenes::Scene& s) {
    hierarchy::ClusterModel m;
    std::vector<scenes::Bounds> bounds;
    for (const scenes::Object& o : s.objects) {
        bounds.push_back(o.worldBounds);
        m.objectTriangles.push_back(s.meshes[o.mesh].triangleCount());
    }
    m.tree = hierarchy::buildClusterTree(bounds, {1, 1, 1});
    return m;
}

class ClusterImpostorsTest : public GlTest {};

TEST_F(ClusterImpostorsTest, ATexturedBoxShowsFullDetailAtItsSamplingEyeAndIsCached) {
    const scenes::Scene scene = threeBoxes();
    const std::filesystem::path cache = testOutputFolder("cluster-impostors") / "cache";
    std::filesystem::remove_all(cache);
    hierarchy::ClusterModel model = modelOf(scene);
    ASSERT_EQ(model.tree.root, 3);  // three leaves, then the cluster
    // Face textures of 64 texels along the longer side, as many as the 64-pixel image's face.
    const hierarchy::gl::ClusterBakeSettings settings{64, 64, 0.35f};
    hierarchy::gl::ClusterImpostors impostors(scene, model, settings, cache);
    EXPECT_EQ(impostors.stats().made, 1);
    ASSERT_TRUE(model.hasImpostors[3]);
    const scenes::Bounds box = hierarchy::impostorBox(model.tree.nodes[3].bounds);
    // From face +x's centre-region eye only that face is towards the eye, and its texture is
    // exactly what the eye sees through it: the impostor differs from full detail only by
    // resampling the texture (texel centres on pixel centres along the longer side).
    const glm::dvec3 eye = hierarchy::samplingEye(box, 0, 0);
    const display::ScreenQuad screen = hierarchy::boxFace(box, 0);
    const scenes::Image full = impostors.image(3, hierarchy::ClusterRep::Full, screen, eye, {64, 64});
    const scenes::Image textured = impostors.image(3, hierarchy::ClusterRep::Textured, screen, eye, {64, 64});
    const scenes::Image average = impostors.image(3, hierarchy::ClusterRep::Average, screen, eye, {64, 64});
    const double texturedError = metrics::flip(textured, full, {10.0}).mean;
    const double averageError = metrics::flip(average, full, {10.0}).mean;
    EXPECT_LT(texturedError, 0.05);
    EXPECT_LT(texturedError, averageError);
    // Measured accuracy from the six directions: in [0, 1], textured above average on the whole.
    const hierarchy::ClusterAccuracy a = model.accuracy[3];
    double sumTextured = 0.0, sumAverage = 0.0;
    for (int d = 0; d < hierarchy::kAccuracyDirections; ++d) {
        EXPECT_GE(a.textured[d], 0.0);
        EXPECT_LE(a.textured[d], 1.0);
        sumTextured += a.textured[d];
        sumAverage += a.average[d];
    }
    EXPECT_GT(sumTextured, sumAverage);
    // Again with the same cache: read, not made, the same accuracies.
    hierarchy::ClusterModel again = modelOf(scene);
    hierarchy::gl::ClusterImpostors cached(scene, again, settings, cache);
    EXPECT_EQ(cached.stats().made, 0);
    EXPECT_EQ(cached.stats().reused, 1);
    EXPECT_EQ(again.accuracy[3], a);
    // A changed object changes the cluster's key: made again.
    scenes::Scene moved = threeBoxes();
    moved.objects[0].worldFromModel[3].x += 0.25;
    moved.updateObjectBounds();
    hierarchy::ClusterModel third = modelOf(moved);
    hierarchy::gl::ClusterImpostors remade(moved, third, settings, cache);
    EXPECT_EQ(remade.stats().made, 1);
}

// A flipped byte in a cached face texture (same size, same time) is caught by its content
// check: the cluster is made again, counted, and the file named once; then it reads again. A
// folder of the older version (no hashes) is made again, said in one line.
TEST_F(ClusterImpostorsTest, AFlippedOrStaleImpostorIsMadeAgainAndSaidOnce) {
    const scenes::Scene scene = threeBoxes();
    const std::filesystem::path cache = testOutputFolder("cluster-impostors-check") / "cache";
    std::filesystem::remove_all(cache);
    const hierarchy::gl::ClusterBakeSettings settings{16, 16, 0.35f};
    hierarchy::ClusterModel first = modelOf(scene);
    ASSERT_EQ(hierarchy::gl::ClusterImpostors(scene, first, settings, cache).stats().made, 1);
    const std::filesystem::path folder = std::filesystem::directory_iterator(cache / "clusters")->path();
    const std::filesystem::path file = folder / "f2r3.tx";
    const auto stamp = std::filesystem::last_write_time(file);
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(-20, std::ios::end);
        const char c = static_cast<char>(f.get());
        f.seekp(-20, std::ios::end);
        f.put(static_cast<char>(c ^ 0x55));
    }
    std::filesystem::last_write_time(file, stamp);
    hierarchy::ClusterModel second = modelOf(scene);
    const hierarchy::gl::ClusterImpostors flipped(scene, second, settings, cache);
    EXPECT_EQ(flipped.stats().made, 1);
    EXPECT_EQ(flipped.stats().checkFailures, 1);
    ASSERT_EQ(flipped.stats().warnings.size(), 1u);
    EXPECT_THAT(flipped.stats().warnings[0],
                ::testing::StartsWith(file.string() + ": content check failed (expected hash "));
    EXPECT_THAT(flipped.stats().warnings[0], ::testing::EndsWith("(making the cluster's impostors again)"));
    hierarchy::ClusterModel third = modelOf(scene);
    const hierarchy::gl::ClusterImpostors again(scene, third, settings, cache);
    EXPECT_EQ(again.stats().reused, 1);
    EXPECT_TRUE(again.stats().warnings.empty());

    // cluster.json as the older version wrote it: no "files".
    nlohmann::json j = nlohmann::json::parse(std::ifstream(folder / "cluster.json"));
    j["version"] = 1;
    j.erase("files");
    std::ofstream(folder / "cluster.json") << j.dump();
    hierarchy::ClusterModel fourth = modelOf(scene);
    const hierarchy::gl::ClusterImpostors stale(scene, fourth, settings, cache);
    EXPECT_EQ(stale.stats().made, 1);
    EXPECT_EQ(stale.stats().stale, 1);
    ASSERT_EQ(stale.stats().warnings.size(), 1u);
    EXPECT_THAT(stale.stats().warnings[0], ::testing::HasSubstr("1 cluster folders of an older version without "
                                                                "content checks (expected version 2): made again"));
}

// The files of this folder and below whose names do not end in one of `kept`.
std::vector<std::string> filesIn(const std::filesystem::path& folder) {
    std::vector<std::string> names;
    if (!std::filesystem::exists(folder)) return names;
    for (const auto& e : std::filesystem::recursive_directory_iterator(folder))
        if (e.is_regular_file()) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A full disk while impostors are written (a file size limit: writes fail as they would on a
// full disk): the error names the file, and what is left is no cluster.json and no temporary
// file, so the next run makes the cluster again instead of trusting a torn file.
TEST_F(ClusterImpostorsTest, AFullDiskLeavesNothingTheNextRunTrusts) {
    const scenes::Scene scene = threeBoxes();
    const std::filesystem::path cache = testOutputFolder("cluster-impostors-full") / "cache";
    std::filesystem::remove_all(cache);
    const hierarchy::gl::ClusterBakeSettings settings{64, 16, 0.35f};
    rlimit before{};
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
    const auto handler = std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG
    rlimit small = before;
    small.rlim_cur = 2048;  // bytes: a 64-texel face's MIP file is larger
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    hierarchy::ClusterModel first = modelOf(scene);
    std::string message;
    try {
        hierarchy::gl::ClusterImpostors impostors(scene, first, settings, cache);
    } catch (const Error& e) {
        message = e.what();
    }
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &before), 0);
    std::signal(SIGXFSZ, handler);
    EXPECT_THAT(message, ::testing::HasSubstr((cache / "clusters").string()));
    EXPECT_THAT(message, ::testing::HasSubstr("f0r0.tx"));
    EXPECT_THAT(message, ::testing::HasSubstr("File too large"));
    for (const std::string& name : filesIn(cache)) {
        SCOPED_TRACE(name);
        EXPECT_NE(name, "cluster.json");
        EXPECT_EQ(name.find(".tmp"), std::string::npos);
    }
    hierarchy::ClusterModel second = modelOf(scene);
    const hierarchy::gl::ClusterImpostors again(scene, second, settings, cache);
    EXPECT_EQ(again.stats().made, 1);
    EXPECT_TRUE(again.stats().warnings.empty());
}

// A cache folder the run cannot make: the error names the folder and why. Its parent is a file,
// which stops root too (file modes do not).
TEST_F(ClusterImpostorsTest, ACacheFolderThatCannotBeMadeIsNamed) {
    const scenes::Scene scene = threeBoxes();
    const std::filesystem::path cache = testOutputFolder("cluster-impostors-blocked") / "cache";
    std::filesystem::remove_all(cache);
    std::filesystem::create_directories(cache);
    std::ofstream(cache / "clusters") << "not a folder";
    hierarchy::ClusterModel model = modelOf(scene);
    EXPECT_THAT(
        [&] {
            hierarchy::gl::ClusterImpostors(scene, model, {16, 16, 0.35f}, cache);
        },
        ::testing::ThrowsMessage<Error>(
            ::testing::AllOf(::testing::HasSubstr((cache / "clusters").string() + "/"),
                             ::testing::HasSubstr("cannot create the cluster cache folder (Not a directory)"))));
    EXPECT_EQ(filesIn(cache), std::vector<std::string>{"clusters"});  // nothing written beside it
}

TEST_F(ClusterImpostorsTest, CostsAreMeasuredPositiveAndCachedPerRendererAndResolution) {
    const scenes::Scene scene = threeBoxes();
    const std::filesystem::path cache = testOutputFolder("cluster-costs") / "cache";
    std::filesystem::remove_all(cache);
    hierarchy::ClusterModel model = modelOf(scene);
    hierarchy::gl::ClusterImpostors impostors(scene, model, {16, 32, 0.35f}, cache);
    render::gl::SceneRenderer renderer(scene);
    const hierarchy::gl::MeasuredCosts first =
        hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "test renderer", cache);
    EXPECT_FALSE(first.cached);
    EXPECT_GT(first.costs.msPerTriangle, 0.0);
    EXPECT_GE(first.costs.msPerObject, 0.0);
    EXPECT_GT(first.costs.texturedBoxMs, 0.0);
    EXPECT_GT(first.costs.averageBoxMs, 0.0);
    const hierarchy::gl::MeasuredCosts second =
        hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "test renderer", cache);
    EXPECT_TRUE(second.cached);
    EXPECT_EQ(second.costs, first.costs);
    EXPECT_EQ(second.file, first.file);
    // Another renderer measures again.
    EXPECT_FALSE(hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "other renderer", cache).cached);
    // So does another resolution (the display's own fill), into its own file; 256 is the default.
    const hierarchy::gl::MeasuredCosts at64 =
        hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "test renderer", cache, 64);
    EXPECT_FALSE(at64.cached);
    EXPECT_NE(at64.file, first.file);
    EXPECT_TRUE(
        hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "test renderer", cache, 64).cached);
    EXPECT_TRUE(
        hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "test renderer", cache, 256).cached);
    EXPECT_THAT(
        [&] { hierarchy::gl::measureClusterCosts(renderer, impostors, model, scene, "test renderer", cache, 0); },
        ::testing::ThrowsMessage<Error>(::testing::HasSubstr("resolution: expected 1 to 16384 pixels, got 0")));
}

}  // namespace
}  // namespace cavewall::testing
