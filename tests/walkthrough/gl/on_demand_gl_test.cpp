// Baking on demand (walls/gl/background_baker.h) on the two-cell scene from an empty cache: the
// first frame is drawn before any texture is baked (its walls fall back to geometry, none is
// missing), later frames draw the baked textures, the cache then lists every file, and a second
// run finds them all and bakes nothing. The baker is held at its first texture by a latch, so
// what each frame sees does not depend on timing.
#include "tests/support/gl/gl_test_support.h"
#include "tests/walkthrough/gl/runtime_fixture.h"

#include "walls/bake_manifest.h"
#include "walls/frame_select.h"
#include "walls/gl/background_baker.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <latch>
#include <optional>

namespace cavewall::testing {
namespace {

class OnDemandTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (IsSkipped()) return;
        root = testOutputFolder("on_demand") / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::filesystem::remove_all(root);
        request.scene = scene.sceneFile;
        request.cache = root / "cache";       // empty: a cold cache
        request.settings.maxResolution = 32;  // small textures: the order does not depend on size
        // An eye in cell A, facing A|B, where the selection draws A|B from textures alone.
        const walls::FrameSelector selector(scene.walls.plan, scene.walls.table, scene.description);
        for (double x = -9.75; x < -0.25 && !textured; x += 0.25) {
            for (const walls::WallBlend& b : selector.select({x, 1.7, 0.0}).walls)
                if (b.wall == wallIndex(scene.walls, "A|B") && !b.textures.empty() && b.geometryWeight == 0.0)
                    textured = glm::dvec3(x, 1.7, 0.0);
        }
        ASSERT_TRUE(textured) << "no eye on z = 0 in cell A sees A|B as textures alone";
        in.worldFromCave = cavePlacedAt(*textured);
    }

    // A walkthrough drawing `baker`'s textures on cave4 at 32 x 32 per screen.
    std::unique_ptr<walkthrough::gl::Walkthrough> walkthrough(walls::gl::BackgroundBaker& baker) {
        walls::WallSetup setup = scene.walls;
        setup.folder = baker.folder();
        setup.manifest = baker.manifest();
        walkthrough::gl::WalkthroughOptions options;
        options.baker = &baker;
        return std::make_unique<walkthrough::gl::Walkthrough>(scene.scene, scene.description, display, *context, setup,
                                                              options);
    }

    const walkthrough::WallState* wallAB(const walkthrough::FrameResult& r) const {
        for (const walkthrough::WallState& s : r.walls)
            if (s.wall == wallIndex(scene.walls, "A|B")) return &s;
        return nullptr;
    }

    const SmallPlant& scene = twoCells();
    const display::Display display = testDisplay(32);
    std::filesystem::path root;
    walls::gl::BakeRequest request;
    walkthrough::FrameInput in;
    std::optional<glm::dvec3> textured;
};

