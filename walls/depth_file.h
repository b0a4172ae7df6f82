#pragma once
// The depth half of a depth wall's texture on disk (walls/depth_wall.h): one scanline TIFF of
// 32-bit float depths (one channel, metres behind the wall plane, +inf where nothing), zip
// compressed: lossless, so the error bound sees exactly the baked values. Written atomically
// beside the colour file, named after it (depthFileName), listed with its own size and hash in
// the manifest (walls/bake_manifest.h BakedTexture::depthFile).

#include "walls/depth_wall.h"

#include <filesystem>
#include <string>

namespace cavewall::walls {

// "tex_0003_<key>.tx" -> "tex_0003_<key>.depth.tif"
std::string depthFileName(const std::string& colourFile);

// Throws cavewall::Error naming the file when it cannot be written or the image is inconsistent.
void writeDepthFile(const std::filesystem::path& file, const DepthImage& image);
// Throws cavewall::Error naming the file when it is unreadable or not one float channel.
DepthImage readDepthFile(const std::filesystem::path& file);

}  // namespace cavewall::walls
