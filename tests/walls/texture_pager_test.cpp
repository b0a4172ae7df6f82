#include "walls/texture_pager.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>

namespace cavewall::walls {
namespace {

// Ten textures of 256 KiB each (one 256x256 RGBA8 level); tex_7 is broken.
BakeManifest manifest() {
    BakeManifest m;
    for (int i = 0; i < 10; ++i) m.textures.push_back({i, 0, 0, {}, {256, 256}, "tex_" + std::to_string(i), 0, 0});
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

// Uploads everything ready, as the GL side does once per frame.
void uploadAll(TexturePager& pager) {
    pager.waitIdle();
    for (const DecodedTexture& d : pager.takeReady(SIZE_MAX)) pager.markResident(d.id, d.bytes);
}

TEST(TexturePager, DecodesWhatIsWantedAndCountsMisses) {
    TexturePager pager("/nowhere", manifest(), 4.0, fakeDecode);
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
    TexturePager pager("/nowhere", manifest(), 0.8, fakeDecode);  // room for three
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
    TexturePager pager("/nowhere", manifest(), 0.3, fakeDecode);  // room for one
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

TEST(TexturePager, BrokenFilesFailOnceAndAreNotRetried) {
    TexturePager pager("/nowhere", manifest(), 4.0, fakeDecode);
    decodes = 0;
    pager.request({7}, {});
    pager.waitIdle();
    EXPECT_TRUE(pager.hasFailed(7));
    pager.request({7}, {});
    pager.waitIdle();
    EXPECT_EQ(decodes, 1);
    EXPECT_EQ(pager.stats().failures, 1);
    EXPECT_TRUE(pager.takeReady(SIZE_MAX).empty());
}

TEST(TexturePager, UploadsWithinAByteBudgetPerFrame) {
    TexturePager pager("/nowhere", manifest(), 4.0, fakeDecode);
    pager.request({0, 1, 2, 3}, {});
    pager.waitIdle();
    EXPECT_EQ(pager.takeReady(2 * kBytes).size(), 2u);
    EXPECT_EQ(pager.takeReady(1).size(), 1u);  // at least one, so paging always progresses
}

}  // namespace
}  // namespace cavewall::walls
