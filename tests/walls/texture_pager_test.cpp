#include "walls/texture_pager.h"

#include "walls/depth_file.h"
#include "walls/texture_blocks.h"
#include "walls/texture_mips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>

namespace cavewall::walls {
namespace {

// Ten small files, tex_0 ... tex_9; the pager checks their sizes and hashes against the
// manifest before and after decoding them.
std::filesystem::path folder() {
    const char* env = std::getenv("CAVEWALL_TEST_OUTPUT");
    // One folder per test: ctest may run them in parallel, and one of them swaps files.
    const auto dir = std::filesystem::path(env ? env : CAVEWALL_BINARY_DIR "/test-output") / "pager" /
                     ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::create_directories(dir);
    for (int i = 0; i < 10; ++i) std::ofstream(dir / ("tex_" + std::to_string(i))) << "texture " << i;
    return dir;
}

// Ten textures of 256 KiB each once decoded (one 256x256 RGBA8 level); tex_7 is broken.
BakeManifest manifest() {
    const auto dir = folder();
    BakeManifest m;
    for (int i = 0; i < 10; ++i) {
        const std::string file = "tex_" + std::to_string(i);
        m.textures.push_back({i,
                              0,
                              0,
                              {},
                              {256, 256},
                              file,
                              std::filesystem::file_size(dir / file),
                              contentHashFile(dir / file).value()});
    }
    return m;
}

std::atomic<int> decodes{0};

std::vector<scenes::Image> fakeDecode(const std::filesystem::path& p) {
    ++decodes;
    if (p.filename() == "tex_7") throw Error("tex_7: torn file");
    scenes::Image level;
    level.width = level.height = 256;
    level.rgba.assign(256 * 256 * 4, 128);
    return {level};
}

constexpr std::size_t kBytes = 256 * 256 * 4;

// Everything ready for upload, in priority order.
std::vector<DecodedTexture> takeAll(TexturePager& pager) {
    std::vector<DecodedTexture> out;
    while (std::optional<DecodedTexture> d = pager.takeNext(false)) out.push_back(std::move(*d));
    return out;
}

// Uploads everything ready, as walls::gl::TextureStore::updateAll does.
void uploadAll(TexturePager& pager) {
    pager.waitIdle();
    for (const DecodedTexture& d : takeAll(pager)) pager.markResident(d.id, d.bytes);
}

TEST(TexturePager, DecodesWhatIsWantedAndCountsMisses) {
    TexturePager pager(folder(), manifest(), 4.0, fakeDecode);
    pager.request({1, 2}, {3});
    EXPECT_EQ(pager.stats().misses, 2);  // 1 and 2 were wanted now and not resident
    uploadAll(pager);
    EXPECT_TRUE(pager.isResident(1) && pager.isResident(2) && pager.isResident(3));
    pager.request({1, 2}, {});
    const PagerStats s = pager.stats();
    EXPECT_EQ(s.misses, 2);  // no new misses
    EXPECT_EQ(s.resident, 3);
    EXPECT_EQ(s.pageIns, 3);
    EXPECT_NEAR(s.residentMB, 0.75, 1e-12);
}

TEST(TexturePager, EvictsTheLeastRecentlyWantedWithinTheBudget) {
    TexturePager pager(folder(), manifest(), 0.8, fakeDecode);  // room for three
    for (int id : {0, 1, 2}) {
        pager.request({id}, {});
        uploadAll(pager);
    }
    EXPECT_TRUE(pager.takeEvictions().empty());
    pager.request({3}, {});
    uploadAll(pager);
    EXPECT_EQ(pager.takeEvictions(), std::vector<int>{0});  // the oldest wish goes
    EXPECT_FALSE(pager.isResident(0));
    EXPECT_TRUE(pager.isResident(3));
}

TEST(TexturePager, NeverEvictsWhatIsWantedNowUnderATinyBudget) {
    TexturePager pager(folder(), manifest(), 0.3, fakeDecode);  // room for one
    std::mt19937 rng(1);
    for (int frame = 0; frame < 200; ++frame) {
        const std::vector<int> now{int(rng() % 10), int(rng() % 10)};
        pager.request(now, {int(rng() % 10)});
        uploadAll(pager);
        pager.takeEvictions();
        for (int id : now) {
            if (id != 7) {  // tex_7 never decodes
                EXPECT_TRUE(pager.isResident(id)) << "frame " << frame << " texture " << id;
            }
        }
    }
}

// Baking on demand: a texture the pager did not know at the start is neither decoded nor counted
// as a miss until it is added; a removed one (its file evicted from the disk) is never decoded.
TEST(TexturePager, TexturesAddedDuringTheRunArePagedAndRemovedOnesAreNot) {
    BakeManifest all = manifest();
    BakeManifest start = all;
    start.textures.resize(2);  // only tex_0 and tex_1 baked when the run begins
    TexturePager pager(folder(), start, 4.0, fakeDecode);
    pager.request({0, 4}, {5});
    uploadAll(pager);
    EXPECT_TRUE(pager.isResident(0));
    EXPECT_FALSE(pager.isResident(4));
    EXPECT_EQ(pager.stats().misses, 1);  // 4 is not a texture of the pager yet: not a miss
    pager.addTexture(all.textures[4]);
    pager.request({0, 4}, {});
    uploadAll(pager);
    EXPECT_TRUE(pager.isResident(4));
    pager.removeTexture(1);
    decodes = 0;
    pager.request({1}, {});
    uploadAll(pager);
    EXPECT_FALSE(pager.isResident(1));
    EXPECT_EQ(decodes, 0);
    // A failed texture baked again is tried again.
    pager.addTexture(all.textures[7]);
    pager.request({7}, {});
    pager.waitIdle();
    EXPECT_TRUE(pager.hasFailed(7));
    pager.addTexture(all.textures[7]);
    EXPECT_FALSE(pager.hasFailed(7));
}

TEST(TexturePager, BrokenFilesFailOnceAndAreNotRetried) {
    TexturePager pager(folder(), manifest(), 4.0, fakeDecode);
    decodes = 0;
    pager.request({7}, {});
    pager.waitIdle();
    EXPECT_TRUE(pager.hasFailed(7));
    pager.request({7}, {});
    pager.waitIdle();
    EXPECT_EQ(decodes, 1);
    EXPECT_EQ(pager.stats().failures, 1);
    EXPECT_TRUE(takeAll(pager).empty());
}

// A decoder that gives no level, or a level of zero size, fails the texture: the uploader is
// never handed one (it would stay pending for good).
TEST(TexturePager, ADecodeWithNoTexelsFailsTheTexture) {
    TexturePager pager(folder(), manifest(), 4.0, [](const std::filesystem::path& p) {
        scenes::Image level;
        level.width = p.filename() == "tex_1" ? 0 : 4;
        level.height = 4;
        level.rgba.assign(static_cast<std::size_t>(level.width) * 4 * 4, 9);
        return p.filename() == "tex_2" ? std::vector<scenes::Image>{} : std::vector<scenes::Image>{level};
    });
    pager.request({0, 1, 2}, {});
    pager.waitIdle();
    EXPECT_FALSE(pager.hasFailed(0));
    EXPECT_TRUE(pager.hasFailed(1));
    EXPECT_TRUE(pager.hasFailed(2));
    EXPECT_EQ(pager.stats().failures, 2);
    const std::vector<DecodedTexture> ready = takeAll(pager);
    ASSERT_EQ(ready.size(), 1u);
    EXPECT_EQ(ready[0].id, 0);
}

// Files swapped on disk during a run are never decoded and drawn.
TEST(TexturePager, FilesThatDoNotMatchTheManifestAreNeverDrawn) {
    const BakeManifest m = manifest();
    const auto dir = folder();
    std::filesystem::copy_file(dir / "tex_4", dir / "tex_3", std::filesystem::copy_options::overwrite_existing);
    std::ofstream(dir / "tex_5", std::ios::app) << "!";  // grown by one byte
    TexturePager pager(dir, m, 4.0, fakeDecode);
    pager.request({3, 4, 5}, {});
    pager.waitIdle();
    std::vector<int> ready;
    for (const DecodedTexture& d : takeAll(pager)) ready.push_back(d.id);
    EXPECT_EQ(ready, std::vector<int>{4});
    EXPECT_TRUE(pager.hasFailed(3));
    EXPECT_TRUE(pager.hasFailed(5));
    EXPECT_EQ(pager.stats().failures, 2);
}

// The pacer (walls/upload_pacer.h) is told what waits: readyBytes() counts what is decoded
// and not yet taken.
TEST(TexturePager, ReadyBytesCountWhatWaitsForUpload) {
    TexturePager pager(folder(), manifest(), 4.0, fakeDecode);
    pager.request({0, 1, 2}, {3, 4, 5});
    pager.waitIdle();
    EXPECT_EQ(pager.readyBytes(), 6 * kBytes);
    std::vector<int> ids;
    for (int i = 0; i < 3; ++i) ids.push_back(pager.takeNext(true)->id);
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<int>{0, 1, 2}));  // the three wanted now, no prefetch
    EXPECT_FALSE(pager.takeNext(true));
    EXPECT_EQ(pager.readyBytes(), 3 * kBytes);
    EXPECT_EQ(takeAll(pager).size(), 3u);
    EXPECT_EQ(pager.readyBytes(), 0u);
}

