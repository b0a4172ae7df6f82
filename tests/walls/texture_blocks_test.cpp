// Block-compressed wall textures (walls/texture_blocks.h): the encoder's error on a wall-like
// texture, exact transparency, the ".bct" file round trip and a clear error for every kind of
// damaged file. GL-free; the GL side (upload, sRGB decode, drawing) is tests/walls/gl.
#include "config/error.h"
#include "metrics/image_error.h"
#include "tests/support/files.h"
#include "walls/texture_blocks.h"
#include "walls/texture_mips.h"

#include <gmock/gmock.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <random>

namespace cavewall::walls {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A wall-like straight-alpha sRGB image of 98 x 70 texels (sizes not multiples of 4, so edge
// blocks are partial): transparent background, a lit box with a smooth shading gradient and a
// fine stripe pattern, and an anti-aliased disc (partial coverage on its rim), as a baked wall
// texture shows objects behind the wall.
scenes::Image wallLike() {
    const int w = 98, h = 70;
    scenes::Image image{"wall-like", w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, 0)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &image.rgba[(std::size_t(y) * w + x) * 4];
            if (x >= 6 && x < 50 && y >= 8 && y < 60) {  // the box: shaded, with stripes
                const double shade = 0.4 + 0.6 * (x - 6) / 44.0;
                const bool stripe = (y / 3) % 4 == 0;
                p[0] = std::uint8_t(std::lround(200 * shade));
                p[1] = std::uint8_t(std::lround((stripe ? 90 : 150) * shade));
                p[2] = std::uint8_t(std::lround(60 * shade));
                p[3] = 255;
            }
            // The disc, centre (72, 35), radius 18, coverage from 4 x 4 subsamples.
            int covered = 0;
            for (int s = 0; s < 16; ++s) {
                const double sx = x + (s % 4 + 0.5) / 4 - 72, sy = y + (s / 4 + 0.5) / 4 - 35;
                covered += sx * sx + sy * sy <= 18.0 * 18.0;
            }
            if (covered > 0) {
                p[0] = std::uint8_t(40 + x);
                p[1] = std::uint8_t(120 + y);
                p[2] = 210;
                p[3] = std::uint8_t(std::lround(255.0 * covered / 16));
            }
        }
    return image;
}

// What the wall pass shows of a premultiplied sRGB texel drawn over an opaque grey: linear
// colour + (1 - alpha) * grey, sRGB-encoded (the blend of walls/gl/wall_quad.h in linear light).
scenes::Image overGrey(const scenes::Image& premultiplied) {
    scenes::Image out = premultiplied;
    const float grey = 0.18f;
    for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
        const float a = premultiplied.rgba[i + 3] / 255.0f;
        for (int c = 0; c < 3; ++c)
            out.rgba[i + c] = encodeSrgbByte(srgbToLinear(premultiplied.rgba[i + c] / 255.0f) + (1.0f - a) * grey);
        out.rgba[i + 3] = 255;
    }
    return out;
}

double psnrOverGrey(const scenes::Image& decoded, const scenes::Image& reference) {
    return metrics::squaredError(overGrey(decoded), overGrey(reference)).psnrDb();
}

// coveredRect: whole texels around every texel with alpha, grown by the margin and clipped to
// the texture; the same from Bc1 and Bc3 blocks (their alpha keeps which texels are empty);
// empty when nothing is covered.
TEST(TextureBlocks, CoveredRectIsTheTexelsWithAlphaGrownByTheMargin) {
    scenes::Image image{"covered", 32, 16, std::vector<std::uint8_t>(32 * 16 * 4, 0)};
    auto set = [&](int x, int y, std::uint8_t alpha) {
        std::uint8_t* p = &image.rgba[(std::size_t(y) * 32 + x) * 4];
        p[0] = p[1] = p[2] = alpha;
        p[3] = alpha;  // premultiplied grey
    };
    EXPECT_TRUE(coveredRect(TextureLevels({image}), 2).empty());
    set(9, 5, 255);
    set(20, 7, 200);
    for (TextureFormat f : {TextureFormat::Rgba8, TextureFormat::Bc1, TextureFormat::Bc3}) {
        SCOPED_TRACE(int(f));
        const TextureLevels levels = f == TextureFormat::Rgba8 ? TextureLevels({image}) : encodeLevels({image}, f);
        TextureRect r = coveredRect(levels, 0);
        EXPECT_EQ(r.lo, glm::dvec2(9.0 / 32, 5.0 / 16));
        EXPECT_EQ(r.hi, glm::dvec2(21.0 / 32, 8.0 / 16));
        r = coveredRect(levels, 6);  // clipped at the upper edge
        EXPECT_EQ(r.lo, glm::dvec2(3.0 / 32, 0.0));
        EXPECT_EQ(r.hi, glm::dvec2(27.0 / 32, 14.0 / 16));
    }
}

