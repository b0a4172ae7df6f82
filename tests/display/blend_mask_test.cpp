#include "display/blend_mask.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <cstdint>

namespace cavewall::display {
namespace {

using ::testing::HasSubstr;

void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
}

// An 8-bit PNG with `channels` channels, rows top first, from `bytes`.
std::string png(int w, int h, int channels, const std::vector<std::uint8_t>& bytes) {
    std::string out;
    stbi_write_png_to_func(append, &out, w, h, channels, bytes.data(), w * channels);
    return out;
}

TEST(BlendMask, EightBitGreyScalesToSixteenBitsAndFlipsRows) {
    // 2 x 2, top row 0 and 255, bottom row 128 and 1.
    const BlendMask m = parseBlendMask(png(2, 2, 1, {0, 255, 128, 1}), "m.png");
    ASSERT_EQ(m.weights.size(), 4u);
    EXPECT_EQ(m.weights[0], 128 * 257);  // (0, 0) is the bottom-left pixel: GL's row order
    EXPECT_EQ(m.weights[1], 257);
    EXPECT_EQ(m.weights[3], 65535);  // 255 is exactly 1
    EXPECT_FLOAT_EQ(m.at(0, 1), 0.0f);
}

TEST(BlendMask, BadInputSaysWhatItExpected) {
    struct Case {
        const char* name;
        std::string bytes;
        std::string message;
    };
    const std::string valid = png(2, 1, 1, {1, 2});
    const Case cases[] = {
        {"empty", "", "m.png: not a PNG file (expected the PNG signature, got 0 bytes"},
        {"text", "P5\n2 2\n255\n", "m.png: not a PNG file"},
        {"rgb", png(2, 1, 3, {1, 2, 3, 4, 5, 6}), "m.png: expected a grey PNG (1 channel, no alpha), got 3 channels"},
        {"grey and alpha", png(1, 1, 2, {1, 2}), "got 2 channels"},
        {"truncated in a chunk", valid.substr(0, 50), "m.png: PNG chunk 'IDAT' at byte 33: its length is "},
        {"truncated between chunks", valid.substr(0, valid.size() - 12),
         "m.png: PNG chunk at byte " + std::to_string(valid.size() - 12) +
             ": expected 12 bytes of length, type and CRC, got 0 (the file is truncated)"},
        {"image data short of the header's size",
         valid.substr(0, 16) + std::string("\0\0\x40\0\0\0\x40\0", 8) + valid.substr(24),
         "m.png: cannot decode the PNG's 16384 x 16384 pixels ("},
        {"IHDR not first", valid.substr(0, 8) + valid.substr(33),
         "m.png: expected the PNG's first chunk to be 'IHDR', got 'IDAT'"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { parseBlendMask(c.bytes, "m.png"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

// An empty IDAT chunk is valid PNG; it decodes as the file without it.
TEST(BlendMask, AnEmptyDataChunkIsSkipped) {
    const std::string valid = png(2, 1, 1, {1, 2});
    const std::string withEmpty = valid.substr(0, 33) + std::string("\0\0\0\0IDAT\0\0\0\0", 12) + valid.substr(33);
    EXPECT_EQ(parseBlendMask(withEmpty, "m.png"), parseBlendMask(valid, "m.png"));
}

TEST(BlendMask, MissingFileNamesIt) {
    EXPECT_THAT([] { loadBlendMask("/nonexistent/front.png"); },
                ThrowsMessage<Error>(HasSubstr("/nonexistent/front.png: cannot open blend mask")));
}

}  // namespace
}  // namespace cavewall::display
