#include "walls/texture_blocks.h"

#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "walls/texture_mips.h"

#include <squish.h>
#include <stb_dxt.h>
#include <zlib.h>
#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <span>

namespace cavewall::walls {

namespace {

constexpr char kMagic[4] = {'C', 'W', 'B', 'C'};
constexpr std::uint32_t kVersion = 2;         // written: every level in one zstd frame
constexpr std::uint32_t kDeflateVersion = 1;  // read: each level deflated on its own
constexpr std::uint32_t kHeaderBytes = 24;    // magic, version, format, width, height, levels
constexpr std::uint32_t kMaxSide = 16384;
// The clinic's cold bake (4,097 BC1 textures of up to 512 texels, 2 cores, llvmpipe): colour
// files 9 % smaller than levels deflated one by one at zlib's default, the bake 69 s against
// 56 s (level 17: 13 % smaller, 78 s); zstd decodes faster than zlib inflates.
constexpr int kZstdLevel = 15;

// Byte widths of a block's fields, stored field by field (the header's "rearranged").
std::vector<int> blockFields(TextureFormat format) {
    if (format == TextureFormat::Bc1) return {4, 4};
    return {2, 6, 4, 4};
}

std::uint32_t formatCode(TextureFormat format) { return format == TextureFormat::Bc1 ? 1u : 3u; }

int squishFlags(TextureFormat format) {
    // Not kWeightColourByAlpha: premultiplied colour adds to the background as it is, whatever
    // the texel's alpha, so an error in a transparent texel's colour shows as much as any other.
    return format == TextureFormat::Bc1 ? squish::kDxt1 | squish::kColourClusterFit
                                        : squish::kDxt5 | squish::kColourClusterFit;
}

void requireBlocks(TextureFormat format, const char* what) {
    if (format != TextureFormat::Bc1 && format != TextureFormat::Bc3)
        throw Error(std::string(what) + ": expected a block format (bc1, bc3), got " +
                    std::string(textureFormatName(format)));
}

int mipCount(int width, int height) {
    int n = 1;
    while (width > 1 || height > 1) {
        width = std::max(1, width / 2);
        height = std::max(1, height / 2);
        ++n;
    }
    return n;
}

// Bc1's texel preparation (header): binary coverage, opaque texels un-premultiplied.
void toBinaryCoverage(std::uint8_t* texel, const std::array<float, 256>& linear) {
    const int a = texel[3];
    if (a < 128) {
        std::fill_n(texel, 4, std::uint8_t(0));
        return;
    }
    if (a == 255) {  // nearly every texel: the round trip's own table, exactly the same bytes
        const std::array<std::uint8_t, 256>& opaque = srgbByteRoundTrip();
        for (int c = 0; c < 3; ++c) texel[c] = opaque[texel[c]];
        return;
    }
    const float alpha = a / 255.0f;
    for (int c = 0; c < 3; ++c) texel[c] = encodeSrgbByte(linear[texel[c]] / alpha);
    texel[3] = 255;
}

// Keeps a Bc1 block in the four-colour mode (endpoint 0 > endpoint 1 as 16-bit numbers), where
// no index means transparent: equal endpoints decode every index alike, so all become 0;
// reversed endpoints are swapped with their indices (0 <-> 1, 2 <-> 3).
void fourColourMode(std::uint8_t* block) {
    const int c0 = block[0] | block[1] << 8, c1 = block[2] | block[3] << 8;
    if (c0 > c1) return;
    if (c0 == c1) {
        std::fill_n(block + 4, 4, std::uint8_t(0));
        return;
    }
    std::swap_ranges(block, block + 2, block + 2);
    for (int i = 4; i < 8; ++i) block[i] ^= 0x55;
}

// A Bc1 block without transparent texels in the four-colour mode only. A whole block (16
// texels) is stb_dxt's fit (header: faster, closer and smaller after deflate than squish's).
// A block cut by the level's edge (fewer texels, masked) is squish's: its Bc1 cluster fit also
// tries the three-colour mode (a quarter of its time), which an opaque block rarely wins; its
// Bc3 colour block is that four-colour fit alone, written with endpoint 0 >= endpoint 1, so it
// decodes the same as a Bc1 block (equal endpoints: every index 0, also the same in both).
void bc1OpaqueBlock(const std::uint8_t* texels, int mask, std::uint8_t* block) {
    if (mask == 0xffff) {
        stb_compress_dxt_block(block, texels, 0, STB_DXT_HIGHQUAL);
        fourColourMode(block);
        return;
    }
    std::uint8_t bc3[16];
    squish::CompressMasked(texels, mask, bc3, squish::kDxt5 | squish::kColourClusterFit);
    std::memcpy(block, bc3 + 8, 8);
}

// The block squish would give a fully transparent block, written directly: Bc1 in its
// three-colour mode (both endpoints 0) with every index 3 (transparent black); Bc3 all zero
// (alpha endpoints 0, so every alpha is 0; colour black).
void transparentBlock(TextureFormat format, std::uint8_t* block) {
    std::fill_n(block, blockBytes(format), std::uint8_t(0));
    if (format == TextureFormat::Bc1) std::fill_n(block + 4, 4, std::uint8_t(0xFF));
}

std::vector<std::uint8_t> splitFields(const std::vector<std::uint8_t>& blocks, TextureFormat format) {
    const int size = blockBytes(format);
    const std::size_t n = blocks.size() / size;
    std::vector<std::uint8_t> out(blocks.size());
    std::size_t at = 0;
    int start = 0;
    for (int width : blockFields(format)) {
        for (std::size_t b = 0; b < n; ++b)
            for (int k = 0; k < width; ++k) out[at++] = blocks[b * size + start + k];
        start += width;
    }
    return out;
}

std::vector<std::uint8_t> joinFields(std::span<const std::uint8_t> fields, TextureFormat format) {
    const int size = blockBytes(format);
    const std::size_t n = fields.size() / size;
    std::vector<std::uint8_t> out(fields.size());
    std::size_t at = 0;
    int start = 0;
    for (int width : blockFields(format)) {
        for (std::size_t b = 0; b < n; ++b)
            for (int k = 0; k < width; ++k) out[b * size + start + k] = fields[at++];
        start += width;
    }
    return out;
}

// One zstd frame of `fields` at kZstdLevel with its content size and a checksum of it (so a
// damaged file is an error, not other blocks).
std::string zstdFrame(const std::vector<std::uint8_t>& fields, const std::filesystem::path& file) {
    const std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> context(ZSTD_createCCtx(), &ZSTD_freeCCtx);
    if (!context) throw Error(file.string() + ": cannot compress the MIP levels (no memory for zstd)");
    std::string packed(ZSTD_compressBound(fields.size()), '\0');
    std::size_t size = ZSTD_CCtx_setParameter(context.get(), ZSTD_c_compressionLevel, kZstdLevel);
    if (!ZSTD_isError(size)) size = ZSTD_CCtx_setParameter(context.get(), ZSTD_c_checksumFlag, 1);
    if (!ZSTD_isError(size))
        size = ZSTD_compress2(context.get(), packed.data(), packed.size(), fields.data(), fields.size());
    if (ZSTD_isError(size))
        throw Error(file.string() + ": cannot compress the MIP levels (" + ZSTD_getErrorName(size) + ")");
    packed.resize(size);
    return packed;
}

void putU32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::uint32_t getU32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<std::uint8_t>(bytes[at + i])) << (8 * i);
    return v;
}