TEST(TextureBlocks, SizesAndNames) {
    EXPECT_EQ(blockBytes(TextureFormat::Bc1), 8);
    EXPECT_EQ(blockBytes(TextureFormat::Bc3), 16);
    // 98 x 70: 25 x 18 blocks (partial blocks count whole).
    EXPECT_EQ(levelBytes(TextureFormat::Bc1, 98, 70), 25u * 18 * 8);
    EXPECT_EQ(levelBytes(TextureFormat::Bc3, 1, 1), 16u);
    EXPECT_EQ(levelBytes(TextureFormat::Rgba8, 98, 70), 98u * 70 * 4);
    EXPECT_EQ(textureFormatName(TextureFormat::Bc3), "bc3");
    EXPECT_EQ(textureFileExtension(TextureFormat::Rgba8), ".tx");
    EXPECT_EQ(textureFileExtension(TextureFormat::Bc1), ".bct");
}

TEST(TextureBlocks, EncodingErrorOnAWallLikeTextureIsWithinTolerance) {
    const std::vector<scenes::Image> levels = premultipliedMipChain(wallLike());
    const scenes::Image& reference = levels[0];
    // Measured (BC1: opaque blocks stb_dxt 1.12 high quality, the rest libsquish 1.15 cluster
    // fit; BC3: libsquish): BC1 40.6 dB, BC3 40.9 dB over grey; the limits leave about 3 dB. BC1 loses the rim's partial coverage (1-bit alpha), BC3 keeps it at
    // the price of a block's four colours shared by the rim's transparent texels.
    const scenes::Image bc1 = decodeLevel(encodeLevel(reference, TextureFormat::Bc1), TextureFormat::Bc1);
    const scenes::Image bc3 = decodeLevel(encodeLevel(reference, TextureFormat::Bc3), TextureFormat::Bc3);
    const double psnr1 = psnrOverGrey(bc1, reference), psnr3 = psnrOverGrey(bc3, reference);
    std::cout << "PSNR over grey, 98 x 70 wall-like texture: bc1 " << psnr1 << " dB, bc3 " << psnr3 << " dB\n";
    EXPECT_GT(psnr1, 37.0);
    EXPECT_GT(psnr3, 38.0);
    EXPECT_GT(psnr3, psnr1);  // partial coverage kept
    // Not vacuous: compression loses something.
    EXPECT_NE(bc3.rgba, reference.rgba);
}

TEST(TextureBlocks, TransparencyIsExact) {
    const scenes::Image reference = premultipliedMipChain(wallLike())[0];
    for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc3}) {
        SCOPED_TRACE(std::string(textureFormatName(format)));
        const scenes::Image decoded = decodeLevel(encodeLevel(reference, format), format);
        int transparent = 0;
        for (std::size_t i = 0; i < reference.rgba.size(); i += 4) {
            const int a = reference.rgba[i + 3];
            // Bc1: alpha < 128 is dropped to (0, 0, 0, 0), >= 128 drawn opaque. Bc3 keeps alpha 0
            // and 255 exactly (both its alpha modes can code them); a transparent texel's colour
            // is only as close as the block's four colours allow, except in blocks that are
            // transparent throughout (checked by the mean below).
            if (format == TextureFormat::Bc1 && a < 128) {
                ++transparent;
                ASSERT_EQ(std::memcmp(&decoded.rgba[i], "\0\0\0\0", 4), 0) << "texel " << i / 4;
            }
            if (format == TextureFormat::Bc1 && a >= 128) {
                ASSERT_EQ(decoded.rgba[i + 3], 255) << "texel " << i / 4;
            }
            if (format == TextureFormat::Bc3 && (a == 0 || a == 255)) {
                transparent += a == 0;
                ASSERT_EQ(decoded.rgba[i + 3], a) << "texel " << i / 4;
            }
        }
        EXPECT_GT(transparent, 1000);
    }
    // A block transparent throughout decodes to zeros in both formats.
    const scenes::Image clear{"clear", 8, 4, std::vector<std::uint8_t>(8 * 4 * 4, 0)};
    for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc3}) {
        EXPECT_EQ(decodeLevel(encodeLevel(clear, format), format).rgba, clear.rgba);
    }
}

