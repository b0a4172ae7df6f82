// Fuzz target: a depth wall's depth file (".depth.tif", walls/depth_file.h), read as the runtime
// reads it: with the size it expects (the march's depths of the colour texture). The input's
// first 4 bytes are that size (two little-endian 16-bit numbers, each taken as 1 + n mod 4096);
// the rest is the file, read from memory by the reader's in-memory entry point, which shares
// every step after the open with the file's.
#include "config/error.h"
#include "tests/fuzz/fuzz_target.h"
#include "walls/depth_file.h"

#include <cmath>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 4) return 0;
    const glm::ivec2 expected(1 + (data[0] | data[1] << 8) % 4096, 1 + (data[2] | data[3] << 8) % 4096);
    try {
        const cavewall::walls::DepthImage image =
            cavewall::walls::readDepthFile(std::span(data + 4, size - 4), "fuzz.depth.tif", expected);
        // What is accepted is consistent: the expected size, one depth per texel, none negative or NaN.
        if (image.width != expected.x || image.height != expected.y) __builtin_trap();
        if (image.depth.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
            __builtin_trap();
        for (float d : image.depth)
            if (std::isnan(d) || d < 0.0f) __builtin_trap();
    } catch (const cavewall::Error&) {}
    return 0;
}