// An uploader that puts a texture up over frames (walls::gl::TextureStore's bands) takes it with
// takeNext: wanted-now textures first, and a taken texture is not decoded again while it waits
// for markResident, however often it is requested meanwhile.
TEST(TexturePager, TakeNextGivesWantedNowFirstAndATakenTextureIsNotDecodedAgain) {
    TexturePager pager(folder(), manifest(), 4.0, fakeDecode);
    pager.request({}, {3, 4});
    pager.waitIdle();
    pager.request({4}, {3});
    EXPECT_TRUE(pager.wantedNow(4));
    EXPECT_FALSE(pager.wantedNow(3));
    const int before = decodes;
    std::optional<DecodedTexture> first = pager.takeNext(false);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->id, 4);             // wanted now, though decoded second
    EXPECT_FALSE(pager.takeNext(true));  // no other wanted-now texture is ready
    std::optional<DecodedTexture> second = pager.takeNext(false);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->id, 3);
    EXPECT_FALSE(pager.takeNext(false));
    for (int frame = 0; frame < 3; ++frame) pager.request({4}, {3});  // both still in flight
    pager.waitIdle();
    EXPECT_EQ(decodes, before);
    EXPECT_EQ(pager.readyBytes(), 0u);
    pager.markResident(4, first->bytes);
    pager.markResident(3, second->bytes);
    EXPECT_TRUE(pager.isResident(3) && pager.isResident(4));
}

