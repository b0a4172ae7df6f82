// MIP chains of baked textures (walls/texture_mips.h): premultiplied in linear light before
// downsampling, exact box filter, and the tiled MIP-mapped file round trip. GL-free.
#include "config/error.h"
#include "scenes/image_io.h"
#include "walls/texture_mips.h"
#include "tests/support/files.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <random>
#include <span>
#include <string>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

scenes::Image image(int w, int h, std::vector<std::uint8_t> rgba) { return {"test", w, h, std::move(rgba)}; }

glm::dvec4 texel(const scenes::Image& i, int x, int y) {
    const std::uint8_t* p = &i.rgba[(std::size_t(y) * i.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

// Linear straight colour of a stored (premultiplied, sRGB-encoded) texel: decode, then divide by alpha.
glm::dvec3 unpremultiplied(const scenes::Image& i, int x, int y) {
    const glm::dvec4 t = texel(i, x, y);
    const double a = t.a / 255.0;
    return glm::dvec3(srgbToLinear(float(t.r / 255.0)), srgbToLinear(float(t.g / 255.0)),
                      srgbToLinear(float(t.b / 255.0))) /
           a;
}

// The formula encodeSrgbByte replaces (texture_mips.h), evaluated directly.
std::uint8_t formulaByte(float v) {
    return static_cast<std::uint8_t>(
        std::lround(std::clamp(linearToSrgb(std::clamp(v, 0.0f, 1.0f)), 0.0f, 1.0f) * 255.0f));
}

TEST(TextureMips, TableEncodingIsTheFormulaExactly) {
    // Around every step of the byte (where sRGB value (k - 0.5) / 255 decodes to, ± 4096 float
    // steps, which covers any rounding of the step's position) and on an even sweep of
    // [-0.01, 1.01] (clamping on both sides).
    int checked = 0;
    for (int k = 1; k < 256; ++k) {
        const std::uint32_t at = std::bit_cast<std::uint32_t>(srgbToLinear((k - 0.5f) / 255.0f));
        for (std::uint32_t b = at - 4096; b <= at + 4096; ++b, ++checked) {
            const float v = std::bit_cast<float>(b);
            ASSERT_EQ(encodeSrgbByte(v), formulaByte(v)) << "value " << v << " near step " << k;
        }
    }
    for (int i = 0; i <= 1 << 20; ++i, ++checked) {
        const float v = -0.01f + 1.02f * float(i) / float(1 << 20);
        ASSERT_EQ(encodeSrgbByte(v), formulaByte(v)) << "value " << v;
    }
    // Both sides of every bucket edge of the encoder's index (the top 16 bits of the float).
    for (std::uint32_t b = 1; b <= (0x3F800000u >> 16); ++b)
        for (std::uint32_t bits : {(b << 16) - 1, b << 16, (b << 16) + 1}) {
            const float v = std::bit_cast<float>(bits);
            ++checked;
            ASSERT_EQ(encodeSrgbByte(v), formulaByte(v)) << "value " << v << " at bucket " << b;
        }
    EXPECT_GT(checked, 3000000);
    EXPECT_EQ(encodeSrgbByte(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(TextureMips, LevelZeroIsThePremultipliedFloatRoundTripForEveryAlpha) {
    // The chain's level 0 takes fast paths for opaque and empty texels; every texel must be what
    // premultiplying in float and encoding gives: colour byte of srgbToLinear(c) * a, alpha
    // round(255 a). Every alpha, 0 and 255 four times as often (as in a bake).
    std::mt19937 rng(11);
    scenes::Image straight{"random", 64, 64, std::vector<std::uint8_t>(64 * 64 * 4)};
    for (std::size_t i = 0; i < straight.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) straight.rgba[i + c] = static_cast<std::uint8_t>(rng() % 256);
        const unsigned pick = rng() % 1280;
        straight.rgba[i + 3] = static_cast<std::uint8_t>(pick < 512 ? 255 : pick < 1024 ? 0 : pick - 1024);
    }
    const scenes::Image first = premultipliedMipChain(straight).at(0);
    for (std::size_t i = 0; i < straight.rgba.size(); i += 4) {
        const float a = straight.rgba[i + 3] / 255.0f;
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(first.rgba[i + c], encodeSrgbByte(srgbToLinear(straight.rgba[i + c] / 255.0f) * a)) << i;
        ASSERT_EQ(first.rgba[i + 3], straight.rgba[i + 3]) << i;
    }
    for (int b = 0; b < 256; ++b) EXPECT_EQ(srgbByteRoundTrip()[b], encodeSrgbByte(srgbToLinear(b / 255.0f)));
}

TEST(TextureMips, HalfTransparentEdgeDoesNotDarken) {
    // One opaque white texel beside a fully transparent one: the 1 x 1 level covers half of each,
    // so it is white at half coverage. Averaging straight sRGB values instead would give 128,
    // i.e. linear 0.216 / 0.5 = 0.43: a dark edge.
    const auto levels = premultipliedMipChain(image(2, 1, {255, 255, 255, 255, 0, 0, 0, 0}));
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(texel(levels[1], 0, 0).a, 128);  // round(0.5 * 255)
    const glm::dvec3 c = unpremultiplied(levels[1], 0, 0);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], 1.0, 0.01) << "channel " << k;  // 8-bit rounding of 0.5
}

// A pane of glass over nothing, as the bake's render target holds it: colour already times
// alpha. The premultiplied chain keeps level 0's bytes (the straight chain would multiply by
// alpha again: a tenth of the tint), and where alpha is 0 or 1 both chains are the same.
TEST(TextureMips, PremultipliedInputIsNotMultipliedAgain) {
    const scenes::Image pane = image(2, 1, {0, 60, 90, 25, 200, 180, 160, 255});
    const auto levels = mipChainOfPremultiplied(pane);
    ASSERT_EQ(levels.size(), 2u);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(texel(levels[0], 0, 0)[c], pane.rgba[std::size_t(c)], 1) << c;
    EXPECT_LT(texel(premultipliedMipChain(pane)[0], 0, 0).g, 30);  // 60 decoded, times 25 / 255
    // Level 1: the mean of the two premultiplied texels in linear light.
    const double g = (srgbToLinear(60 / 255.0f) + srgbToLinear(180 / 255.0f)) / 2.0;
    EXPECT_NEAR(srgbToLinear(float(texel(levels[1], 0, 0).g / 255.0)), g, 0.004);
    EXPECT_NEAR(texel(levels[1], 0, 0).a, (25 + 255) / 2.0, 1);
    const scenes::Image binary = image(2, 1, {10, 20, 30, 255, 0, 0, 0, 0});
    const auto a = mipChainOfPremultiplied(binary), b = premultipliedMipChain(binary);
    for (std::size_t l = 0; l < a.size(); ++l) EXPECT_EQ(a[l].rgba, b[l].rgba) << "level " << l;
}

TEST(TextureMips, TransparentTexelsDoNotBleedTheirColour) {
    // The transparent texel carries garbage red (straight alpha 0): premultiplying removes it, so
    // the mixed texel is pure blue at half coverage.
    const auto levels = premultipliedMipChain(image(2, 1, {255, 0, 0, 0, 0, 0, 255, 255}));
    const glm::dvec4 t = texel(levels[1], 0, 0);
    EXPECT_EQ(t.r, 0);
    EXPECT_EQ(t.g, 0);
    EXPECT_NEAR(unpremultiplied(levels[1], 0, 0).b, 1.0, 0.01);
}

TEST(TextureMips, LevelSizesHalveDownToOneTexel) {
    struct Case {
        int w, h;
        std::vector<glm::ivec2> sizes;  // floor(size / 2) per level, at least 1, as GL expects
    };
    const Case cases[] = {{1, 1, {{1, 1}}},
                          {5, 3, {{5, 3}, {2, 1}, {1, 1}}},
                          {8, 2, {{8, 2}, {4, 1}, {2, 1}, {1, 1}}},
                          {64, 32, {{64, 32}, {32, 16}, {16, 8}, {8, 4}, {4, 2}, {2, 1}, {1, 1}}}};
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(c.w) + " x " + std::to_string(c.h));
        const auto levels =
            premultipliedMipChain(image(c.w, c.h, std::vector<std::uint8_t>(std::size_t(c.w) * c.h * 4, 200)));
        ASSERT_EQ(levels.size(), c.sizes.size());
        for (std::size_t i = 0; i < levels.size(); ++i)
            EXPECT_EQ(glm::ivec2(levels[i].width, levels[i].height), c.sizes[i]);
    }
}

TEST(TextureMips, BoxFilterKeepsMeanCoverageAndColour) {
    // An exact area-weighted box filter conserves the mean of premultiplied linear colour and of
    // alpha over the image, also for odd sizes; only 8-bit rounding (<= 0.5/255 per texel,
    // averaged) and the sRGB step near black may move it.
    std::mt19937 random(7);
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<std::uint8_t> rgba(7 * 5 * 4);
    for (auto& b : rgba) b = static_cast<std::uint8_t>(byte(random));
    const auto levels = premultipliedMipChain(image(7, 5, rgba));
    auto mean = [](const scenes::Image& l) {
        glm::dvec4 sum(0.0);
        for (int y = 0; y < l.height; ++y)
            for (int x = 0; x < l.width; ++x) {
                const glm::dvec4 t = texel(l, x, y) / 255.0;
                sum += glm::dvec4(srgbToLinear(float(t.r)), srgbToLinear(float(t.g)), srgbToLinear(float(t.b)), t.a);
            }
        return sum / double(l.width * l.height);
    };
    const glm::dvec4 base = mean(levels[0]);
    for (std::size_t i = 1; i < levels.size(); ++i)
        for (int k = 0; k < 4; ++k)
            EXPECT_NEAR(mean(levels[i])[k], base[k], 0.006) << "level " << i << " channel " << k;
}

TEST(TextureMips, FileRoundTripIsExactTiledAndMipMapped) {
    std::vector<std::uint8_t> rgba(100 * 40 * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>((i * 37) % 251);
    const auto levels = premultipliedMipChain(image(100, 40, rgba));
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "cavewall-mips-test" / "t.tx";
    writeMipFile(file, levels, {32, "zip"});
    const auto back = scenes::readMipLevels(file);
    ASSERT_EQ(back.size(), levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i)
        EXPECT_EQ(back[i].rgba, levels[i].rgba) << "level " << i;  // pure data: exact

    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().tile_width, 32);
    EXPECT_EQ(in->spec().get_int_attribute("oiio:UnassociatedAlpha", 0), 0);  // associated = premultiplied
    EXPECT_THAT(in->spec().get_string_attribute("ImageDescription"), HasSubstr("premultiplied"));
    // No temporary file is left beside it.
    int files = 0;
    for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(file.parent_path())) ++files;
    EXPECT_EQ(files, 1);
}

