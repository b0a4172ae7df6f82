#pragma once
// SSIM (Wang, Bovik, Sheikh, Simoncelli, "Image Quality Assessment: From Error Visibility to
// Structural Similarity", IEEE TIP 2004) with the paper's standard parameters, so that figures
// compare with other tools:
//  - on luma Y' = 0.299 R' + 0.587 G' + 0.114 B' (ITU-R BT.601 weights) of the stored,
//    sRGB-encoded bytes, in levels 0-255 (dynamic range L = 255); alpha ignored. This is the
//    grey image most tools compare (MATLAB's rgb2gray, the Y plane of video codecs);
//  - local statistics under an 11x11 Gaussian window, sigma 1.5 pixels, weights normalised to
//    sum 1; weighted (not sample) variances and covariance;
//  - C1 = (K1 L)², C2 = (K2 L)², K1 = 0.01, K2 = 0.03;
//  - SSIM(x, y) = (2 mx my + C1)(2 sxy + C2) / ((mx² + my² + C1)(sx² + sy² + C2)) at each pixel
//    where the whole window fits inside the image (the "valid" region, no padding), and the
//    image's SSIM is the mean over those pixels. No automatic downsampling.
// Along a side shorter than 11 pixels the window is shrunk to radius (side - 1) / 2 (rounded
// down; the Gaussian truncated and renormalised), so that it still fits.
//
// Range [-1, 1]; 1 only for images with the same luma; symmetric in its two images.

#include "scenes/scene.h"

namespace cavewall::metrics {

// SSIM of the luma of two 8-bit RGBA images (see above). Throws cavewall::Error naming both
// images when their sizes differ or either is empty.
double ssim(const scenes::Image& a, const scenes::Image& b);

}  // namespace cavewall::metrics