// Opaque Bc1 blocks are fitted in the four-colour mode only (texture_blocks.cpp): whatever the
// block (one colour, whose endpoints may be equal; two colours; noise), it must decode opaque,
// since a block read in the three-colour mode would make index 3 transparent.
TEST(TextureBlocks, OpaqueBc1BlocksDecodeOpaqueWhateverTheirColours) {
    std::mt19937 rng(5);
    scenes::Image image{"opaque", 64, 16, std::vector<std::uint8_t>(64 * 16 * 4, 255)};
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x) {
            std::uint8_t* t = &image.rgba[(std::size_t(y) * 64 + x) * 4];
            const int block = x / 4;
            for (int c = 0; c < 3; ++c)
                t[c] = block % 4 == 0   ? std::uint8_t(17 * block)                          // one colour
                       : block % 4 == 1 ? std::uint8_t((x + y) % 2 ? 250 : 3)               // two
                       : block % 4 == 2 ? std::uint8_t(rng() % 256)                         // noise
                                        : std::uint8_t(128 + (x % 4) * 40 - (y % 4) * 30);  // a ramp
        }
    const scenes::Image decoded = decodeLevel(encodeLevel(image, TextureFormat::Bc1), TextureFormat::Bc1);
    double error = 0.0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        ASSERT_EQ(decoded.rgba[i + 3], 255) << "texel " << i / 4;
        for (int c = 0; c < 3; ++c) error += std::abs(int(decoded.rgba[i + c]) - int(image.rgba[i + c]));
    }
    // One-colour blocks within the 565 rounding, the rest as a four-colour fit allows.
    for (int x = 0; x < 64; x += 16)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(decoded.rgba[std::size_t(x) * 4 + c], image.rgba[std::size_t(x) * 4 + c], 4);
    EXPECT_LT(error / (64.0 * 16.0 * 3.0), 40.0);
}

TEST(TextureBlocks, Bc1StoresOpaqueTexelsUnpremultiplied) {
    // A half-covered mid grey: premultiplied it is dark; BC1 draws it opaque, so it must hold
    // the surface's own grey (within 565 quantisation), not the darkened one.
    const float grey = 0.5f;
    const std::uint8_t premultiplied = encodeSrgbByte(grey * (160 / 255.0f));
    scenes::Image image{"edge", 4, 4, {}};
    for (int i = 0; i < 16; ++i)
        image.rgba.insert(image.rgba.end(), {premultiplied, premultiplied, premultiplied, 160});
    const scenes::Image decoded = decodeLevel(encodeLevel(image, TextureFormat::Bc1), TextureFormat::Bc1);
    EXPECT_EQ(decoded.rgba[3], 255);
    EXPECT_NEAR(decoded.rgba[0], encodeSrgbByte(grey), 4);  // 188 in sRGB; 565 steps are 8 and 4 levels
}

// Bc1 keeps one bit of alpha, so a texture with translucent texels (a window pane over nothing)
// is stored as Bc3, which keeps them; a few texels, or alpha rounded off 0 or 1, do not count.
TEST(TextureBlocks, TranslucentTexturesAreStoredAsBc3) {
    scenes::Image image{"pane", 16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 255)};
    auto withAlpha = [&](int texels, std::uint8_t alpha) {
        for (int i = 0; i < texels; ++i) image.rgba[std::size_t(i) * 4 + 3] = alpha;
        return storedFormat(image, TextureFormat::Bc1);
    };
    EXPECT_EQ(withAlpha(0, 255), TextureFormat::Bc1);  // opaque
    EXPECT_EQ(withAlpha(15, 25), TextureFormat::Bc1);  // fewer than a block's worth
    EXPECT_EQ(withAlpha(16, 25), TextureFormat::Bc3);
    EXPECT_EQ(storedFormat(image, TextureFormat::Bc3), TextureFormat::Bc3);
    EXPECT_EQ(storedFormat(image, TextureFormat::Rgba8), TextureFormat::Rgba8);
    EXPECT_EQ(withAlpha(256, 250), TextureFormat::Bc1);  // rounded off opaque
    EXPECT_EQ(withAlpha(256, 5), TextureFormat::Bc1);    // rounded off transparent
    EXPECT_EQ(withAlpha(256, 8), TextureFormat::Bc3);
    EXPECT_EQ(withAlpha(256, 247), TextureFormat::Bc3);
    // A pane of alpha 25 (premultiplied colour): Bc3 keeps it within a few levels, Bc1 drops it.
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 0, image.rgba[i + 1] = 40, image.rgba[i + 2] = 60, image.rgba[i + 3] = 25;
    }
    const scenes::Image bc3 = decodeLevel(encodeLevel(image, TextureFormat::Bc3), TextureFormat::Bc3);
    const scenes::Image bc1 = decodeLevel(encodeLevel(image, TextureFormat::Bc1), TextureFormat::Bc1);
    EXPECT_NEAR(bc3.rgba[3], 25, 2);
    EXPECT_NEAR(bc3.rgba[2], 60, 4);
    EXPECT_EQ(bc1.rgba[3], 0);
}