TEST_F(OnDemandTest, FirstFrameBeforeTheBakeThenBakedTexturesThenNothingToBake) {
    const int total = static_cast<int>(scene.walls.plan.textures.size());
    ASSERT_GT(total, 1);
    std::latch open(1);
    walls::gl::BackgroundBakerOptions options;
    options.beforeBake = [&](int) { open.wait(); };
    {
        walls::gl::BackgroundBaker baker(scene.scene, scene.description, scene.walls, request, options);
        EXPECT_TRUE(baker.manifest().textures.empty());
        EXPECT_EQ(baker.stats().missingAtStart, total);
        auto walk = walkthrough(baker);

        // Frame 0: nothing baked yet; the wall wants textures and is drawn as geometry instead.
        const walkthrough::FrameResult first = walk->renderFrame(in);
        ASSERT_NE(wallAB(first), nullptr);
        EXPECT_TRUE(wallAB(first)->fallback);
        EXPECT_TRUE(wallAB(first)->textures.empty());
        EXPECT_EQ(wallAB(first)->geometryWeight, 1.0);  // never a missing wall
        EXPECT_GE(first.geometryFallbacks, 1);
        EXPECT_EQ(first.texturesBaked, 0);
        EXPECT_EQ(first.texturesToBake, total);  // one of them held at the latch

        open.count_down();
        baker.waitIdle();
        EXPECT_EQ(baker.stats().baked, total);
        EXPECT_EQ(baker.stats().missing, 0);
        // Frame 1 hands every bake to the pager (and asks for the wall's textures); once they
        // are decoded and uploaded, frame 2 draws them.
        in.frame = 1;
        const walkthrough::FrameResult handed = walk->renderFrame(in);
        EXPECT_EQ(handed.texturesBakedNow, total);
        EXPECT_EQ(handed.texturesBaked, total);
        walk->waitForTextures();
        in.frame = 2;
        const walkthrough::FrameResult drawn = walk->renderFrame(in);
        ASSERT_NE(wallAB(drawn), nullptr);
        EXPECT_FALSE(wallAB(drawn)->fallback);
        EXPECT_FALSE(wallAB(drawn)->textures.empty());
        EXPECT_EQ(drawn.geometryFallbacks, 0);
        EXPECT_EQ(drawn.texturesBakedNow, 0);
        EXPECT_EQ(drawn.texturesBaked, total);
        EXPECT_EQ(drawn.texturesToBake, 0);

        // The cache lists every texture of the plan, each file valid (size and hash).
        const walls::BakeManifest listed = walls::readManifest(baker.folder());
        ASSERT_EQ(static_cast<int>(listed.textures.size()), total);
        for (const walls::BakedTexture& t : listed.textures)
            EXPECT_TRUE(walls::textureFileValid(baker.folder(), t)) << t.file;
    }

    // A second run finds everything and bakes nothing.
    walls::gl::BackgroundBaker again(scene.scene, scene.description, scene.walls, request);
    EXPECT_EQ(static_cast<int>(again.manifest().textures.size()), total);
    EXPECT_EQ(again.stats().missingAtStart, 0);
    auto walk = walkthrough(again);
    in.frame = 0;
    walk->renderFrame(in);
    again.waitIdle();
    walk->waitForTextures();
    in.frame = 1;
    const walkthrough::FrameResult r = walk->renderFrame(in);
    EXPECT_EQ(r.texturesBaked, 0);
    EXPECT_EQ(again.stats().baked, 0);
    ASSERT_NE(wallAB(r), nullptr);
    EXPECT_FALSE(wallAB(r)->textures.empty());
}