// The in-memory entry point (what the cluster_impostor fuzz target reads) is the file's reader
// after the open: the same levels, named after the name given. Only the TIFF reader opens a MIP
// file: bytes that are not a TIFF are refused, never handed to another format's reader (the
// image library's RLA reader aborted the process on these bytes; the fuzz corpus keeps them).
TEST(TextureMips, BytesInMemoryReadAsTheFileAndOnlyTiff) {
    const auto levels = premultipliedMipChain(image(20, 12, std::vector<std::uint8_t>(20 * 12 * 4, 200)));
    const test::TempFolder dir("texture-mips-memory");
    writeMipFile(dir / "t.tx", levels, {16, "zip"});
    const std::string bytes = test::readFile(dir / "t.tx");
    const auto span = [](const std::string& b) {
        return std::span(reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
    };
    const auto fromFile = scenes::readMipLevels(dir / "t.tx");
    const auto fromMemory = scenes::readMipLevels(span(bytes), "f0r0.tx");
    ASSERT_EQ(fromMemory.size(), fromFile.size());
    ASSERT_EQ(fromMemory.size(), levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        EXPECT_EQ(fromMemory[i].rgba, fromFile[i].rgba) << "level " << i;
        EXPECT_EQ(fromMemory[i].name, "f0r0.tx level " + std::to_string(i));
    }
    const std::string notTiff =
        test::readFile(CAVEWALL_SOURCE_DIR "/tests/fuzz/corpus/cluster_impostor/not_a_tiff_rla_abort.tx");
    test::writeFile(dir / "rla.tx", notTiff);
    EXPECT_THAT([&] { scenes::readMipLevels(dir / "rla.tx"); },
                ThrowsMessage<Error>(HasSubstr("rla.tx: cannot read image")));
    EXPECT_THAT([&] { scenes::readMipLevels(span(notTiff), "rla.tx"); },
                ThrowsMessage<Error>(HasSubstr("rla.tx: cannot read image")));
    EXPECT_THAT([&] { scenes::readMipLevels(span(bytes.substr(0, 200)), "cut.tx"); },
                ThrowsMessage<Error>(HasSubstr("cut.tx: ")));
}

// Headers that would make the reader or the image library allocate gigabytes or loop for
// minutes are refused before any texel is read: tiles of 17 GB and tiles 2^32 - 1 texels high
// (the fuzz corpus's tiled_huge_tile_oom.tx and tiled_negative_tile_hang.tx), more channels
// than RGBA, sides beyond the largest bake.
TEST(TextureMips, HugeHeadersAreRefusedBeforeAllocating) {
    const test::TempFolder dir("texture-mips-huge");
    for (const char* input : {"tiled_huge_tile_oom.tx", "tiled_negative_tile_hang.tx"}) {
        SCOPED_TRACE(input);
        const std::string bytes =
            test::readFile(std::string(CAVEWALL_SOURCE_DIR "/tests/fuzz/corpus/cluster_impostor/") + input);
        EXPECT_THAT(
            [&] {
                scenes::readMipLevels(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
                                      "f0r0.tx");
            },
            ThrowsMessage<Error>(
                HasSubstr("f0r0.tx: MIP level 0: expected tiles of 1 x 1 to 4096 x 4096 texels, got ")));
    }
    const auto write = [&](const char* name, int w, int h, int channels) {
        const std::filesystem::path file = dir / name;
        auto out = OIIO::ImageOutput::create(file.string());
        OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
        const std::vector<std::uint8_t> texels(std::size_t(w) * h * channels, 7);
        EXPECT_TRUE(out->open(file.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, texels.data()) &&
                    out->close());
        return file;
    };
    EXPECT_THAT([&] { scenes::readMipLevels(write("five.tx", 2, 2, 5)); },
                ThrowsMessage<Error>(HasSubstr("five.tx: MIP level 0: expected at most 4 channels (RGBA), got 5")));
    EXPECT_THAT(
        [&] { scenes::readMipLevels(write("wide.tx", scenes::kMaxMipSide + 1, 1, 1)); },
        ThrowsMessage<Error>(HasSubstr("wide.tx: MIP level 0: expected at most 16384 x 16384 texels, got 16385 x 1")));
    EXPECT_EQ(scenes::readMipLevels(write("grey.tx", 3, 2, 1)).at(0).rgba.size(), 3u * 2u * 4u);  // within: read
}

TEST(TextureMips, WriteRejectsBadInput) {
    const auto levels = premultipliedMipChain(image(4, 4, std::vector<std::uint8_t>(64, 255)));
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "cavewall-mips-test" / "bad.tx";
    EXPECT_THAT(
        [&] {
            writeMipFile(file, levels, {10, "zip"});
        },
        ThrowsMessage<Error>(HasSubstr("tile size: expected a multiple of 16 in [16, 1024], got 10")));
    std::vector<scenes::Image> skipped{levels[0], levels[2]};
    EXPECT_THAT([&] { writeMipFile(file, skipped); },
                ThrowsMessage<Error>(HasSubstr("MIP level 1: expected half the size of level 0, got 1 x 1")));
    EXPECT_THAT([&] { writeMipFile(file, {}); }, ThrowsMessage<Error>(HasSubstr("expected at least one MIP level")));
    EXPECT_FALSE(std::filesystem::exists(file));
    EXPECT_THAT([&] { scenes::readMipLevels(file); }, ThrowsMessage<Error>(HasSubstr("bad.tx: cannot read image")));
}

}  // namespace
}  // namespace cavewall::walls