TEST(TextureBlocks, FileRoundTripIsExactAndSmallerThanItsBlocks) {
    test::TempFolder folder("texture_blocks_round_trip");
    const std::vector<scenes::Image> levels = premultipliedMipChain(wallLike());
    for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc3}) {
        SCOPED_TRACE(std::string(textureFormatName(format)));
        const TextureLevels encoded = encodeLevels(levels, format);
        ASSERT_EQ(encoded.count(), 7u);  // 98 x 70 down to 1 x 1
        std::string name(textureFormatName(format));
        name += textureFileExtension(format);
        const std::filesystem::path file = folder / name;
        writeBlockFile(file, encoded);
        const TextureLevels back = readBakedTexture(file);  // by magic, not by name
        ASSERT_EQ(back.format, format);
        ASSERT_EQ(back.count(), encoded.count());
        for (std::size_t i = 0; i < back.count(); ++i) {
            EXPECT_EQ(back.blocks[i].width, encoded.blocks[i].width);
            EXPECT_EQ(back.blocks[i].blocks, encoded.blocks[i].blocks) << "level " << i;  // pure data: exact
        }
        EXPECT_EQ(back.bytes(), encoded.bytes());
        // zstd shrinks the transparent blocks to almost nothing.
        EXPECT_LT(std::filesystem::file_size(file), encoded.bytes() / 2);
    }
    int files = 0;  // no temporary file is left behind
    for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(folder.path())) ++files;
    EXPECT_EQ(files, 2);
}

TEST(TextureBlocks, WriteRejectsBadLevels) {
    test::TempFolder folder("texture_blocks_bad_levels");
    const TextureLevels encoded = encodeLevels(premultipliedMipChain(wallLike()), TextureFormat::Bc1);
    TextureLevels skipped = encoded;
    skipped.blocks.erase(skipped.blocks.begin() + 1);
    EXPECT_THAT([&] { writeBlockFile(folder / "x.bct", skipped); },
                ThrowsMessage<Error>(HasSubstr("x.bct: MIP level 1: expected 49 x 35 in 936 bytes, got 24 x 17")));
    EXPECT_THAT([&] { writeBlockFile(folder / "x.bct", TextureLevels(TextureFormat::Bc3, {})); },
                ThrowsMessage<Error>(HasSubstr("expected at least one MIP level, got none")));
    EXPECT_THAT([&] { writeBlockFile(folder / "x.bct", TextureLevels(premultipliedMipChain(wallLike()))); },
                ThrowsMessage<Error>(HasSubstr("expected a block format (bc1, bc3), got rgba8")));
    EXPECT_FALSE(std::filesystem::exists(folder / "x.bct"));
}

void putU32(std::string& bytes, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

// A version 1 file as earlier bakes wrote it: a u32 size per level, each level's blocks
// rearranged field by field (Bc1: the 4-byte endpoint pairs, then the 4-byte index words) and
// deflated on its own.
std::string deflatedFile(const TextureLevels& levels) {
    std::string bytes = "CWBC";
    auto put = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
    };
    put(1), put(1), put(std::uint32_t(levels.blocks[0].width)), put(std::uint32_t(levels.blocks[0].height));
    put(std::uint32_t(levels.count()));
    std::vector<std::string> packed;
    for (const BlockLevel& level : levels.blocks) {
        std::vector<std::uint8_t> fields;
        for (std::size_t start : {0u, 4u})
            for (std::size_t b = 0; b < level.blocks.size(); b += 8)
                fields.insert(fields.end(), level.blocks.begin() + std::ptrdiff_t(b + start),
                              level.blocks.begin() + std::ptrdiff_t(b + start + 4));
        uLongf size = compressBound(fields.size());
        std::string out(size, '\0');
        EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(out.data()), &size, fields.data(), fields.size(), 6), Z_OK);
        out.resize(size);
        packed.push_back(out);
    }
    for (const std::string& p : packed) put(std::uint32_t(p.size()));
    for (const std::string& p : packed) bytes += p;
    return bytes;
}