std::string readAll(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot open the compressed texture for reading");
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw Error(file.string() + ": cannot read the compressed texture");
    return bytes;
}

[[noreturn]] void bad(const std::string& file, const std::string& where, const std::string& what) {
    throw Error(file + ": " + where + ": " + what);
}

// Deflate's largest expansion is about 1032:1 (258-byte matches of 2 bits at best): a level
// whose stored size cannot hold its blocks is refused before anything is allocated for them.
constexpr std::size_t kMaxInflation = 1100;
// A zstd block of up to 128 KiB repeating one byte is stored in 4 bytes (an RLE block).
constexpr std::size_t kMaxZstdInflation = 32768;

}  // namespace

std::string_view textureFormatName(TextureFormat format) {
    switch (format) {
        case TextureFormat::Rgba8: return "rgba8";
        case TextureFormat::Bc1: return "bc1";
        case TextureFormat::Bc3: return "bc3";
    }
    return "?";
}

int blockBytes(TextureFormat format) {
    return format == TextureFormat::Bc1 ? 8 : format == TextureFormat::Bc3 ? 16 : 0;
}

std::size_t levelBytes(TextureFormat format, int width, int height) {
    if (format == TextureFormat::Rgba8) return std::size_t(width) * height * 4;
    return std::size_t((width + 3) / 4) * ((height + 3) / 4) * blockBytes(format);
}

