#pragma once
// Block-compressed baked wall textures: S3TC/BC encoding and decoding of MIP levels, and their
// file (".bct"). GL-free; the GL side uploads the blocks as they are (walls/gl/wall_quad.h
// uploadWallTexture, walls/gl/texture_store.h).
//
// What llvmpipe offers (Mesa 22.3.6, LLVM 15, Debian 12, EGL_PLATFORM=surfaceless, GL 4.5
// core; printed by the GL test CompressedTextureTest.ListsCompressedFormatsAndLlvmpipeHasS3tcSrgb):
// GL_EXT_texture_compression_s3tc (+ _dxt1, ANGLE dxt3/dxt5), GL_EXT_texture_sRGB (which adds
// the sRGB S3TC formats; GL_EXT_texture_compression_s3tc_srgb itself is not listed),
// GL_ARB_texture_compression_bptc (BC6H/BC7), GL_ARB_texture_compression_rgtc and
// GL_EXT_texture_compression_rgtc (BC4/BC5), GL_KHR_texture_compression_astc_ldr and
// GL_3DFX_texture_compression_FXT1. GL_COMPRESSED_TEXTURE_FORMATS lists only 12 "general
// purpose" formats: FXT1 RGB/RGBA, DXT1 RGB, DXT3, DXT5 and seven ETC2/EAC formats; neither
// the sRGB S3TC formats nor BPTC are listed, but both are accepted (the GL test uploads sRGB
// DXT1 and DXT5 and reads back GL_TEXTURE_COMPRESSED and the stored size). BPTC (BC7) would
// keep more colour at 1 byte per texel, but libsquish encodes BC1-BC5 only, and Debian's other
// encoder (nvidia-texture-tools) was not tried: S3TC it is. llvmpipe decodes blocks as it
// samples them (it keeps no decoded copy); the fill cost is bench/wall_pass_bench.cpp's
// FillLayer/compressed.
//
// Formats (`--texture-format`). Encoders: Bc1 blocks whose 16 texels are all opaque (nearly all
// of a wall's visible blocks) are fitted by stb_dxt (Debian's libstb-dev, high-quality mode,
// kept in the four-colour mode): on 100 textures of the plant's bake 2.5x faster than
// libsquish's cluster fit (3.6 against 9.1 ms a texture, deflate and write included), 0.08 dB
// closer over grey (40.22 against 40.14 dB) and 12 % smaller on disk after deflate. Blocks
// with transparent texels, and every Bc3 block, are libsquish's (cluster fit):
//  - Rgba8: the tiled, zip-compressed TIFF of 8-bit texels (walls/texture_mips.h);
//    4 bytes per texel on the GPU.
//  - Bc1: GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT, 8 bytes per 4 x 4 block (0.5 byte per
//    texel). Alpha is one bit: texels with alpha < 128 become transparent black (0, 0, 0, 0),
//    the others opaque. Because an opaque BC1 texel is drawn with alpha 1, its colour is stored
//    *un-premultiplied* (the linear premultiplied colour divided by alpha, then sRGB-encoded):
//    a half-covered edge texel then shows the surface's own colour with a hard edge, instead of
//    the premultiplied colour (darkened by its coverage) drawn as if it covered the texel.
//  - Bc3: GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT, 16 bytes per block (1 byte per texel):
//    premultiplied colour as stored (walls/texture_mips.h) plus interpolated 8-bit alpha, so
//    partial coverage survives. The colour fit weighs every texel alike (not by alpha): a
//    premultiplied colour is added to what lies behind whatever its alpha, so a transparent
//    texel's colour error (alpha 0 is kept exactly, colour only as close as the block's four
//    colours allow) shows like any other.
// Both decode in the sampler from sRGB to linear like GL_SRGB8_ALPHA8 (the sRGB variants
// linearise R, G, B after decoding the block), so the wall pass and its blending are unchanged.
// Blocks that are entirely transparent (most of a wall's texels) skip the encoder.
//
// File (".bct", little-endian): magic "CWBC", u32 version 2, u32 format (1 = Bc1, 3 = Bc3),
// u32 width, u32 height (of level 0, each in [1, 16384]), u32 levels (the MIP chain, in
// [1, full chain]), u32 stored size, then one zstd frame (Debian's libzstd) holding every
// level's blocks, level 0 first. A level is its blocks (row by row, blocksX = ceil(width / 4)
// per row) rearranged field by field (Bc1: all colour endpoint pairs, then all index words; Bc3:
// alpha endpoints, alpha indices, colour endpoints, colour indices), which groups alike bytes.
// Version 1 files (still read) store a u32 size per level instead and deflate (zlib) each level
// on its own: one frame over all levels, and zstd's stronger coder, make the clinic's colour
// files 9 % smaller.
// Writes are atomic (temporary file, rename) and checked.

#include "scenes/scene.h"
#include "walls/texture_rect.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cavewall::walls {

