// Fuzz target: a block-compressed wall texture file (".bct", walls/texture_blocks.h).
#include "config/error.h"
#include "tests/fuzz/fuzz_target.h"
#include "walls/texture_blocks.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace cavewall::walls;
    try {
        const TextureLevels levels =
            blocksFromBytes(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.bct");
        // What is accepted is consistent: every level holds exactly its blocks, and decodes.
        for (const BlockLevel& l : levels.blocks) {
            if (l.blocks.size() != levelBytes(levels.format, l.width, l.height)) __builtin_trap();
            if (l.width <= 256 && l.height <= 256) decodeLevel(l, levels.format);
        }
    } catch (const cavewall::Error&) {}
    return 0;
}