int TextureLevels::width() const {
    if (format == TextureFormat::Rgba8) return rgba.empty() ? 0 : rgba[0].width;
    return blocks.empty() ? 0 : blocks[0].width;
}

int TextureLevels::height() const {
    if (format == TextureFormat::Rgba8) return rgba.empty() ? 0 : rgba[0].height;
    return blocks.empty() ? 0 : blocks[0].height;
}

std::size_t TextureLevels::bytes() const {
    std::size_t sum = 0;
    for (const scenes::Image& l : rgba) sum += l.rgba.size();
    for (const BlockLevel& l : blocks) sum += l.blocks.size();
    return sum;
}

BlockLevel encodeLevel(const scenes::Image& image, TextureFormat format) {
    requireBlocks(format, ("encoding '" + image.name + "'").c_str());
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != std::size_t(image.width) * image.height * 4)
        throw Error("encoding '" + image.name + "': expected " + std::to_string(image.width) + " x " +
                    std::to_string(image.height) + " RGBA texels, got " + std::to_string(image.rgba.size()) + " bytes");
    std::array<float, 256> linear{};
    for (int i = 0; i < 256; ++i) linear[i] = srgbToLinear(i / 255.0f);
    BlockLevel out{image.width, image.height, std::vector<std::uint8_t>(levelBytes(format, image.width, image.height))};
    const int size = blockBytes(format), flags = squishFlags(format);
    std::uint8_t* block = out.blocks.data();
    for (int by = 0; by < image.height; by += 4)
        for (int bx = 0; bx < image.width; bx += 4, block += size) {
            std::uint8_t texels[16 * 4] = {};
            int mask = 0;
            bool transparent = true, opaque = true;
            for (int y = 0; y < 4 && by + y < image.height; ++y)
                for (int x = 0; x < 4 && bx + x < image.width; ++x) {
                    std::uint8_t* t = &texels[(y * 4 + x) * 4];
                    std::memcpy(t, &image.rgba[(std::size_t(by + y) * image.width + bx + x) * 4], 4);
                    if (format == TextureFormat::Bc1) toBinaryCoverage(t, linear);
                    transparent = transparent && (t[0] | t[1] | t[2] | t[3]) == 0;
                    opaque = opaque && t[3] == 255;
                    mask |= 1 << (y * 4 + x);
                }
            if (transparent)
                transparentBlock(format, block);
            else if (format == TextureFormat::Bc1 && opaque)
                bc1OpaqueBlock(texels, mask, block);
            else
                squish::CompressMasked(texels, mask, block, flags);
        }
    return out;
}

