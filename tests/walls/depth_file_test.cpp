// Depth files and the manifest's depth entries (walls/depth_file.h, bake_manifest.h): depths
// round-trip within their 16-bit codes' stated precision (inf exactly; old float files bit for
// bit), a depth texture is valid only when both its files are, and bad depth entries are
// rejected naming the JSON path.
#include "walls/bake_manifest.h"
#include "walls/depth_file.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <span>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;

std::filesystem::path scratch(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / ("cavewall_depth_file_" + std::string(name));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(DepthFile, NamesFollowTheColourFile) {
    EXPECT_EQ(depthFileName("tex_0003_0123456789abcdef.tx"), "tex_0003_0123456789abcdef.depth.tif");
    EXPECT_EQ(depthFileName("tex_0003_0123456789abcdef.bct"), "tex_0003_0123456789abcdef.depth.tif");
}

// The 16-bit code: within depthFileError everywhere (and that bound is not loose: a sweep
// reaches half of it), nothing and zero exactly, codes falling as depth grows.
TEST(DepthFile, CodesAreWithinTheirStatedPrecision) {
    EXPECT_EQ(encodeDepth(kNoSurface), 0);
    EXPECT_EQ(decodeDepth(0), kNoSurface);
    EXPECT_EQ(encodeDepth(0.0f), 65535);
    EXPECT_EQ(decodeDepth(65535), 0.0f);
    EXPECT_EQ(encodeDepth(-1.0f), 65535);          // in front of the plane: 0
    EXPECT_EQ(encodeDepth(std::nanf("")), 65535);  // never a NaN back
    EXPECT_EQ(encodeDepth(1e9f), 2);               // beyond the codes: the farthest
    EXPECT_TRUE(std::isfinite(decodeDepth(2)));
    double worstShare = 0.0;
    std::uint16_t last = 65535;
    for (double d = 0.0; d < 2000.0; d = d * 1.01 + 1e-4) {
        const std::uint16_t q = encodeDepth(static_cast<float>(d));
        EXPECT_LE(q, last) << d;
        last = q;
        const double error = std::abs(double(decodeDepth(q)) - double(static_cast<float>(d)));
        ASSERT_LE(error, depthFileError(d)) << "depth " << d;
        worstShare = std::max(worstShare, error / depthFileError(d));
    }
    EXPECT_GT(worstShare, 0.5);
    EXPECT_NEAR(depthFileError(1.0), 3.05e-5, 1e-6);  // the header's figures
    EXPECT_NEAR(depthFileError(10.0), 9.2e-4, 1e-5);
    EXPECT_NEAR(depthFileError(100.0), 0.078, 1e-3);
}

TEST(DepthFile, DepthsRoundTripWithinTheCodesPrecision) {
    const auto dir = scratch("roundtrip");
    DepthImage image{7, 5, {}};
    for (int i = 0; i < 35; ++i) image.depth.push_back(i % 6 == 0 ? kNoSurface : 0.001f * i * i + 1.0f / 3.0f);
    writeDepthFile(dir / "d.depth.tif", image);
    const DepthImage back = readDepthFile(dir / "d.depth.tif");
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.depth.size(), image.depth.size());
    for (std::size_t i = 0; i < image.depth.size(); ++i) {
        if (std::isinf(image.depth[i])) {
            EXPECT_EQ(back.depth[i], kNoSurface);
        } else {
            EXPECT_NEAR(back.depth[i], image.depth[i], depthFileError(image.depth[i])) << i;
        }
    }
    // Clamped to the baked range, as the loader does: inside it, the ends exact.
    DepthImage clamped = back;
    clampDepths(clamped, depthRange(image));
    EXPECT_GE(depthRange(clamped).x, depthRange(image).x);
    EXPECT_LE(depthRange(clamped).y, depthRange(image).y);
    EXPECT_EQ(clamped.depth[0], kNoSurface);
    EXPECT_THROW(writeDepthFile(dir / "bad.depth.tif", DepthImage{3, 3, {1.0f}}), Error);
    EXPECT_THROW(readDepthFile(dir / "missing.depth.tif"), Error);
    // The size the runtime expects: the same file read with it, and refused from its header with another.
    EXPECT_EQ(readDepthFile(dir / "d.depth.tif", glm::ivec2(7, 5)).depth, back.depth);
    EXPECT_THAT(
        [&] { readDepthFile(dir / "d.depth.tif", glm::ivec2(8, 5)); },
        ::testing::ThrowsMessage<Error>(HasSubstr("d.depth.tif: expected 8 x 5 texels (the march's depths of its "
                                                  "colour), got 7 x 5")));
}

