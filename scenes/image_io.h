#pragma once
// Image files through OpenImageIO. Writes are atomic (temporary file in the same folder, then
// rename), so a reader never sees a torn file. Errors throw cavewall::Error naming the file.

#include "scenes/scene.h"

#include <filesystem>

namespace cavewall::scenes {

// Writes an 8-bit RGBA image (rows top to bottom) as PNG (or any format OIIO knows from the
// extension). Creates missing parent folders.
void writeImage(const std::filesystem::path& file, const Image& image);

// Reads any image OIIO can decode into 8-bit RGBA (grey and RGB are expanded, alpha = 255).
Image readImage(const std::filesystem::path& file);

}  // namespace cavewall::scenes
