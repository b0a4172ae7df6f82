#pragma once
// The depth half of a depth wall's texture on disk (walls/depth_wall.h): one scanline TIFF of
// 16-bit codes, one channel, zip compressed with horizontal differencing. A depth d >= 0 (metres
// behind the wall plane) is stored as q = round(1 + 65534 L / (L + d)), L = kDepthFileMetres,
// clamped to [2, 65535]; q = 0 where nothing was drawn (+inf). The code is a reciprocal depth,
// so a plane seen from the sampling point changes it almost linearly across the texture and the
// differences deflate well (2.4 times smaller than lossless float on the default plant). Decoded,
// d' = L (65534 / (q - 1) - 1) is within depthFileError(d) of d: 0.03 mm at 1 m, 0.9 mm at
// 10 m, 8 cm at 100 m. The depth walls' bounds (depth_wall.h) hold for any stored depth inside
// the wall's depth span, so the loader clamps decoded depths to the texture's baked range
// (clampDepths), which lies inside the span; only the image (the hit positions, by far less than
// a texel) sees the rounding. Older files of 32-bit float depths are read as
// they are. Written atomically beside the colour file, named after it (depthFileName), listed
// with its own size and hash in the manifest (walls/bake_manifest.h BakedTexture::depthFile).

#include "walls/depth_wall.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace cavewall::walls {

inline constexpr double kDepthFileMetres = 1.0;  // L of the 16-bit code
inline constexpr int kMaxDepthFileSide = 16384;  // texels per side at most (the largest bake)

// "tex_0003_<key>.tx" -> "tex_0003_<key>.depth.tif"
std::string depthFileName(const std::string& colourFile);

// The 16-bit code of depth d and the depth of a code (header); kNoSurface <-> 0.
std::uint16_t encodeDepth(float d);
float decodeDepth(std::uint16_t q);
// The largest |decodeDepth(encodeDepth(d)) - d| for 0 <= d <= 43,000 m: half a code step at the
// far end of d's rounding interval.
double depthFileError(double d);

// Throws cavewall::Error naming the file when it cannot be written or the image is inconsistent.
void writeDepthFile(const std::filesystem::path& file, const DepthImage& image);
// Throws cavewall::Error naming the file when it is unreadable, not one channel of 16-bit codes
// or 32-bit floats, in tiles instead of scanlines, larger than kMaxDepthFileSide on a side, or
// (floats) holds a NaN or a negative depth. With `expectedSize` (what the runtime always knows:
// the march's depths of the colour texture) a file of another size is refused from its header,
// before anything is allocated for its texels.
DepthImage readDepthFile(const std::filesystem::path& file, std::optional<glm::ivec2> expectedSize = std::nullopt);
// The same reader on a depth file's bytes in memory, named `name` in messages: the steps after
// the open are the file's (the fuzz target reads this way, without a file per input).
DepthImage readDepthFile(std::span<const std::uint8_t> bytes, const std::string& name,
                         std::optional<glm::ivec2> expectedSize = std::nullopt);

}  // namespace cavewall::walls