enum class TextureFormat : std::uint8_t { Rgba8, Bc1, Bc3 };
std::string_view textureFormatName(TextureFormat format);
// The words `--texture-format` accepts, in the order its help lists them.
inline constexpr std::array<std::pair<std::string_view, TextureFormat>, 3> kTextureFormatNames{
    {{"rgba8", TextureFormat::Rgba8}, {"bc1", TextureFormat::Bc1}, {"bc3", TextureFormat::Bc3}}};

// `--texture-format`'s default on bake, run, bench and demo (chosen from measurements:
// docs/virtual-walls.md, texture storage). BakeSettings, RunOptions and BenchOptions default
// to Rgba8.
inline constexpr TextureFormat kDefaultTextureFormat = TextureFormat::Bc1;

// Bytes of one 4 x 4 block: 8 (Bc1), 16 (Bc3); 0 for Rgba8.
int blockBytes(TextureFormat format);
// Bytes of a width x height level in `format` (Rgba8: 4 per texel; blocks: whole blocks).
std::size_t levelBytes(TextureFormat format, int width, int height);

struct BlockLevel {
    int width = 0, height = 0;         // texels
    std::vector<std::uint8_t> blocks;  // levelBytes(format, width, height) bytes
};

// Every MIP level of one texture as the GPU takes it: RGBA8 images (walls/texture_mips.h
// convention) or compressed blocks. Converts from RGBA8 levels, so a decoder that returns
// std::vector<scenes::Image> is one that returns TextureLevels.
struct TextureLevels {
    TextureFormat format = TextureFormat::Rgba8;
    std::vector<scenes::Image> rgba;  // format Rgba8: largest first
    std::vector<BlockLevel> blocks;   // Bc1, Bc3: largest first

    TextureLevels() = default;
    TextureLevels(std::vector<scenes::Image> levels) : rgba(std::move(levels)) {}  // NOLINT: implicit
    TextureLevels(TextureFormat f, std::vector<BlockLevel> levels) : format(f), blocks(std::move(levels)) {}
    std::size_t count() const { return format == TextureFormat::Rgba8 ? rgba.size() : blocks.size(); }
    int width() const;  // of level 0; 0 when empty
    int height() const;
    std::size_t bytes() const;  // GPU bytes of every level
};

// Encodes one level (8-bit RGBA, premultiplied as walls/texture_mips.h says) into `format`
// (Bc1 or Bc3, as the header says). Edges of sizes that are not multiples of 4 are encoded
// from the texels inside the level only.
BlockLevel encodeLevel(const scenes::Image& premultiplied, TextureFormat format);
// The 8-bit RGBA texels a GPU decodes `level` to (before the sRGB decode): for Bc1 opaque
// texels have alpha 255 and un-premultiplied colour, transparent ones are (0, 0, 0, 0).
scenes::Image decodeLevel(const BlockLevel& level, TextureFormat format);
// encodeLevel of every level.
TextureLevels encodeLevels(const std::vector<scenes::Image>& premultiplied, TextureFormat format);

// The format a bake stores a texture in when `asked` is asked for: Bc1 keeps one bit of
// alpha, so a texture with translucent texels (alpha in [8, 247] at level 0, in at least 16
// texels: a window pane's, not a few rounded ones) is stored as Bc3, which keeps them; with
// Bc1 a pane of glass over nothing would vanish (alpha < 0.5) or turn opaque. Every other
// texture, and every other format, as asked. The file says which (readBlockFile).
TextureFormat storedFormat(const scenes::Image& levelZero, TextureFormat asked);

// Writes `levels` (Bc1 or Bc3, level i the next MIP size of level i - 1) as a ".bct" file,
// atomically. Throws cavewall::Error naming the file (bad levels, write failures).
void writeBlockFile(const std::filesystem::path& file, const TextureLevels& levels);
// Reads a ".bct" file. Throws cavewall::Error naming the file, the part (header, level N) and
// what was expected against what was found, for any file that is not exactly one this
// version writes (wrong magic, version or format, sizes out of range, truncated or extra
// bytes, a level that does not inflate to its size).
TextureLevels readBlockFile(const std::filesystem::path& file);
// readBlockFile of a file's bytes; `file` names it in messages.
TextureLevels blocksFromBytes(std::string_view bytes, const std::string& file);

// A baked texture file of any format: ".bct" files (by their magic) through readBlockFile,
// others through scenes::readMipLevels. The pager's default decoder.
TextureLevels readBakedTexture(const std::filesystem::path& file);

// The rectangle (walls/texture_rect.h) of whole texels around every texel of level 0 with
// non-zero alpha, grown by `margin` texels on every side (a coarser MIP level spreads a texel's
// colour a few texels around it when sampled) and clipped to the texture; empty when every
// texel is transparent. A flat wall pixel outside it samples nothing but transparent texels at
// levels up to log2(margin). Block formats are decoded first (decodeLevel).
TextureRect coveredRect(const TextureLevels& levels, int margin);

// The file name extension of baked textures in `format`: ".tx" (TIFF) or ".bct".
std::string_view textureFileExtension(TextureFormat format);

}  // namespace cavewall::walls
