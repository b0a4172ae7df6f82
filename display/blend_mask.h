#pragma once
// Projector blend masks: per output pixel, the share of the wall's light this projector gives
// where projectors overlap (edge blending). GL-free; display/gl/projector_pass.h applies them.
//
// File: an 8- or 16-bit grey PNG (one channel, no alpha) over the projector's whole output,
// top row first as PNG stores it; white = 1 (this projector alone), black = 0. The values are
// linear-light weights: the pass multiplies the image's linear-light colour by them (it decodes
// sRGB before and encodes after), so two projectors whose masks sum to 1 over an overlap add up
// to the light of one. A mask of another size than the screen's resolution is stretched over it
// with linear filtering.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::display {

struct BlendMask {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> weights;  // width * height, 65535 = 1; rows from the bottom (GL order)
    float at(int x, int y) const { return weights[static_cast<std::size_t>(y) * width + x] / 65535.0f; }
    bool operator==(const BlendMask&) const = default;
};

inline constexpr int kMaxBlendMaskSide = 16384;

// Decodes PNG bytes (8-bit grey scaled by 257, so 255 maps to 65535 exactly). `source` names the
// file in messages. Throws cavewall::Error for anything but a 1-channel PNG within
// kMaxBlendMaskSide.
BlendMask parseBlendMask(std::string_view pngBytes, const std::string& source);

// Reads and decodes a file.
BlendMask loadBlendMask(const std::filesystem::path& file);

}  // namespace cavewall::display
