// The bake cache (walls/gl/baker.h): unchanged input does no work, damaged files are re-baked
// one by one, changed options get a new key, and a scene change re-bakes only what it touches.
#include "config/error.h"
#include "scenes/loader.h"
#include "tests/support/gl/gl_test_support.h"
#include "tests/walls/gl/bake_test_scene.h"
#include "walls/bake_cache.h"
#include "walls/depth_file.h"
#include "walls/gl/baker.h"
#include "walls/texture_pager.h"
#include "walls/wall_setup.h"

#include <gmock/gmock.h>

#include <chrono>
#include <fstream>

namespace cavewall::walls::gl {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class BakeCacheTest : public cavewall::testing::GlTest {
protected:
    void SetUp() override {
        cavewall::testing::GlTest::SetUp();
        if (IsSkipped()) return;
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root = cavewall::testing::testOutputFolder("bake_cache") / info->name();
        std::filesystem::remove_all(root);
        request.scene = gl::testing::writeBakeTestScene(root / "scene");
        request.cache = root / "cache";
        request.settings.maxResolution = 32;  // small textures: the cache logic does not depend on size
        request.context = context.get();
    }

    std::filesystem::path root;
    BakeRequest request;
};

std::filesystem::file_time_type modified(const std::filesystem::path& p) { return std::filesystem::last_write_time(p); }

// The manifest without the files' stamps (time, inode): what a re-bake of the same input must
// reproduce exactly (a re-made file has a new time).
std::string withoutStamps(walls::BakeManifest m) {
    for (walls::BakedTexture& t : m.textures) {
        t.mtimeNs = 0;
        t.inode = 0;
    }
    return manifestToJson(m);
}

std::vector<scenes::Image> fakeDecode(const std::filesystem::path&) {
    scenes::Image level;
    level.width = level.height = 4;
    level.rgba.assign(4 * 4 * 4, 255);
    return {level};
}

TEST_F(BakeCacheTest, UnchangedSceneDoesNoWork) {
    std::vector<BakeProgress> progress;
    request.progress = [&](const BakeProgress& p) { progress.push_back(p); };
    const BakeResult first = bakeScene(request);
    const int n = static_cast<int>(first.manifest.textures.size());
    ASSERT_GT(n, 2);
    EXPECT_EQ(first.baked, n);  // an empty cache renders everything
    EXPECT_EQ(first.reused, 0);
    // Progress counts up to the whole plan, ending with everything done exactly once.
    ASSERT_FALSE(progress.empty());
    for (std::size_t i = 1; i < progress.size(); ++i) EXPECT_GE(progress[i].done, progress[i - 1].done);
    EXPECT_EQ(progress.back().done, n);
    EXPECT_EQ(progress.back().total, n);
    EXPECT_EQ(progress.back().baked, n);
    progress.clear();
    const auto manifestTime = modified(first.folder / "manifest.json");
    const auto textureTime = modified(first.folder / first.manifest.textures[0].file);

    const BakeResult second = bakeScene(request);
    EXPECT_EQ(second.folder, first.folder);
    EXPECT_EQ(second.baked, 0);
    EXPECT_EQ(second.reused, n);
    EXPECT_EQ(second.bytesWritten, 0u);
    ASSERT_EQ(progress.size(), 1u);  // one report: everything was found at once
    EXPECT_EQ(progress[0].reused, n);
    EXPECT_EQ(second.manifest, first.manifest);
    EXPECT_EQ(second.hashed, n);  // `bake` reads and checks every listed file
    EXPECT_TRUE(second.warnings.empty());
    for (const walls::BakedTexture& t : first.manifest.textures) EXPECT_NE(t.mtimeNs, 0) << t.file;
    // Nothing was written: neither the manifest nor a texture file.
    EXPECT_EQ(modified(second.folder / "manifest.json"), manifestTime);
    EXPECT_EQ(modified(second.folder / second.manifest.textures[0].file), textureTime);
    // A run's start trusts the stamps: every file's size, time and inode were the manifest's,
    // so none was read.
    request.trustStamps = true;
    const BakeResult third = bakeScene(request);
    EXPECT_EQ(third.hashed, 0);
    EXPECT_EQ(third.reused, n);
}

// Without the caller's context the bake makes its own current; the caller's is current again
// when it returns (a GL call with none current aborts the process in libepoxy).
TEST_F(BakeCacheTest, ABakeWithItsOwnContextLeavesTheCallersCurrent) {
    request.context = nullptr;
    const cavewall::testing::ContextMark mark;
    const BakeResult baked = bakeScene(request);
    EXPECT_GT(baked.baked, 0);  // it rendered, so its own context was current for a while
    EXPECT_EQ(display::gl::Context::current(), context.get());
    EXPECT_TRUE(mark.current());
}

TEST_F(BakeCacheTest, DamagedFileIsReBakedAlone) {
    const BakeResult first = bakeScene(request);
    const int n = static_cast<int>(first.manifest.textures.size());
    struct Damage {
        const char* name;
        void (*apply)(const std::filesystem::path&);
    };
    const Damage damages[] = {
        {"torn",
         [](const std::filesystem::path& f) { std::filesystem::resize_file(f, std::filesystem::file_size(f) / 2); }},
        {"one byte changed",
         [](const std::filesystem::path& f) {
             std::fstream s(f, std::ios::in | std::ios::out | std::ios::binary);
             const auto last = static_cast<std::streamoff>(std::filesystem::file_size(f) / 2);
             s.seekg(last);
             const char c = static_cast<char>(s.get());
             s.seekp(last);
             s.put(static_cast<char>(c ^ 0x01));
         }},
        {"missing", [](const std::filesystem::path& f) { std::filesystem::remove(f); }},
    };
    int victim = 0;
    for (const Damage& d : damages) {
        SCOPED_TRACE(d.name);
        const walls::BakedTexture& t = first.manifest.textures[victim++ % n];
        d.apply(first.folder / t.file);
        ASSERT_FALSE(walls::textureFileValid(first.folder, t));
        const BakeResult again = bakeScene(request);
        EXPECT_EQ(again.baked, 1);  // exactly the damaged one
        EXPECT_EQ(again.reused, n - 1);
        EXPECT_TRUE(walls::textureFileValid(again.folder, again.manifest.textures[t.id]));
        // Rendering is deterministic, so the re-baked file is the original one again.
        EXPECT_EQ(withoutStamps(again.manifest), withoutStamps(first.manifest));
    }
}

// After two texture files are swapped, a bake re-makes both and its manifest lists both, valid:
// the final manifest is written even when it equals the one read at the start, so no manifest
// written after the first re-bake alone is left on disk.
TEST_F(BakeCacheTest, SwappedFilesAreReMadeAndAllListed) {
    const BakeResult first = bakeScene(request);
    const int n = static_cast<int>(first.manifest.textures.size());
    ASSERT_GT(n, 2);
    const std::filesystem::path a = first.folder / first.manifest.textures[0].file;
    const std::filesystem::path b = first.folder / first.manifest.textures[1].file;
    const std::filesystem::path tmp = first.folder / "swap.tmp";
    std::filesystem::rename(a, tmp);
    std::filesystem::rename(b, a);
    std::filesystem::rename(tmp, b);
    const BakeResult again = bakeScene(request);
    EXPECT_EQ(again.baked + again.reused, n)
        << again.baked << " baked, " << again.reused << " reused, " << again.linked << " linked";
    ASSERT_EQ(static_cast<int>(again.manifest.textures.size()), n);
    const walls::BakeManifest onDisk = walls::readManifest(again.folder);
    ASSERT_EQ(static_cast<int>(onDisk.textures.size()), n);
    for (const walls::BakedTexture& t : onDisk.textures)
        EXPECT_TRUE(walls::textureFileValid(again.folder, t)) << t.file;
    EXPECT_EQ(withoutStamps(onDisk), withoutStamps(first.manifest));
}

// Trusting stamps (a run's start): a file whose time changed but not its bytes (touched,
// copied back) is hashed once, kept, and stamped again: the next start reads nothing.
TEST_F(BakeCacheTest, TouchedFileIsHashedOnceAndKept) {
    request.trustStamps = true;
    const BakeResult first = bakeScene(request);
    const int n = static_cast<int>(first.manifest.textures.size());
    const walls::BakedTexture& t = first.manifest.textures[1];
    std::filesystem::last_write_time(first.folder / t.file, modified(first.folder / t.file) + std::chrono::seconds(5));
    const BakeResult again = bakeScene(request);
    EXPECT_EQ(again.hashed, 1);
    EXPECT_EQ(again.baked, 0);
    EXPECT_EQ(again.reused, n);
    EXPECT_NE(again.manifest.textures[1].mtimeNs, t.mtimeNs);
    EXPECT_EQ(walls::readManifest(again.folder), again.manifest);  // the new stamp is on disk
    const BakeResult third = bakeScene(request);
    EXPECT_EQ(third.hashed, 0);
    EXPECT_EQ(third.baked, 0);
}

// A same-size write in place that leaves the file's time as the manifest has it (as a write
// within the clock tick of the stamp would) passes a run's start-up check (stamps trusted); the
// pager's content check refuses it, so the wall falls back and the failure is counted; `bake`,
// which checks every file's content, re-bakes it and names it.
TEST_F(BakeCacheTest, ChangeTheStartUpCheckCannotSeeIsRefusedByThePager) {
    request.trustStamps = true;
    const BakeResult first = bakeScene(request);
    const walls::BakedTexture& t = first.manifest.textures[0];
    const std::filesystem::path file = first.folder / t.file;
    const auto stamped = modified(file);
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        const auto middle = static_cast<std::streamoff>(std::filesystem::file_size(file) / 2);
        f.seekg(middle);
        const char c = static_cast<char>(f.get());
        f.seekp(middle);
        f.put(static_cast<char>(c ^ 0x01));
    }
    std::filesystem::last_write_time(file, stamped);
    const BakeResult again = bakeScene(request);
    EXPECT_EQ(again.hashed, 0);
    EXPECT_EQ(again.baked, 0);