scenes::Image decodeLevel(const BlockLevel& level, TextureFormat format) {
    requireBlocks(format, "decoding a level");
    if (level.width <= 0 || level.height <= 0 || level.blocks.size() != levelBytes(format, level.width, level.height))
        throw Error("decoding a " + std::string(textureFormatName(format)) + " level of " +
                    std::to_string(level.width) + " x " + std::to_string(level.height) + ": expected " +
                    std::to_string(levelBytes(format, level.width, level.height)) + " bytes of blocks, got " +
                    std::to_string(level.blocks.size()));
    scenes::Image image{"decoded", level.width, level.height,
                        std::vector<std::uint8_t>(std::size_t(level.width) * level.height * 4)};
    squish::DecompressImage(image.rgba.data(), level.width, level.height, level.blocks.data(), squishFlags(format));
    return image;
}

TextureLevels encodeLevels(const std::vector<scenes::Image>& premultiplied, TextureFormat format) {
    TextureLevels out(format, {});
    for (const scenes::Image& l : premultiplied) out.blocks.push_back(encodeLevel(l, format));
    return out;
}

TextureFormat storedFormat(const scenes::Image& levelZero, TextureFormat asked) {
    if (asked != TextureFormat::Bc1) return asked;
    constexpr int kLeast = 16;
    int translucent = 0;
    for (std::size_t i = 3; i < levelZero.rgba.size() && translucent < kLeast; i += 4)
        translucent += levelZero.rgba[i] >= 8 && levelZero.rgba[i] <= 247;
    return translucent >= kLeast ? TextureFormat::Bc3 : TextureFormat::Bc1;
}

void writeBlockFile(const std::filesystem::path& file, const TextureLevels& levels) {
    requireBlocks(levels.format, file.string().c_str());
    const auto& l = levels.blocks;
    if (l.empty()) throw Error(file.string() + ": expected at least one MIP level, got none");
    if (l[0].width < 1 || l[0].height < 1 || std::uint32_t(l[0].width) > kMaxSide ||
        std::uint32_t(l[0].height) > kMaxSide)
        throw Error(file.string() + ": level 0: expected a size in [1, 16384], got " + std::to_string(l[0].width) +
                    " x " + std::to_string(l[0].height));
    for (std::size_t i = 0; i < l.size(); ++i) {
        const int w = i == 0 ? l[0].width : std::max(1, l[i - 1].width / 2);
        const int h = i == 0 ? l[0].height : std::max(1, l[i - 1].height / 2);
        if (l[i].width != w || l[i].height != h || l[i].blocks.size() != levelBytes(levels.format, w, h))
            throw Error(file.string() + ": MIP level " + std::to_string(i) + ": expected " + std::to_string(w) + " x " +
                        std::to_string(h) + " in " + std::to_string(levelBytes(levels.format, w, h)) + " bytes, got " +
                        std::to_string(l[i].width) + " x " + std::to_string(l[i].height) + " in " +
                        std::to_string(l[i].blocks.size()));
    }
    std::vector<std::uint8_t> fields;
    for (const BlockLevel& level : l) {
        const std::vector<std::uint8_t> f = splitFields(level.blocks, levels.format);
        fields.insert(fields.end(), f.begin(), f.end());
    }
    const std::string packed = zstdFrame(fields, file);
    std::string bytes(kMagic, 4);
    putU32(bytes, kVersion);
    putU32(bytes, formatCode(levels.format));
    putU32(bytes, std::uint32_t(l[0].width));
    putU32(bytes, std::uint32_t(l[0].height));
    putU32(bytes, std::uint32_t(l.size()));
    putU32(bytes, std::uint32_t(packed.size()));
    bytes += packed;
    scenes::writeBytesAtomically(file, bytes);
}

TextureLevels readBlockFile(const std::filesystem::path& file) { return blocksFromBytes(readAll(file), file.string()); }