// A run's start trusts unchanged stamps (BakeRequest::trustStamps); a file flipped in place
// keeping its size, time and inode is caught when the pager pages it in: never drawn, handed
// back to the baker (rebake) and baked again, then drawn.
TEST_F(OnDemandTest, AFileThatFailsItsContentCheckIsBakedAgain) {
    {
        walls::gl::BackgroundBaker first(scene.scene, scene.description, scene.walls, request);
        first.want({}, {}, *textured);
        first.waitIdle();
    }
    const std::filesystem::path folder = std::filesystem::directory_iterator(root / "cache")->path();
    const walls::BakeManifest baked = walls::readManifest(folder);
    ASSERT_FALSE(baked.textures.empty());
    for (const walls::BakedTexture& t : baked.textures) {
        const auto stamp = std::filesystem::last_write_time(folder / t.file);
        std::fstream f(folder / t.file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(-5, std::ios::end);
        const char c = static_cast<char>(f.get());
        f.seekp(-5, std::ios::end);
        f.put(static_cast<char>(c ^ 0x20));
        f.close();
        std::filesystem::last_write_time(folder / t.file, stamp);
    }
    request.trustStamps = true;
    walls::gl::BackgroundBaker baker(scene.scene, scene.description, scene.walls, request);
    EXPECT_EQ(baker.stats().missingAtStart, 0);  // the stamps are unchanged: trusted at the start
    auto walk = walkthrough(baker);
    const walkthrough::FrameResult first = walk->renderFrame(in);
    walk->waitForTextures();
    in.frame = 1;
    const walkthrough::FrameResult refused = walk->renderFrame(in);  // hands the refusals back
    ASSERT_NE(wallAB(refused), nullptr);
    EXPECT_TRUE(wallAB(refused)->textures.empty());  // never drawn
    EXPECT_GE(refused.pager.checkFailures, 1);
    EXPECT_FALSE(first.warnings.empty() && refused.warnings.empty());
    baker.waitIdle();
    EXPECT_GE(baker.stats().rebakes, 1);
    EXPECT_EQ(baker.stats().rebakes, baker.stats().baked);
    in.frame = 2;
    walk->renderFrame(in);  // takes the new bakes
    walk->waitForTextures();
    in.frame = 3;
    const walkthrough::FrameResult drawn = walk->renderFrame(in);
    ASSERT_NE(wallAB(drawn), nullptr);
    EXPECT_FALSE(wallAB(drawn)->textures.empty());
    for (const auto& [id, weight] : wallAB(drawn)->textures) {
        const walls::BakeManifest now = walls::readManifest(folder);
        const auto t = std::find_if(now.textures.begin(), now.textures.end(),
                                    [&, id = id](const walls::BakedTexture& e) { return e.id == id; });
        ASSERT_NE(t, now.textures.end());
        EXPECT_TRUE(walls::textureFileValid(folder, *t)) << t->file;
    }
}

// Depth walls baked on demand: each texture arrives with its depth file and is drawn by the
// depth pass, so a frame is the same image as the same frame drawn from the finished cache by
// a walkthrough that read the manifest at its start: textures baked during the run are drawn
// with their depths, not flat.
TEST_F(OnDemandTest, DepthWallsBakedOnDemandAreDrawnWithTheirDepths) {
    walls::PlanOptions plan;
    const walls::WallSetup depth =
        walls::prepareWalls(scene.scene, scene.description, walls::planOptionsFor(plan, walls::WallKind::Depth, 32));
    request.settings.kind = walls::WallKind::Depth;
    walkthrough::gl::WalkthroughOptions options;
    options.wallKind = walls::WallKind::Depth;
    auto walkthrough = [&](walls::WallSetup setup, walls::gl::BackgroundBaker* baker) {
        options.baker = baker;
        return std::make_unique<walkthrough::gl::Walkthrough>(scene.scene, scene.description, display, *context,
                                                              std::move(setup), options);
    };
    // The eye off every texture's sampling point, where depth and flat walls differ.
    in.worldFromCave = cavePlacedAt(*textured + glm::dvec3(0.0, 0.0, 0.35));
    in.readImages = true;
    std::vector<scenes::ScreenImage> onDemand;
    std::filesystem::path folder;
    {
        walls::gl::BackgroundBaker baker(scene.scene, scene.description, depth, request);
        walls::WallSetup setup = depth;
        setup.folder = folder = baker.folder();
        setup.manifest = baker.manifest();
        auto walk = walkthrough(setup, &baker);
        walk->renderFrame(in);
        baker.waitIdle();
        in.frame = 1;
        walk->renderFrame(in);  // hands the bakes to the pager
        walk->waitForTextures();
        in.frame = 2;
        const walkthrough::FrameResult drawn = walk->renderFrame(in);
        ASSERT_NE(wallAB(drawn), nullptr);
        ASSERT_FALSE(wallAB(drawn)->textures.empty());
        EXPECT_EQ(wallAB(drawn)->geometryWeight, 0.0);
        onDemand = drawn.images;
    }
    const walls::BakeManifest listed = walls::readManifest(folder);
    ASSERT_EQ(listed.textures.size(), depth.plan.textures.size());
    for (const walls::BakedTexture& t : listed.textures) {
        EXPECT_FALSE(t.depthFile.empty()) << t.file;
        EXPECT_TRUE(walls::textureFileValid(folder, t)) << t.file;
    }
    walls::WallSetup cached = depth;
    cached.folder = folder;
    cached.manifest = listed;
    options.synchronousPaging = true;
    auto walk = walkthrough(cached, nullptr);
    const walkthrough::FrameResult fromCache = walk->renderFrame(in);
    ASSERT_EQ(fromCache.images.size(), onDemand.size());
    int differing = 0;
    for (std::size_t i = 0; i < onDemand.size(); ++i)
        differing += onDemand[i].pixels.rgba != fromCache.images[i].pixels.rgba;
    EXPECT_EQ(differing, 0);
    // ... and the flat drawing of the same textures is another image: the test can fail.
    cached.manifest.textures.clear();
    for (walls::BakedTexture t : listed.textures) cached.manifest.textures.push_back((t.depthFile.clear(), t));
    options.wallKind = walls::WallKind::Flat;
    auto flat = walkthrough(cached, nullptr);
    const walkthrough::FrameResult flatFrame = flat->renderFrame(in);
    int flatDiffers = 0;
    for (std::size_t i = 0; i < onDemand.size() && i < flatFrame.images.size(); ++i)
        flatDiffers += onDemand[i].pixels.rgba != flatFrame.images[i].pixels.rgba;
    EXPECT_GT(flatDiffers, 0);
}

// A disk budget of five of the largest texture files: a frame wants at most four textures of the
// one wall now (a 2 x 2 blend) and one more is being added, so eviction always fits the folder
// within it (walls/cache_budget.h never evicts what is wanted now); evicted textures leave the manifest with their files, and the frames keep
// drawing every wall (textures or geometry).
TEST_F(OnDemandTest, DiskBudgetEvictsLeastRecentlyWantedFiles) {
    // Measure one texture's file on a first, unbudgeted bake of the same plan.
    std::uint64_t fileBytes = 0;
    {
        walls::gl::BakeRequest probe = request;
        probe.cache = root / "probe";
        walls::gl::BackgroundBaker baker(scene.scene, scene.description, scene.walls, probe);
        auto walk = walkthrough(baker);
        walk->renderFrame(in);
        baker.waitIdle();
        for (const walls::BakedTexture& t : walls::readManifest(baker.folder()).textures)
            fileBytes = std::max(fileBytes, t.bytes);
    }
    ASSERT_GT(fileBytes, 0u);
    walls::gl::BackgroundBakerOptions options;
    options.cacheBudgetBytes = 5 * fileBytes;
    walls::gl::BackgroundBaker baker(scene.scene, scene.description, scene.walls, request, options);
    auto walk = walkthrough(baker);
    // Walk over cell A facing A|B, row by row, then over cell B facing it back (the CAVE turned
    // by half a turn): the baker fills the budget with A's side first, so B's side must evict.
    std::vector<glm::dmat4> poses;
    for (double z = -4.5; z <= 4.5; z += 1.5)
        for (double x = -9.5; x < 0.0; x += 1.0) poses.push_back(cavePlacedAt({x, 1.7, z}));
    for (double z = -4.5; z <= 4.5; z += 1.5)
        for (double x = 9.5; x > 0.0; x -= 1.0)
            poses.push_back(glm::rotate(cavePlacedAt({x, 1.7, z}), glm::pi<double>(), glm::dvec3(0.0, 1.0, 0.0)));
    for (int i = 0; i < static_cast<int>(poses.size()); ++i) {
        in.frame = i;
        in.worldFromCave = poses[i];
        const walkthrough::FrameResult r = walk->renderFrame(in);
        baker.waitIdle();
        for (const walkthrough::WallState& s : r.walls)
            EXPECT_TRUE(!s.textures.empty() || s.geometryWeight > 0.0) << "frame " << i << ", wall " << s.wall;
    }
    const walls::gl::BackgroundBakeStats stats = baker.stats();
    EXPECT_GT(stats.evictions, 0) << "textures " << scene.walls.plan.textures.size() << ", baked " << stats.baked
                                  << ", cache MB " << stats.cacheMB << ", file " << fileBytes;
    const walls::BakeManifest listed = walls::readManifest(baker.folder());
    std::uint64_t bytes = 0;
    for (const walls::BakedTexture& t : listed.textures) {
        bytes += t.bytes;
        EXPECT_TRUE(walls::textureFileValid(baker.folder(), t)) << t.file;
    }
    // Listed files and the budget's count agree; the folder holds no unlisted texture file.
    EXPECT_EQ(bytes, static_cast<std::uint64_t>(std::llround(stats.cacheMB * 1024.0 * 1024.0)));
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(baker.folder()))
        files += entry.path().extension() == ".tx" ? 1 : 0;
    EXPECT_EQ(files, static_cast<int>(listed.textures.size()));
    EXPECT_LE(bytes, 5 * fileBytes);
}

}  // namespace
}  // namespace cavewall::testing