    walls::TexturePager pager(again.folder, again.manifest, 64.0, fakeDecode);
    pager.request({t.id, first.manifest.textures[1].id}, {});
    pager.waitIdle();
    EXPECT_TRUE(pager.hasFailed(t.id));
    EXPECT_FALSE(pager.hasFailed(first.manifest.textures[1].id));
    EXPECT_EQ(pager.stats().failures, 1);
    ASSERT_TRUE(pager.takeNext(false));  // only the intact texture can be uploaded
    EXPECT_FALSE(pager.takeNext(false));

    request.trustStamps = false;
    const BakeResult third = bakeScene(request);
    EXPECT_EQ(third.hashed, static_cast<int>(first.manifest.textures.size()));
    EXPECT_EQ(third.baked, 1);
    EXPECT_TRUE(walls::textureFileValid(third.folder, third.manifest.textures[t.id]));
    ASSERT_EQ(third.warnings.size(), 1u);
    EXPECT_THAT(third.warnings[0], ::testing::StartsWith(file.string() + ": content check failed (expected hash "));
    EXPECT_THAT(third.warnings[0], ::testing::EndsWith("(re-baking it)"));
}

TEST_F(BakeCacheTest, ChangedAlphaGetsANewKey) {
    const BakeResult first = bakeScene(request);
    request.plan.alphaDeg = 20.0;
    const BakeResult second = bakeScene(request);
    EXPECT_NE(second.key, first.key);
    EXPECT_NE(second.folder, first.folder);
    EXPECT_EQ(second.manifest.alphaDeg, 20.0);
    EXPECT_TRUE(std::filesystem::exists(first.folder / "manifest.json"));  // the old bake stays valid
    request.settings.maxResolution = 64;                                   // a bake setting is part of the key too
    EXPECT_NE(bakeScene(request).key, second.key);
}

