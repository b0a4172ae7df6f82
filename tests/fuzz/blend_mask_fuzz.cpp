// Fuzz target: a projector blend mask (display/blend_mask.h), a grey PNG decoded from memory.
// What is accepted must be consistent: a size within the limits and one weight per pixel.
#include "config/error.h"
#include "display/blend_mask.h"
#include "tests/fuzz/fuzz_target.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        using namespace cavewall::display;
        const BlendMask m = parseBlendMask(bytes, "fuzz.png");
        if (m.width < 1 || m.height < 1 || m.width > kMaxBlendMaskSide || m.height > kMaxBlendMaskSide)
            __builtin_trap();
        if (m.weights.size() != static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height))
            __builtin_trap();
        const float corner = m.at(m.width - 1, m.height - 1);
        if (!(corner >= 0.0f && corner <= 1.0f)) __builtin_trap();
    } catch (const cavewall::Error&) {}
    return 0;
}
