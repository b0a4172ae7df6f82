// Fuzz target: a depth wall's depth file (".depth.tif", walls/depth_file.h), read from disk as
// the runtime reads it: with the size it expects (the march's depths of the colour texture).
// The input's first 4 bytes are that size (two little-endian 16-bit numbers, each taken as
// 1 + n mod 4096); the rest is the file, written to a file of this process first.
#include "config/error.h"
#include "tests/fuzz/fuzz_target.h"
#include "walls/depth_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 4) return 0;
    const glm::ivec2 expected(1 + (data[0] | data[1] << 8) % 4096, 1 + (data[2] | data[3] << 8) % 4096);
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("cavewall_fuzz_" + std::to_string(getpid()) + ".depth.tif");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 4), static_cast<std::streamsize>(size - 4));
    }
    try {
        const cavewall::walls::DepthImage image = cavewall::walls::readDepthFile(file, expected);
        // What is accepted is consistent: the expected size, one depth per texel, none negative or NaN.
        if (image.width != expected.x || image.height != expected.y) __builtin_trap();
        if (image.depth.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
            __builtin_trap();
        for (float d : image.depth)
            if (std::isnan(d) || d < 0.0f) __builtin_trap();
    } catch (const cavewall::Error&) {}
    return 0;
}