TEST_F(BakeCacheTest, LevelsOfDetailKeyTheBakeAndFullDetailKeepsItsKey) {
    request.settings.lodTexels = 0.0;
    const BakeResult full = bakeScene(request);
    request.settings.lodTexels = 0.5;
    const BakeResult lod = bakeScene(request);
    // Other pixels, so another folder and other texture keys: the two are never mixed.
    EXPECT_NE(lod.key, full.key);
    ASSERT_EQ(lod.manifest.textures.size(), full.manifest.textures.size());
    EXPECT_EQ(lod.linked, 0);
    for (std::size_t i = 0; i < lod.manifest.textures.size(); ++i)
        EXPECT_NE(lod.manifest.textures[i].file, full.manifest.textures[i].file);
    request.settings.lodTexels = 1.0;  // the tolerance is part of the key
    EXPECT_NE(bakeScene(request).key, lod.key);
}

TEST_F(BakeCacheTest, ALimitBakesASpreadSampleAndTheRestLater) {
    request.limit = 3;
    const BakeResult sample = bakeScene(request);
    request.limit = 0;
    const BakeResult rest = bakeScene(request);
    const int total = static_cast<int>(rest.manifest.textures.size());
    ASSERT_GT(total, 4);
    EXPECT_EQ(sample.baked, 3);
    EXPECT_EQ(rest.reused, 3);
    EXPECT_EQ(rest.baked, total - 3);
    // Every k-th of the pending textures (all of them here), k = total / 3: ids 0, total / 3 and
    // 2 total / 3, rounded down; the manifest lists only what was baked.
    ASSERT_EQ(sample.manifest.textures.size(), 3u);
    EXPECT_EQ(sample.manifest.textures[0].id, 0);
    EXPECT_EQ(sample.manifest.textures[1].id, total / 3);
    EXPECT_EQ(sample.manifest.textures[2].id, 2 * total / 3);
}

