// Fuzz target: a depth wall's depth file (".depth.tif", walls/depth_file.h), read from disk as
// the runtime reads it (the bytes are written to a file of this process first).
#include "config/error.h"
#include "tests/fuzz/fuzz_target.h"
#include "walls/depth_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("cavewall_fuzz_" + std::to_string(getpid()) + ".depth.tif");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        const cavewall::walls::DepthImage image = cavewall::walls::readDepthFile(file);
        // What is accepted is consistent: one depth per texel, none negative or NaN.
        if (image.depth.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
            __builtin_trap();
        for (float d : image.depth)
            if (std::isnan(d) || d < 0.0f) __builtin_trap();
    } catch (const cavewall::Error&) {}
    return 0;
}