// Bakes from before the 16-bit codes stored 32-bit floats: still read, bit for bit.
// A full disk while baking depth (on demand, mid-run) says so, naming the file and the bytes
// needed, before the image library's own words (which say only "Could not write").
TEST(DepthFile, AFullDiskSaysSoNamingTheFile) {
    const test::TempFolder dir("depth_file_full");
    const test::SmallDisk disk(dir / "disk", 64 * 1024);
    if (!disk.mounted()) GTEST_SKIP() << disk.why();
    DepthImage image{256, 256, {}};
    std::uint32_t state = 1;             // noise: zip cannot shrink 128 KiB of codes to fit 64 KiB
    for (int i = 0; i < 256 * 256; ++i)  // 0 to 10 m: codes over most of their range
        image.depth.push_back(float((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f * 10.0f);
    // 256 x 256 codes of 2 bytes: 131072 bytes before compression.
    EXPECT_THAT([&] { writeDepthFile(disk.path() / "t.depth.tif", image); },
                ::testing::ThrowsMessage<Error>(HasSubstr((disk.path() / "t.depth.tif").string() +
                                                          ": cannot write the depth file: the disk is full (131072 "
                                                          "bytes needed, ")));
    EXPECT_TRUE(std::filesystem::is_empty(disk.path()));  // no temporary left
}

TEST(DepthFile, FloatDepthFilesAreStillReadBitForBit) {
    const auto dir = scratch("float");
    const std::vector<float> depths{0.25f, kNoSurface, 1.0f / 3.0f, 17.5f, 0.0f, 123.456f};
    const std::string file = (dir / "old.depth.tif").string();
    auto out = OIIO::ImageOutput::create(file);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(3, 2, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    ASSERT_TRUE(out->open(file, spec) && out->write_image(OIIO::TypeDesc::FLOAT, depths.data()) && out->close());
    const DepthImage back = readDepthFile(file);
    ASSERT_EQ(back.depth.size(), depths.size());
    EXPECT_EQ(std::memcmp(back.depth.data(), depths.data(), depths.size() * sizeof(float)), 0);
    // Neither codes nor floats: refused, saying what it found.
    const std::string bytes = (dir / "bytes.depth.tif").string();
    auto byteOut = OIIO::ImageOutput::create(bytes);
    OIIO::ImageSpec byteSpec(2, 1, 1, OIIO::TypeDesc::UINT8);
    const unsigned char pixels[2] = {1, 2};
    ASSERT_TRUE(byteOut->open(bytes, byteSpec) && byteOut->write_image(OIIO::TypeDesc::UINT8, pixels) &&
                byteOut->close());
    try {
        readDepthFile(bytes);
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("expected 16-bit depth codes or 32-bit float depths, got uint8"));
    }
}

// The in-memory entry point (what the fuzz target reads) is the file's reader after the open:
// the same depths and refusals, named as told. Bytes that are not a TIFF are refused by both,
// never handed to another format's reader (the image library's RLA reader aborted the process
// on these bytes; the fuzz corpus keeps them).
TEST(DepthFile, BytesInMemoryReadAsTheFile) {
    const auto dir = scratch("memory");
    DepthImage image{7, 5, {}};
    for (int i = 0; i < 35; ++i) image.depth.push_back(i % 4 == 0 ? kNoSurface : 0.01f * i);
    writeDepthFile(dir / "d.depth.tif", image);
    const std::string bytes = test::readFile(dir / "d.depth.tif");
    const auto span = [](const std::string& b) {
        return std::span(reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
    };
    const DepthImage fromFile = readDepthFile(dir / "d.depth.tif", glm::ivec2(7, 5));
    const DepthImage fromMemory = readDepthFile(span(bytes), "m.depth.tif", glm::ivec2(7, 5));
    EXPECT_EQ(fromMemory.width, 7);
    EXPECT_EQ(fromMemory.height, 5);
    EXPECT_EQ(std::memcmp(fromMemory.depth.data(), fromFile.depth.data(), 35 * sizeof(float)), 0);
    EXPECT_THAT([&] { readDepthFile(span(bytes), "m.depth.tif", glm::ivec2(8, 5)); },
                ::testing::ThrowsMessage<Error>(HasSubstr("m.depth.tif: expected 8 x 5 texels")));
    EXPECT_THAT([&] { readDepthFile(span(bytes.substr(0, 100)), "cut.depth.tif"); },
                ::testing::ThrowsMessage<Error>(HasSubstr("cut.depth.tif: ")));
    const std::string rla =
        test::readFile(CAVEWALL_SOURCE_DIR "/tests/fuzz/corpus/depth_file/not_a_tiff_rla_abort.bin");
    const std::string notTiff = rla.substr(4);  // the fuzz input's first 4 bytes are the expected size
    test::writeFile(dir / "rla.depth.tif", notTiff);
    EXPECT_THAT(
        [&] { readDepthFile(dir / "rla.depth.tif"); },
        ::testing::ThrowsMessage<Error>(HasSubstr("rla.depth.tif: cannot read the depth file, expected a TIFF")));
    EXPECT_THAT(
        [&] { readDepthFile(span(notTiff), "rla.depth.tif"); },
        ::testing::ThrowsMessage<Error>(HasSubstr("rla.depth.tif: cannot read the depth file, expected a TIFF")));
}

// Float files holding what no bake writes, and sizes beyond any bake, are refused naming the
// texel or the size: a NaN would reach the screen, a huge header would allocate gigabytes.
TEST(DepthFile, NaNNegativeDepthsAndHugeSizesAreRefused) {
    const auto dir = scratch("float-bad");
    auto writeFloats = [&](const std::string& name, int w, int h, const std::vector<float>& v) {
        const std::string file = (dir / name).string();
        auto out = OIIO::ImageOutput::create(file);
        OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::FLOAT);
        EXPECT_TRUE(out->open(file, spec) && out->write_image(OIIO::TypeDesc::FLOAT, v.data()) && out->close());
        return file;
    };
    const struct {
        std::vector<float> depths;
        const char* message;
    } cases[] = {
        {{1.0f, std::nanf(""), 2.0f, 3.0f},
         "texel (1, 0): expected a depth >= 0 m or +infinity (nothing drawn), got nan"},
        {{1.0f, 2.0f, -0.5f, 3.0f}, "texel (0, 1): expected a depth >= 0 m or +infinity (nothing drawn), got -0.5"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.message);
        const std::string file = writeFloats("bad.depth.tif", 2, 2, c.depths);
        EXPECT_THAT([&] { readDepthFile(file); }, ::testing::ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    // Tiles: no depth file is written in tiles, and the image library reads them through a buffer
    // of the size the header gives a tile (17 GB for the fuzz corpus's tiled_huge_tile_oom.bin).
    const std::string tiled = (dir / "tiled.depth.tif").string();
    auto tiledOut = OIIO::ImageOutput::create(tiled);
    OIIO::ImageSpec tiledSpec(2, 2, 1, OIIO::TypeDesc::UINT16);
    tiledSpec.tile_width = tiledSpec.tile_height = 16;
    const std::uint16_t codes[4] = {2, 3, 4, 5};
    ASSERT_TRUE(tiledOut->open(tiled, tiledSpec) && tiledOut->write_image(OIIO::TypeDesc::UINT16, codes) &&
                tiledOut->close());
    EXPECT_THAT([&] { readDepthFile(tiled); },
                ::testing::ThrowsMessage<Error>(HasSubstr("tiled.depth.tif: expected a TIFF in scanlines (as depth "
                                                          "files are written), got tiles of 16 x 16 texels")));
    // Tiles 17 GB in size, and 2^32 - 1 texels high (read as -1): both refused from the header.
    for (const char* input : {"depth_file/tiled_huge_tile_oom.bin", "cluster_impostor/tiled_negative_tile_hang.tx"}) {
        SCOPED_TRACE(input);
        std::string bytes = test::readFile(std::string(CAVEWALL_SOURCE_DIR "/tests/fuzz/corpus/") + input);
        if (bytes.rfind("II", 0) != 0) bytes.erase(0, 4);  // a depth_file input starts with the expected size
        EXPECT_THAT(
            [&] {
                readDepthFile(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
                              "huge.depth.tif");
            },
            ::testing::ThrowsMessage<Error>(HasSubstr("huge.depth.tif: expected a TIFF in scanlines")));
    }
    const std::string wide =
        writeFloats("wide.depth.tif", kMaxDepthFileSide + 1, 1, std::vector<float>(kMaxDepthFileSide + 1, 1.0f));
    EXPECT_THAT([&] { readDepthFile(wide); },
                ::testing::ThrowsMessage<Error>(HasSubstr("expected at most 16384 x 16384 texels (the largest bake), "
                                                          "got 16385 x 1")));
}

TEST(DepthFile, ATextureIsValidOnlyWithItsDepthFile) {
    const auto dir = scratch("valid");
    std::ofstream(dir / "tex_0000_0000000000000001.tx") << "colour";
    writeDepthFile(dir / "tex_0000_0000000000000001.depth.tif", DepthImage{2, 1, {1.0f, 2.0f}});
    BakedTexture t;
    t.file = "tex_0000_0000000000000001.tx";
    t.bytes = 6;
    t.hash = contentHashFile(dir / t.file).value();
    EXPECT_TRUE(textureFileValid(dir, t));  // a flat texture: no depth file needed
    t.depthFile = depthFileName(t.file);
    t.depthBytes = std::filesystem::file_size(dir / t.depthFile);
    t.depthHash = contentHashFile(dir / t.depthFile).value();
    EXPECT_TRUE(textureFileValid(dir, t));
    writeDepthFile(dir / t.depthFile, DepthImage{2, 1, {1.0f, 2.5f}});  // replaced: same size, other hash
    EXPECT_FALSE(textureFileValid(dir, t));
    std::filesystem::remove(dir / t.depthFile);
    EXPECT_FALSE(textureFileValid(dir, t));
}

TEST(DepthFile, ManifestKeepsDepthEntriesAndRejectsBadOnes) {
    BakeManifest m{0x0123456789abcdefull, 10.0, {}};
    BakedTexture t{3, 1, 2, {0.5, 1.6, -2.25}, {512, 256}, "tex_0003.tx", 42, 0xfeedull};
    t.depthFile = "tex_0003.depth.tif";
    t.depthBytes = 99;
    t.depthHash = 0xbeefull;
    t.depthRange = {0.25, 18.5};
    m.textures.push_back(t);
    EXPECT_EQ(manifestFromJson(manifestToJson(m), "m.json"), m);
    std::string text = manifestToJson(m);
    text.replace(text.find("tex_0003.depth.tif"), 18, "../escape.depth.ti");
    try {
        manifestFromJson(text, "m.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("depth"));
        EXPECT_THAT(e.what(), HasSubstr("plain file name"));
    }
}

}  // namespace
}  // namespace cavewall::walls