TEST_F(BakeCacheTest, SceneChangeReBakesOnlyTheTexturesItTouches) {
    const BakeResult first = bakeScene(request);
    int front = 0;  // textures seen from the front cell: they show the back cell's boxes
    for (const walls::BakedTexture& t : first.manifest.textures) front += t.cell == 0;
    ASSERT_GT(front, 0);
    ASSERT_LT(front, static_cast<int>(first.manifest.textures.size()));
    // Move the red box (back cell): side-0 textures change, side-1 textures (the yellow box in
    // the front cell, seen from the back) do not, and are taken over from the first bake.
    gl::testing::writeBakeTestScene(root / "scene", 0.5);
    const BakeResult second = bakeScene(request);
    EXPECT_NE(second.folder, first.folder);
    EXPECT_EQ(second.baked, front);
    EXPECT_EQ(second.linked, static_cast<int>(first.manifest.textures.size()) - front);
    for (const walls::BakedTexture& t : second.manifest.textures) {
        EXPECT_TRUE(walls::textureFileValid(second.folder, t)) << t.file;
        const walls::BakedTexture& old = first.manifest.textures[t.id];
        EXPECT_EQ(t.file == old.file, t.cell == 1) << t.file;  // same texture key exactly when untouched
    }
}

// What a wall side bakes keys the folder: with the same files and settings, other baked lists
// (as a change to the classification rules gives) must not reuse a complete manifest whose
// textures show the old ones. The side whose list changed is re-rendered; the other side's
// textures are taken over from the first bake.
TEST_F(BakeCacheTest, OtherBakedListsGetANewFolder) {
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(request.scene, &description);
    walls::WallSetup setup = walls::prepareWalls(scene, description, request.plan);
    const BakeResult first = bakeWalls(scene, description, setup, request);
    EXPECT_EQ(bakeWalls(scene, description, setup, request).folder, first.folder);  // same lists: same folder
    int front = 0;
    for (const walls::BakedTexture& t : first.manifest.textures) front += t.cell == 0;
    ASSERT_GT(front, 0);
    // The front cell's textures no longer show the first object they baked.
    std::vector<int>& baked = setup.contents.at({0, 0}).baked;
    ASSERT_GT(baked.size(), 1u);
    baked.erase(baked.begin());
    const BakeResult second = bakeWalls(scene, description, setup, request);
    EXPECT_NE(second.key, first.key);
    EXPECT_NE(second.folder, first.folder);
    EXPECT_EQ(second.baked, front);
    EXPECT_EQ(second.linked, static_cast<int>(first.manifest.textures.size()) - front);
}