// Block-compressed files (walls/texture_blocks.h) are paged as blocks and count their GPU
// bytes: a 256 x 256 BC1 texture with its MIP chain is 43,704 bytes (8 bytes per 4 x 4 block:
// 32,768 + 8,192 + 2,048 + 512 + 128 + 32 + 8 + 8 + 8), not RGBA8's 349,524.
TEST(TexturePager, PagesBlockFilesAsCompressedBytes) {
    const auto dir = folder();
    scenes::Image image{"grey", 256, 256, std::vector<std::uint8_t>(256 * 256 * 4, 200)};
    BakeManifest m;
    for (int i = 0; i < 2; ++i) {
        const std::string file = "tex_" + std::to_string(i) + ".bct";
        writeBlockFile(dir / file, encodeLevels(premultipliedMipChain(image), TextureFormat::Bc1));
        m.textures.push_back({i,
                              0,
                              0,
                              {},
                              {256, 256},
                              file,
                              std::filesystem::file_size(dir / file),
                              contentHashFile(dir / file).value()});
    }
    TexturePager pager(dir, m, 4.0, readBakedTexture);
    pager.request({0, 1}, {});
    pager.waitIdle();
    const std::vector<DecodedTexture> ready = takeAll(pager);
    ASSERT_EQ(ready.size(), 2u);
    for (const DecodedTexture& d : ready) {
        EXPECT_EQ(d.levels.format, TextureFormat::Bc1);
        EXPECT_EQ(d.levels.count(), 9u);
        EXPECT_EQ(d.bytes, 43704u);
        pager.markResident(d.id, d.bytes);
    }
    EXPECT_DOUBLE_EQ(pager.stats().residentMB, 2 * 43704 / (1024.0 * 1024.0));
}

