// Cutting a texture's upload into bands (walls/upload_cursor.h): every stored byte goes up exactly
// once, in the units the GPU takes (texel rows, rows of 4 x 4 blocks), within the byte limit
// except for the one unit that guarantees progress.
#include "walls/upload_cursor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace cavewall::walls {
namespace {

TextureLevels rgbaChain(int w, int h) {
    std::vector<scenes::Image> levels;
    for (;;) {
        scenes::Image l;
        l.width = w;
        l.height = h;
        l.rgba.assign(static_cast<std::size_t>(w) * h * 4, 0);
        levels.push_back(l);
        if (w == 1 && h == 1) break;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    return TextureLevels(std::move(levels));
}

TextureLevels blockChain(TextureFormat format, int w, int h) {
    std::vector<BlockLevel> levels;
    for (;;) {
        levels.push_back(BlockLevel{w, h, std::vector<std::uint8_t>(levelBytes(format, w, h))});
        if (w == 1 && h == 1) break;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    return TextureLevels(format, std::move(levels));
}

std::size_t storedBytes(const TextureLevels& t, int level) {
    return t.format == TextureFormat::Rgba8 ? t.rgba[level].rgba.size() : t.blocks[level].blocks.size();
}

// Walks the whole cursor with `limit` bytes a call; checks the pieces tile every level's bytes
// and rows in order, and returns the pieces.
std::vector<UploadPiece> walk(const TextureLevels& t, std::size_t limit) {
    UploadCursor cursor(t);
    EXPECT_EQ(cursor.remainingBytes(), t.bytes());
    std::vector<UploadPiece> pieces;
    std::vector<std::size_t> covered(t.count(), 0);
    std::vector<int> rows(t.count(), 0);
    std::size_t sum = 0;
    while (!cursor.done()) {
        const UploadPiece p = cursor.next(limit);
        EXPECT_EQ(p.offset, covered[p.level]) << "level " << p.level;
        EXPECT_EQ(p.y, rows[p.level]) << "level " << p.level;
        covered[p.level] += p.bytes;
        rows[p.level] += p.rows;
        sum += p.bytes;
        EXPECT_EQ(cursor.remainingBytes(), t.bytes() - sum);
        pieces.push_back(p);
        if (pieces.size() > 100000) break;
    }
    for (std::size_t l = 0; l < t.count(); ++l) {
        EXPECT_EQ(covered[l], storedBytes(t, static_cast<int>(l))) << "level " << l;
        const int height = t.format == TextureFormat::Rgba8 ? t.rgba[l].height : t.blocks[l].height;
        EXPECT_EQ(rows[l], height) << "level " << l;
    }
    EXPECT_EQ(sum, t.bytes());
    return pieces;
}

TEST(UploadCursor, Rgba8PiecesAreWholeTexelRowsWithinTheLimit) {
    const TextureLevels t = rgbaChain(64, 32);
    const std::size_t limit = 64 * 4 * 5 + 7;  // five rows of level 0 and a bit
    for (const UploadPiece& p : walk(t, limit)) {
        EXPECT_LE(p.bytes, limit);
        const int width = t.rgba[p.level].width;
        EXPECT_EQ(p.bytes, static_cast<std::size_t>(p.rows) * width * 4);
    }
    // Level 0 goes up in bands of five rows: 32 rows take 7 pieces.
    const std::vector<UploadPiece> pieces = walk(t, limit);
    EXPECT_EQ(std::count_if(pieces.begin(), pieces.end(), [](const UploadPiece& p) { return p.level == 0; }), 7);
}

TEST(UploadCursor, BlockPiecesStartOnBlockRowsAndEndOnBlockRowsOrTheEdge) {
    for (TextureFormat f : {TextureFormat::Bc1, TextureFormat::Bc3})
        for (auto [w, h] : {std::pair{512, 512}, std::pair{100, 37}, std::pair{6, 3}}) {
            const TextureLevels t = blockChain(f, w, h);
            const std::size_t limit = 3 * levelBytes(f, w, 4) + 1;  // three block rows of level 0
            for (const UploadPiece& p : walk(t, limit)) {
                const int height = t.blocks[p.level].height;
                EXPECT_EQ(p.y % 4, 0);
                EXPECT_TRUE(p.rows % 4 == 0 || p.y + p.rows == height) << p.y << " + " << p.rows << " of " << height;
                EXPECT_LE(p.bytes, limit);
                // The band's bytes are exactly its rows' blocks.
                EXPECT_EQ(p.bytes, levelBytes(f, t.blocks[p.level].width, p.rows));
            }
        }
}

TEST(UploadCursor, ALimitBelowOneRowStillProgressesByOneRow) {
    const TextureLevels t = blockChain(TextureFormat::Bc1, 256, 256);
    const std::vector<UploadPiece> pieces = walk(t, 1);
    // One block row per call: level 0 has 64, each next level half as many (at least 1).
    EXPECT_EQ(pieces.front().rows, 4);
    EXPECT_EQ(pieces.front().bytes, levelBytes(TextureFormat::Bc1, 256, 4));
    EXPECT_EQ(pieces.size(), 64u + 32 + 16 + 8 + 4 + 2 + 1 + 1 + 1);
}

TEST(UploadCursor, ALargeLimitTakesAWholeLevelButNeverTwo) {
    const TextureLevels t = rgbaChain(16, 16);
    const std::vector<UploadPiece> pieces = walk(t, 1u << 30);
    ASSERT_EQ(pieces.size(), t.count());
    for (std::size_t l = 0; l < pieces.size(); ++l) EXPECT_EQ(pieces[l].level, static_cast<int>(l));
}

}  // namespace
}  // namespace cavewall::walls