// Two textures of one key (one far wall, one sampling point, one resolution) show the same
// pixels: one is rendered, the other is a hard link to its file, and the folder counts it once.
TEST_F(BakeCacheTest, TexturesOfOneKeyShareOneFile) {
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(request.scene, &description);
    walls::WallSetup setup = walls::prepareWalls(scene, description, request.plan);
    const int n = static_cast<int>(setup.plan.textures.size());
    ASSERT_GT(n, 0);
    walls::Texture twin = setup.plan.textures[0];
    twin.id = n;
    setup.plan.textures.push_back(twin);
    const BakeResult result = bakeWalls(scene, description, setup, request);
    EXPECT_EQ(result.baked, n);
    EXPECT_EQ(result.shared, 1);
    ASSERT_EQ(result.manifest.textures.size(), static_cast<std::size_t>(n + 1));
    const walls::BakedTexture& first = result.manifest.textures[0];
    const walls::BakedTexture& second = result.manifest.textures[n];
    EXPECT_NE(first.file, second.file);
    EXPECT_EQ(walls::textureKeyOf(first.file), walls::textureKeyOf(second.file));
    EXPECT_TRUE(walls::textureFileValid(result.folder, second));
    EXPECT_TRUE(std::filesystem::equivalent(result.folder / first.file, result.folder / second.file));
    std::uint64_t bytes = 0;
    for (int i = 0; i < n; ++i) bytes += result.manifest.textures[i].bytes;
    EXPECT_EQ(result.totalBytes, bytes + std::filesystem::file_size(result.folder / "manifest.json"));
}

TEST_F(BakeCacheTest, CorruptManifestIsAWarningAndEverythingIsReBaked) {
    const BakeResult first = bakeScene(request);
    std::ofstream(first.folder / "manifest.json") << "{\"version\": 1, \"key\":";
    const BakeResult again = bakeScene(request);
    EXPECT_EQ(again.baked, static_cast<int>(first.manifest.textures.size()));
    ASSERT_EQ(again.warnings.size(), 1u);
    EXPECT_THAT(again.warnings[0], HasSubstr("manifest.json"));
    EXPECT_EQ(withoutStamps(again.manifest), withoutStamps(first.manifest));
}

TEST_F(BakeCacheTest, BadSettingsAndFoldersAreErrors) {
    request.cache = "/proc/cavewall-cache";  // nobody, not even root, creates folders in /proc
    EXPECT_THAT([&] { bakeScene(request); }, ThrowsMessage<Error>(HasSubstr("/proc/cavewall-cache/")));
    EXPECT_THAT([&] { bakeScene(request); }, ThrowsMessage<Error>(HasSubstr(": cannot create the bake folder")));
    request.cache = root / "cache";
    request.settings.jobs = 0;
    EXPECT_THAT([&] { bakeScene(request); },
                ThrowsMessage<Error>(HasSubstr("bake settings: jobs: expected [1, 64], got 0")));
    request.settings.jobs = 1;
    request.settings.tileSize = 40;
    EXPECT_THAT([&] { bakeScene(request); },
                ThrowsMessage<Error>(HasSubstr("tileSize: expected a multiple of 16 in [16, 1024], got 40")));
    request.settings.tileSize = 64;
    request.settings.lodTexels = 4.5;
    EXPECT_THAT([&] { bakeScene(request); }, ThrowsMessage<Error>(HasSubstr("lodTexels: expected [0, 4], got 4.5")));
    request.settings.lodTexels = 0.5;
    request.settings.drawThreads = 9;
    EXPECT_THAT([&] { bakeScene(request); }, ThrowsMessage<Error>(HasSubstr("drawThreads: expected [1, 8], got 9")));
}

// Textures drawn by several contexts at once (each on its own thread) are the very files one
// context draws: the same names, sizes and hashes in the manifest.
TEST_F(BakeCacheTest, SeveralDrawingThreadsWriteTheSameFiles) {
    request.settings.textureFormat = walls::TextureFormat::Bc1;
    const BakeResult one = bakeScene(request);
    ASSERT_GT(one.baked, 6);
    request.cache = root / "cache-threads";
    request.settings.drawThreads = 3;
    request.settings.jobs = 2;
    const BakeResult three = bakeScene(request);
    EXPECT_EQ(three.baked, one.baked);
    EXPECT_EQ(withoutStamps(three.manifest), withoutStamps(one.manifest));
    EXPECT_EQ(three.trianglesDrawn, one.trianglesDrawn);
}

