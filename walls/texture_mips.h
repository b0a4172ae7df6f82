#pragma once
// MIP chains of baked wall textures, correct for alpha, and their tiled MIP-mapped files.
// GL-free (CPU and OpenImageIO only); it lives here because only the baker writes these files.
//
// Pixel convention of every baked texture level (files, scenes::readMipLevels, the pager):
// 8-bit RGBA, rows top to bottom; alpha is linear coverage; R, G, B are the sRGB encoding of the
// *linear premultiplied* colour (colour × alpha computed in linear light). Upload as
// GL_SRGB8_ALPHA8 and blend with (GL_ONE, GL_ONE_MINUS_SRC_ALPHA): the sampler decodes to linear
// premultiplied colour, which filters and blends correctly. A fully transparent texel is
// (0, 0, 0, 0).
//
// Why premultiply before downsampling: averaging straight (non-premultiplied) colour lets the
// colour of transparent texels (black, or garbage) bleed into half-transparent edge texels,
// which then look dark; averaging sRGB-encoded values darkens edges further. Here every level is
// box-filtered from the previous one in linear premultiplied float, and only then encoded.

#include "scenes/scene.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::walls {

// sRGB transfer functions on [0, 1] (IEC 61966-2-1).
float srgbToLinear(float encoded);
float linearToSrgb(float linear);
// The stored byte of a linear value: round(255 * linearToSrgb(clamp(linear, 0, 1))), exactly,
// from a table of the 255 values where the byte steps up (no pow per texel); 0 for NaN.
std::uint8_t encodeSrgbByte(float linear);
// encodeSrgbByte(srgbToLinear(b / 255.0f)) for every byte b: an opaque texel's stored byte
// (fast paths that must give exactly what the float round trip gives).
const std::array<std::uint8_t, 256>& srgbByteRoundTrip();

// The full MIP chain of `straight`, an 8-bit RGBA image with straight (non-premultiplied)
// alpha and sRGB-encoded colour, as produced by an sRGB render target: level 0 is the image
// premultiplied, each next level has max(1, floor(size / 2)) texels per side and is an exact
// area-weighted box filter of the previous one (odd sizes included), down to 1 x 1. Every level
// follows the pixel convention above. `straight` must be non-empty.
std::vector<scenes::Image> premultipliedMipChain(const scenes::Image& straight);
// The same chain of `premultiplied`, whose colour is already premultiplied by its alpha: what
// an sRGB render target holds once blended surfaces are drawn over transparent black
// (glBlendFuncSeparate(SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ONE, ONE_MINUS_SRC_ALPHA): a pane of
// glass over nothing leaves its colour times its alpha). Where alpha is 0 or 1, as everywhere
// but such panes, both chains are the same.
std::vector<scenes::Image> mipChainOfPremultiplied(const scenes::Image& premultiplied);

struct MipFileOptions {
    int tileSize = 64;                // tile edge in texels; a multiple of 16 in [16, 1024]
    std::string compression = "zip";  // OIIO "compression" attribute ("none", "zip", "lzw")
};

// Writes `levels` (largest first, each level the next MIP size of the previous one) as one tiled,
// MIP-mapped file, the format chosen from the extension (".tx" or ".tif": TIFF). The file says
// that alpha is associated (premultiplied) and that colour is sRGB. Atomic: writes a temporary
// file in the same folder, then renames it. Throws cavewall::Error naming the file.
void writeMipFile(const std::filesystem::path& file, const std::vector<scenes::Image>& levels,
                  const MipFileOptions& options = {});

}  // namespace cavewall::walls
