#include "walls/content_hash.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace cavewall::walls {
namespace {

TEST(ContentHash, MatchesPublishedXxh64Values) {
    // XXH64 reference values (xxhsum -H1 and python-xxhash), seed 0. The inputs take every path:
    // the empty one only the avalanche; "abc" the byte tail; 32 bytes exactly one stripe; 39
    // bytes one stripe, then a 4-byte word and three single bytes; 43 bytes one stripe and an
    // 8-byte word.
    EXPECT_EQ(contentHash(""), 0xEF46DB3751D8E999ull);
    EXPECT_EQ(contentHash("abc"), 0x44BC2CF5AD770999ull);
    EXPECT_EQ(contentHash(std::string(32, 'a')), 0x856E843298F99AD7ull);
    EXPECT_EQ(contentHash("Nobody inspects the spammish repetition"), 0xFBCEA83C8A378BF1ull);
    EXPECT_EQ(contentHash("The quick brown fox jumps over the lazy dog"), 0x0B242D361FDA71BCull);
}

TEST(ContentHash, EveryFlippedBitChangesTheHash) {
    // A 1 KiB buffer with each of its bits flipped in turn: no flip keeps the hash (what the
    // cache check relies on for a flipped byte).
    std::string bytes(1024, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7 + 3);
    const std::uint64_t base = contentHash(bytes);
    for (std::size_t bit = 0; bit < bytes.size() * 8; ++bit) {
        bytes[bit / 8] = static_cast<char>(bytes[bit / 8] ^ (1 << (bit % 8)));
        ASSERT_NE(contentHash(bytes), base) << "bit " << bit;
        bytes[bit / 8] = static_cast<char>(bytes[bit / 8] ^ (1 << (bit % 8)));
    }
    EXPECT_NE(contentHash(bytes, 1), base);  // the seed matters
}

TEST(ContentHash, FilesAreReadWhole) {
    const auto dir = std::filesystem::temp_directory_path() / "cavewall_content_hash";
    std::filesystem::create_directories(dir);
    std::string bytes(100000, 'x');
    bytes[54321] = 'y';
    std::ofstream(dir / "f.bin", std::ios::binary) << bytes;
    EXPECT_EQ(readFileBytes(dir / "f.bin"), bytes);
    EXPECT_EQ(contentHashFile(dir / "f.bin"), contentHash(bytes));
    EXPECT_EQ(readFileBytes(dir / "none.bin"), std::nullopt);
    EXPECT_EQ(contentHashFile(dir / "none.bin"), std::nullopt);
}

}  // namespace
}  // namespace cavewall::walls