TEST(TextureBlocks, ReadsVersionOneFilesAndWritesSmallerOnes) {
    test::TempFolder folder("texture_blocks_version_one");
    const TextureLevels encoded = encodeLevels(premultipliedMipChain(wallLike()), TextureFormat::Bc1);
    const std::string old = deflatedFile(encoded);
    test::writeFile(folder / "old.bct", old);
    const TextureLevels back = readBakedTexture(folder / "old.bct");
    ASSERT_EQ(back.count(), encoded.count());
    for (std::size_t i = 0; i < back.count(); ++i) EXPECT_EQ(back.blocks[i].blocks, encoded.blocks[i].blocks);
    writeBlockFile(folder / "new.bct", encoded);
    EXPECT_LT(std::filesystem::file_size(folder / "new.bct"), old.size());
    // A damaged version 1 level says so in the deflate reader's words.
    std::string flipped = old;
    flipped[24 + 7 * 4 + 20] = static_cast<char>(flipped[24 + 7 * 4 + 20] ^ 0x5A);
    EXPECT_THAT([&] { blocksFromBytes(flipped, "old.bct"); },
                ThrowsMessage<Error>(HasSubstr("old.bct: MIP level 0: expected")));
}

TEST(TextureBlocks, DamagedFilesGiveClearErrors) {
    test::TempFolder folder("texture_blocks_damaged");
    const std::filesystem::path good = folder / "good.bct";
    writeBlockFile(good, encodeLevels(premultipliedMipChain(wallLike()), TextureFormat::Bc1));
    const std::string bytes = test::readFile(good);
    // Header: 24 bytes, the stored size, then one zstd frame of 7 levels' blocks (98 x 70 has 7
    // MIP levels: 3600 + 936 + 240 + 48 + 16 + 8 + 8 = 4856 bytes of BC1 blocks).
    const std::size_t frame = 24 + 4;
    struct Case {
        const char* name;
        std::string bytes;
        std::string expected;
    };
    std::vector<Case> cases;
    auto with = [&](std::size_t at, std::uint32_t v) {
        std::string b = bytes;
        putU32(b, at, v);
        return b;
    };
    std::string flipped = bytes;
    flipped[bytes.size() - 30] = static_cast<char>(flipped[bytes.size() - 30] ^ 0x5A);
    std::string headless = bytes;
    headless[frame] = 'x';  // not a zstd frame's magic
    cases.push_back({"empty", "", "header: expected at least 24 bytes, got 0"});
    std::string magic = bytes;
    magic.replace(0, 4, "DDS ");
    cases.push_back({"magic", magic, "header: expected the magic 'CWBC', got other bytes"});
    cases.push_back({"version", with(4, 3), "header: expected version 1 or 2, got 3"});
    cases.push_back({"format", with(8, 7), "header: expected format 1 (bc1) or 3 (bc3), got 7"});
    cases.push_back({"width", with(12, 0), "header: expected a size in [1, 16384], got 0 x 70"});
    cases.push_back({"levels", with(20, 99), "header: expected 1 to 7 MIP levels, got 99"});
    cases.push_back({"size cut", bytes.substr(0, 26), "header: expected 28 bytes with the stored size, got 26"});
    cases.push_back({"data cut", bytes.substr(0, bytes.size() - 3), "(the file is truncated)"});
    cases.push_back({"stored size", with(24, 1'000'000), "levels: expected 1000000 stored bytes"});
    cases.push_back({"too small", with(24, 0).substr(0, frame), "levels: expected 0 compressed bytes to hold 4856"});
    cases.push_back({"no frame", headless, "decompress to 4856 bytes of bc1 blocks, got no zstd frame"});
    cases.push_back({"corrupt", flipped, "decompress to 4856 bytes of bc1 blocks, got corrupt data"});
    cases.push_back({"extra", bytes + "xx",
                     "levels: expected " + std::to_string(bytes.size() - frame) + " stored bytes, got " +
                         std::to_string(bytes.size() - frame + 2) + " (extra bytes)"});
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::filesystem::path file = folder / (std::string(c.name) + ".bct");
        test::writeFile(file, c.bytes);
        EXPECT_THAT([&] { readBlockFile(file); },
                    ThrowsMessage<Error>(AllOf(HasSubstr(file.string() + ": "), HasSubstr(c.expected))));
    }
    EXPECT_THAT([&] { readBlockFile(folder / "missing.bct"); },
                ThrowsMessage<Error>(HasSubstr("missing.bct: cannot open")));
}

}  // namespace
}  // namespace cavewall::walls