namespace {

struct BlockHeader {
    std::uint32_t version = 0;
    TextureFormat format = TextureFormat::Bc1;
    int width = 0, height = 0, levels = 0;
};

BlockHeader readHeader(const std::string& bytes, const std::string& file) {
    if (bytes.size() < kHeaderBytes)
        bad(file, "header",
            "expected at least " + std::to_string(kHeaderBytes) + " bytes, got " + std::to_string(bytes.size()));
    if (bytes.compare(0, 4, kMagic, 4) != 0) bad(file, "header", "expected the magic 'CWBC', got other bytes");
    BlockHeader h;
    h.version = getU32(bytes, 4);
    if (h.version != kVersion && h.version != kDeflateVersion)
        bad(file, "header", "expected version 1 or 2, got " + std::to_string(h.version));
    const std::uint32_t code = getU32(bytes, 8);
    if (code != 1 && code != 3) bad(file, "header", "expected format 1 (bc1) or 3 (bc3), got " + std::to_string(code));
    h.format = code == 1 ? TextureFormat::Bc1 : TextureFormat::Bc3;
    const std::uint32_t width = getU32(bytes, 12), height = getU32(bytes, 16), count = getU32(bytes, 20);
    if (width < 1 || width > kMaxSide || height < 1 || height > kMaxSide)
        bad(file, "header",
            "expected a size in [1, 16384], got " + std::to_string(width) + " x " + std::to_string(height));
    const int chain = mipCount(int(width), int(height));
    if (count < 1 || count > std::uint32_t(chain))
        bad(file, "header", "expected 1 to " + std::to_string(chain) + " MIP levels, got " + std::to_string(count));
    h.width = int(width);
    h.height = int(height);
    h.levels = int(count);
    return h;
}

// Version 1: a stored size per level, then each level deflated on its own.
TextureLevels readDeflatedLevels(const std::string& bytes, const BlockHeader& header, const std::string& file) {
    std::size_t at = kHeaderBytes + 4ull * header.levels;
    if (bytes.size() < at)
        bad(file, "header",
            "expected " + std::to_string(at) + " bytes of level sizes, got a file of " + std::to_string(bytes.size()));
    TextureLevels out(header.format, {});
    int w = header.width, h = header.height;
    for (int i = 0; i < header.levels; ++i) {
        const std::string where = "MIP level " + std::to_string(i);
        const std::size_t stored = getU32(bytes, kHeaderBytes + 4ull * i);
        if (bytes.size() - at < stored)
            bad(file, where,
                "expected " + std::to_string(stored) + " stored bytes, got " + std::to_string(bytes.size() - at) +
                    " (the file is truncated)");
        const std::size_t expected = levelBytes(header.format, w, h);
        if (expected > stored * kMaxInflation + 64)
            bad(file, where,
                "expected " + std::to_string(stored) + " deflated bytes to hold " + std::to_string(expected) +
                    " bytes of blocks, got too few for that");
        std::vector<std::uint8_t> fields(expected);
        uLongf size = expected;
        const int z = uncompress(fields.data(), &size, reinterpret_cast<const Bytef*>(bytes.data() + at), stored);
        if (z != Z_OK || size != expected)
            bad(file, where,
                "expected " + std::to_string(stored) + " deflated bytes that inflate to " + std::to_string(expected) +
                    " bytes of " + std::string(textureFormatName(header.format)) + " blocks, got " +
                    (z == Z_OK ? std::to_string(size) + " bytes" : std::string("corrupt data (") + zError(z) + ")"));
        out.blocks.push_back({w, h, joinFields(fields, header.format)});
        at += stored;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    if (at != bytes.size())
        bad(file, "end",
            "expected " + std::to_string(at) + " bytes, got " + std::to_string(bytes.size()) + " (extra bytes)");
    return out;
}

// Version 2: one stored size, then every level's fields in one zstd frame, level 0 first.
TextureLevels readZstdLevels(const std::string& bytes, const BlockHeader& header, const std::string& file) {
    const std::size_t at = kHeaderBytes + 4;
    if (bytes.size() < at)
        bad(file, "header",
            "expected " + std::to_string(at) + " bytes with the stored size, got " + std::to_string(bytes.size()));
    const std::size_t stored = getU32(bytes, kHeaderBytes);
    if (bytes.size() - at != stored)
        bad(file, "levels",
            "expected " + std::to_string(stored) + " stored bytes, got " + std::to_string(bytes.size() - at) +
                (bytes.size() - at < stored ? " (the file is truncated)" : " (extra bytes)"));
    std::vector<glm::ivec2> sizes;  // of each level, level 0 first
    std::size_t expected = 0;
    for (glm::ivec2 size(header.width, header.height); int(sizes.size()) < header.levels;
         size = glm::max(size / 2, glm::ivec2(1))) {
        sizes.push_back(size);
        expected += levelBytes(header.format, size.x, size.y);
    }
    const std::string what = "expected " + std::to_string(stored) + " compressed bytes that decompress to " +
                             std::to_string(expected) + " bytes of " + std::string(textureFormatName(header.format)) +
                             " blocks, got ";
    if (expected > stored * kMaxZstdInflation + 64)
        bad(file, "levels",
            "expected " + std::to_string(stored) + " compressed bytes to hold " + std::to_string(expected) +
                " bytes of blocks, got too few for that");
    // The frame's own content size is checked before anything is allocated for it.
    const unsigned long long declared = ZSTD_getFrameContentSize(bytes.data() + at, stored);
    if (declared != expected)
        bad(file, "levels",
            what + (declared == ZSTD_CONTENTSIZE_ERROR     ? std::string("no zstd frame")
                    : declared == ZSTD_CONTENTSIZE_UNKNOWN ? std::string("a frame of unstated size")
                                                           : "a frame of " + std::to_string(declared) + " bytes"));
    std::vector<std::uint8_t> fields(expected);
    const std::size_t size = ZSTD_decompress(fields.data(), fields.size(), bytes.data() + at, stored);
    if (ZSTD_isError(size) || size != expected)
        bad(file, "levels",
            what + (ZSTD_isError(size) ? std::string("corrupt data (") + ZSTD_getErrorName(size) + ")"
                                       : std::to_string(size) + " bytes"));
    TextureLevels out(header.format, {});
    std::size_t from = 0;
    for (const glm::ivec2 size : sizes) {
        const std::size_t n = levelBytes(header.format, size.x, size.y);
        out.blocks.push_back({size.x, size.y, joinFields(std::span(fields).subspan(from, n), header.format)});
        from += n;
    }
    return out;
}

}  // namespace

TextureLevels blocksFromBytes(std::string_view view, const std::string& file) {
    const std::string bytes(view);
    const BlockHeader header = readHeader(bytes, file);
    return header.version == kDeflateVersion ? readDeflatedLevels(bytes, header, file)
                                             : readZstdLevels(bytes, header, file);
}

TextureLevels readBakedTexture(const std::filesystem::path& file) {
    char magic[4] = {};
    {
        std::ifstream in(file, std::ios::binary);
        in.read(magic, 4);
    }
    if (std::memcmp(magic, kMagic, 4) == 0) return readBlockFile(file);
    return TextureLevels(scenes::readMipLevels(file));
}

TextureRect coveredRect(const TextureLevels& levels, int margin) {
    if (levels.count() == 0) return noRect();
    const scenes::Image decoded =
        levels.format == TextureFormat::Rgba8 ? scenes::Image{} : decodeLevel(levels.blocks[0], levels.format);
    const scenes::Image& image = levels.format == TextureFormat::Rgba8 ? levels.rgba[0] : decoded;
    return texelBounds(image.width, image.height, margin,
                       [&](int i, int j) { return image.rgba[(std::size_t(j) * image.width + i) * 4 + 3] != 0; });
}

std::string_view textureFileExtension(TextureFormat format) { return format == TextureFormat::Rgba8 ? ".tx" : ".bct"; }

}  // namespace cavewall::walls
