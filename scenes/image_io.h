#pragma once
// Image files through OpenImageIO. Writes are atomic (temporary file in the same folder, then
// rename), so a reader never sees a torn file. Errors throw cavewall::Error naming the file.

#include "scenes/scene.h"

#include <filesystem>
#include <vector>

namespace cavewall::scenes {

// Writes an 8-bit RGBA image (rows top to bottom) as PNG (or any format OIIO knows from the
// extension). Creates missing parent folders.
void writeImage(const std::filesystem::path& file, const Image& image);

// A temporary name beside `file` for an atomic write (same folder, so rename() is atomic), unique
// per process and call, keeping the extension because OIIO picks the writer from it.
std::filesystem::path temporarySibling(const std::filesystem::path& file);

// Reads any image OIIO can decode into 8-bit RGBA (grey and RGB are expanded, alpha = 255).
Image readImage(const std::filesystem::path& file);

// Reads every MIP level of a (tiled) MIP-mapped file such as a baked wall texture, largest
// first, each as 8-bit RGBA like readImage. The bytes are returned as stored: no alpha
// conversion (baked textures store premultiplied alpha, walls/gl/texture_mips.h). A file
// without MIP levels gives one level. Throws Error naming the file and the level.
std::vector<Image> readMipLevels(const std::filesystem::path& file);

}  // namespace cavewall::scenes
