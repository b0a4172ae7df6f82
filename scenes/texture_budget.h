#pragma once
// Texture sizes at load: what a CAVE can resolve, and a memory budget for the whole scene.
//
// A CAVE shows a model's atlases at a few hundred pixels, so images are reduced when they are
// decoded (scenes/gltf_loader.cpp: decode one image, reduce it, release the full-size decode,
// then the next one), and the scene's reduced set is then fitted to a budget.
//
// Reduction is a box filter by a power of two, averaged in linear light (colour channels are
// sRGB-encoded, alpha is linear), as the GPU's MIP levels are: output pixel (x, y) of a
// reduction by f is the mean of the source pixels in [x f, x f + f) x [y f, y f + f) that lie
// inside the image, so an image of w x h becomes ceil(w / f) x ceil(h / f).
//
// Rule: every image is reduced by the smallest power of two that brings both sides to at most
// `maxSide` pixels; then, while the images' bytes (width x height x 4, the base level; MIP
// levels add a third on the GPU) exceed `budgetBytes`, the largest image in bytes (the first
// of equals) is halved again, down to 1 x 1.

#include "scenes/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cavewall::scenes {

struct TextureLimits {
    int maxSide = 2048;                                // pixels, >= 1
    std::size_t budgetBytes = std::size_t{512} << 20;  // bytes of all images together (512 MB)
};

// The smallest power of two f for which ceil(width / f) and ceil(height / f) are <= maxSide.
int reductionFactor(int width, int height, int maxSide);

// `width` x `height` 8-bit RGBA pixels (rows top to bottom), reduced by `factor` (a power of
// two >= 1) as described above. `bytesPerSample` is 1, or 2 for 16-bit samples stored little-
// endian (their high byte is used). Sets name, width, height and rgba; sourceWidth and
// sourceHeight are left for the caller.
Image reduceImage(const std::uint8_t* rgba, int width, int height, int bytesPerSample, int factor);

// What fitTextures did, for the line printed at load.
struct TextureReport {
    int images = 0;               // images with pixels
    std::size_t sourceBytes = 0;  // their bytes decoded at full size (sourceWidth x sourceHeight x 4)
    std::size_t keptBytes = 0;    // their bytes as kept
    int largestSide = 0;          // the largest side kept, pixels
    int halvings = 0;             // halvings made to fit the budget
    TextureLimits limits;
};

// Halves the largest images until `images` fit limits.budgetBytes (images are expected to be
// within limits.maxSide already, as the loader leaves them). Empty images are skipped.
TextureReport fitTextures(std::vector<Image>& images, const TextureLimits& limits);

// "textures: 41 images, 11,006 MB decoded at full size -> 512 MB, largest side 2048 px
// (limits: 2048 px, budget 512 MB)"; MB are 2^20 bytes, with one decimal below 10 MB.
std::string describe(const TextureReport& report);

}  // namespace cavewall::scenes
