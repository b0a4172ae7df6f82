#pragma once
// Image files through OpenImageIO. Writes are atomic (temporary file in the same folder, then
// rename), so a reader never sees a torn file. Errors throw cavewall::Error naming the file.

#include "scenes/scene.h"

#include <filesystem>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace cavewall::scenes {

// Writes an 8-bit RGBA image (rows top to bottom) as PNG (or any format OIIO knows from the
// extension). Creates missing parent folders.
void writeImage(const std::filesystem::path& file, const Image& image);

// Writes `file` atomically: `write` fills a temporary file beside it (same folder, so rename() is
// atomic; unique per process and call; same extension, because OIIO picks the writer from it),
// which then replaces `file`. Creates missing parent folders. On any failure the temporary file
// is removed and the error rethrown; a failed rename throws Error naming `file`.
void writeAtomically(const std::filesystem::path& file,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

// Reads any image OIIO can decode into 8-bit RGBA (grey and RGB are expanded, alpha = 255).
Image readImage(const std::filesystem::path& file);

inline constexpr int kMaxMipSide = 16384;  // texels per side of a MIP level at most (the largest bake)
inline constexpr int kMaxMipTile = 4096;   // texels per side of a MIP file's tile at most

// Reads every MIP level of a (tiled) MIP-mapped TIFF such as a baked wall texture, largest
// first, each as 8-bit RGBA like readImage. The bytes are returned as stored: no alpha
// conversion (baked textures store premultiplied alpha, walls/texture_mips.h). A file
// without MIP levels gives one level. Only the TIFF reader opens it: a file that is not a TIFF
// is refused whatever its name, and so is a level with more than 4 channels, more than
// kMaxMipSide texels on a side or tiles over kMaxMipTile, from its header. Throws Error naming
// the file and the level.
std::vector<Image> readMipLevels(const std::filesystem::path& file);
// The same reader on a file's bytes in memory, named `name` in messages: the steps after the
// open are the file's (the fuzz target reads this way, without a file per input).
std::vector<Image> readMipLevels(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace cavewall::scenes