TEST(BakeFileNames, TextureKeyRoundTripsThroughTheFileName) {
    EXPECT_EQ(textureFileName(7, 0x0123456789abcdefull), "tex_0007_0123456789abcdef.tx");
    EXPECT_EQ(walls::textureKeyOf("tex_0007_0123456789abcdef.tx"), 0x0123456789abcdefull);
    EXPECT_EQ(walls::textureKeyOf("tex_12345_0123456789abcdef.tx"), 0x0123456789abcdefull);  // ids beyond 4 digits
    EXPECT_EQ(walls::textureKeyOf("manifest.json"), std::nullopt);
    EXPECT_EQ(walls::textureKeyOf("tex_0007_0123456789ABCDEF.tx"), std::nullopt);  // walls::hex64 writes lower case
    EXPECT_EQ(walls::textureKeyOf(".tex_0007_0123456789abcdef.tmp-1-0.tx"), std::nullopt);
    // Block-compressed textures (walls/texture_blocks.h) have their own extension.
    EXPECT_EQ(textureFileName(7, 0x0123456789abcdefull, walls::TextureFormat::Bc1), "tex_0007_0123456789abcdef.bct");
    EXPECT_EQ(walls::textureKeyOf("tex_0007_0123456789abcdef.bct"), 0x0123456789abcdefull);
    EXPECT_EQ(walls::textureKeyOf("tex_0007_0123456789abcdef.bc"), std::nullopt);
}

// Depth walls: the wall kind keys the folder; every texture gets a valid depth file of the
// march's depths (halved where both sides are even) whose range is that of its depths; a
// re-bake renders nothing, and a damaged depth file is re-baked (only that texture).
TEST_F(BakeCacheTest, DepthBakesKeyTheirKindAndKeepDepthFilesValid) {
    const BakeResult flat = bakeScene(request);
    request.settings.kind = walls::WallKind::Depth;
    const BakeResult depth = bakeScene(request);
    EXPECT_NE(depth.folder, flat.folder);
    // Depth walls are planned with their own bound (walls::planOptionsFor), so their texture
    // count is their plan's, not the flat one.
    const int n = static_cast<int>(depth.manifest.textures.size());
    ASSERT_GT(n, 0);
    EXPECT_EQ(depth.baked, n);
    for (const walls::BakedTexture& t : depth.manifest.textures) {
        ASSERT_FALSE(t.depthFile.empty());
        EXPECT_TRUE(walls::textureFileValid(depth.folder, t));
        const walls::DepthImage d = walls::readDepthFile(depth.folder / t.depthFile);
        // The march's depths (walls::marchDepths): half the size when both sides are even.
        EXPECT_EQ(glm::ivec2(d.width, d.height), walls::marchDepthSize(t.resolution.x, t.resolution.y));
        // 16-bit codes on disk (walls/depth_file.h): the range read back is the baked one
        // within the codes' precision, and exactly it once clamped as the loader does.
        walls::DepthImage clamped = d;
        walls::clampDepths(clamped, t.depthRange);
        const glm::dvec2 read = walls::depthRange(d);
        EXPECT_NEAR(read.x, t.depthRange.x, walls::depthFileError(t.depthRange.x));
        EXPECT_NEAR(read.y, t.depthRange.y, walls::depthFileError(t.depthRange.y));
        const glm::dvec2 inside = walls::depthRange(clamped);
        EXPECT_GE(inside.x, t.depthRange.x);
        EXPECT_LE(inside.y, t.depthRange.y);
    }
    for (const walls::BakedTexture& t : flat.manifest.textures) EXPECT_TRUE(t.depthFile.empty());
    EXPECT_EQ(bakeScene(request).baked, 0);

    std::ofstream(depth.folder / depth.manifest.textures[0].depthFile, std::ios::binary | std::ios::app) << "x";
    const BakeResult repaired = bakeScene(request);
    EXPECT_EQ(repaired.baked, 1);
    EXPECT_TRUE(walls::textureFileValid(repaired.folder, repaired.manifest.textures[0]));
}

}  // namespace
}  // namespace cavewall::walls::gl