// Two real block files and a third, as a bake lists them; `flip` flips one byte of texture 0's
// file in place (same size), `swap` swaps the files of textures 1 and 2 on disk after the
// manifest was written. The pager's own decoder (none given) decodes from the checked bytes.
struct Damaged {
    std::filesystem::path dir;
    BakeManifest manifest;
};
Damaged damagedBlockFiles(bool flip, bool swap) {
    Damaged d{folder(), {}};
    for (int i = 0; i < 3; ++i) {
        const scenes::Image image{"grey", 64, 64, std::vector<std::uint8_t>(64 * 64 * 4, std::uint8_t(60 + 60 * i))};
        const std::string file = "tex_" + std::to_string(i) + ".bct";
        writeBlockFile(d.dir / file, encodeLevels(premultipliedMipChain(image), TextureFormat::Bc1));
        d.manifest.textures.push_back({i,
                                       0,
                                       0,
                                       {},
                                       {64, 64},
                                       file,
                                       std::filesystem::file_size(d.dir / file),
                                       contentHashFile(d.dir / file).value()});
    }
    if (flip) {
        std::fstream f(d.dir / "tex_0.bct", std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(40);
        const char c = static_cast<char>(f.get());
        f.seekp(40);
        f.put(static_cast<char>(c ^ 0x10));
    }
    if (swap) {
        std::filesystem::rename(d.dir / "tex_1.bct", d.dir / "swap.bct");
        std::filesystem::rename(d.dir / "tex_2.bct", d.dir / "tex_1.bct");
        std::filesystem::rename(d.dir / "swap.bct", d.dir / "tex_2.bct");
    }
    return d;
}

TEST(TexturePager, FlippedAndSwappedFilesAreRefusedCountedAndReportedOnce) {
    const Damaged d = damagedBlockFiles(true, true);
    TexturePager pager(d.dir, d.manifest, 4.0, {});
    pager.request({0, 1, 2}, {});
    pager.waitIdle();
    EXPECT_TRUE(takeAll(pager).empty());  // none is drawn: each wall falls back
    EXPECT_EQ(pager.stats().failures, 3);
    EXPECT_EQ(pager.stats().checkFailures, 3);
    const std::vector<std::string> warnings = pager.takeWarnings();
    ASSERT_EQ(warnings.size(), 3u);
    // The flipped file has its size: its hash tells. The swapped ones (compressed to other
    // sizes) fail on their size first.
    EXPECT_THAT(warnings, ::testing::Contains(::testing::StartsWith((d.dir / "tex_0.bct").string() +
                                                                    ": content check failed (expected hash ")));
    for (const std::string& w : warnings) EXPECT_THAT(w, ::testing::EndsWith("(not drawn: the wall falls back)"));
    EXPECT_THAT(warnings, ::testing::Contains(::testing::HasSubstr("tex_1.bct: expected ")));
    EXPECT_THAT(warnings, ::testing::Contains(::testing::HasSubstr("tex_2.bct: expected ")));
    // Baking on demand bakes the refused ones again (walls::gl::BackgroundBaker::rebake).
    EXPECT_THAT(pager.takeRefused(), ::testing::UnorderedElementsAre(0, 1, 2));
    EXPECT_TRUE(pager.takeRefused().empty());
    // Wanted again: neither decoded again nor reported again.
    pager.request({0, 1, 2}, {});
    pager.waitIdle();
    EXPECT_TRUE(takeAll(pager).empty());
    EXPECT_TRUE(pager.takeWarnings().empty());
    EXPECT_EQ(pager.stats().checkFailures, 3);
}

TEST(TexturePager, IntactBlockFilesPageFromTheBytesTheyChecked) {
    const Damaged d = damagedBlockFiles(false, false);
    TexturePager pager(d.dir, d.manifest, 4.0, {});
    pager.request({0, 1, 2}, {});
    pager.waitIdle();
    EXPECT_EQ(takeAll(pager).size(), 3u);
    EXPECT_EQ(pager.stats().failures, 0);
    EXPECT_TRUE(pager.takeWarnings().empty());
}

// A decoded texture says where it has content (coveredRect with kCoveredMargin texels), made on
// the pager's thread: the flat pass draws only that part of its wall.
TEST(TexturePager, FindsWhereATextureHasContent) {
    const auto dir = folder();
    scenes::Image image{"patch", 256, 256, std::vector<std::uint8_t>(256 * 256 * 4, 0)};
    for (int y = 100; y < 140; ++y)
        for (int x = 32; x < 64; ++x) std::fill_n(&image.rgba[(std::size_t(y) * 256 + x) * 4], 4, std::uint8_t(255));
    const std::string file = "patch.bct";
    writeBlockFile(dir / file, encodeLevels(premultipliedMipChain(image), TextureFormat::Bc1));
    BakeManifest m;
    m.textures.push_back(
        {0, 0, 0, {}, {256, 256}, file, std::filesystem::file_size(dir / file), contentHashFile(dir / file).value()});
    TexturePager pager(dir, m, 4.0, readBakedTexture);
    pager.request({0}, {});
    pager.waitIdle();
    const std::vector<DecodedTexture> ready = takeAll(pager);
    ASSERT_EQ(ready.size(), 1u);
    const double m8 = kCoveredMargin;
    EXPECT_EQ(ready[0].content.lo, glm::dvec2(32 - m8, 100 - m8) / 256.0);
    EXPECT_EQ(ready[0].content.hi, glm::dvec2(64 + m8, 140 + m8) / 256.0);
}

// Depth walls: a texture whose manifest entry lists a depth file gets its depths with the colour
// (decoded, clamped into the baked range, with skip blocks, sampling point and range) and counts
// their GPU bytes against the budget; a damaged or mismatched depth file fails the texture like
// a bad colour file.
TEST(TexturePager, PagesADepthWallsDepthWithItsColourAndBudgetsBoth) {
    const auto dir = folder();
    BakeManifest m = manifest();
    // The nearest depth one whose code decodes nearer, the farthest one whose code decodes
    // farther: only clamping brings them back exactly.
    auto roundsTo = [](float start, bool nearer) {
        for (float d = start;; d += 0.001f) {
            const float back = decodeDepth(encodeDepth(d));
            if (nearer ? back < d : back > d) return d;
        }
    };
    const float nearest = roundsTo(0.5f, true), farthest = roundsTo(5.0f, false);
    // Written halved for the march (marchDepths), as the bake writes it: each 2 x 2 block its
    // nearest depth. Block (0, 0) is empty, (1, 0) holds the nearest depth beside 2 m, (2, 0) is
    // all the farthest.
    DepthImage depth{256, 256, std::vector<float>(256 * 256, 2.0f)};
    for (int k : {0, 1, 256, 257}) depth.depth[k] = kNoSurface;
    depth.depth[3] = nearest;
    for (int k : {4, 5, 260, 261}) depth.depth[k] = farthest;
    auto addDepth = [&](BakedTexture& t, const DepthImage& image) {
        t.depthFile = "depth_" + std::to_string(t.id) + ".depth.tif";
        writeDepthFile(dir / t.depthFile, marchDepths(image));  // as the bake writes it
        t.depthBytes = std::filesystem::file_size(dir / t.depthFile);
        t.depthHash = contentHashFile(dir / t.depthFile).value();
        t.depthRange = depthRange(marchDepths(image));
    };
    addDepth(m.textures[1], depth);
    m.textures[1].samplingPoint = {1.5, -2.0, 3.25};
    addDepth(m.textures[2], DepthImage{100, 100, std::vector<float>(100 * 100, 1.0f)});  // not the colour's size
    addDepth(m.textures[3], depth);
    std::ofstream(dir / m.textures[3].depthFile, std::ios::binary | std::ios::app) << "x";  // damaged
    const std::size_t depthBytes = (128 * 128 + 16 * 16) * 4;  // the halved depths and their 8 x 8 skip blocks
    // Room for textures 0 and 1 with 1's depth, and for three colours alone, but not for three
    // colours and the depth.
    const double budgetMB = (3 * kBytes + depthBytes / 2) / (1024.0 * 1024.0);
    TexturePager pager(dir, m, budgetMB, fakeDecode);
    pager.request({0, 1, 2, 3}, {});
    pager.waitIdle();
    std::map<int, DecodedTexture> ready;
    for (DecodedTexture& d : takeAll(pager)) ready.emplace(d.id, std::move(d));
    ASSERT_EQ(ready.size(), 2u);  // 2 and 3 failed
    EXPECT_TRUE(pager.hasFailed(2) && pager.hasFailed(3));
    EXPECT_EQ(pager.stats().failures, 2);
    EXPECT_EQ(pager.stats().checkFailures, 1);  // 3's depth file: its size is not the manifest's
    EXPECT_FALSE(ready.at(0).depth);
    EXPECT_EQ(ready.at(0).bytes, kBytes);
    const DecodedTexture& withDepth = ready.at(1);
    ASSERT_TRUE(withDepth.depth);
    EXPECT_EQ(withDepth.bytes, kBytes + depthBytes);
    EXPECT_EQ(withDepth.depth->gpuBytes(), depthBytes);
    ASSERT_EQ(withDepth.depth->depth.width, 128);
    ASSERT_EQ(withDepth.depth->depth.height, 128);
    EXPECT_EQ(withDepth.depth->depth.depth[0], kNoSurface);
    EXPECT_EQ(withDepth.depth->depth.depth[1], nearest);  // clamped into the baked range
    EXPECT_EQ(withDepth.depth->depth.depth[2], farthest);
    EXPECT_NEAR(withDepth.depth->depth.depth[3], 2.0f, depthFileError(2.0));
    EXPECT_EQ(withDepth.depth->blocks.width, 128 / kSkipBlock);
    EXPECT_EQ(withDepth.depth->blocks.depth[0], nearest);
    // What the march needs beside the texels comes with them (the walkthrough keeps no copy).
    EXPECT_EQ(withDepth.depth->samplingPoint, m.textures[1].samplingPoint);
    EXPECT_EQ(withDepth.depth->range, m.textures[1].depthRange);
    for (const auto& [id, d] : ready) pager.markResident(id, d.bytes);
    EXPECT_DOUBLE_EQ(pager.stats().residentMB, (2 * kBytes + depthBytes) / (1024.0 * 1024.0));
    EXPECT_TRUE(pager.takeEvictions().empty());
    // One more colour exceeds the budget only because the depth's bytes count: one goes.
    pager.request({4}, {});
    uploadAll(pager);
    EXPECT_TRUE(pager.isResident(4));
    EXPECT_FALSE(pager.takeEvictions().empty());
    EXPECT_LE(pager.stats().residentMB, budgetMB + 1e-12);
}

}  // namespace
}  // namespace cavewall::walls
