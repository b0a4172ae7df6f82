// Fuzz target: a display configuration file (parse, then validate).
#include "config/error.h"
#include "config/display_config.h"
#include "tests/fuzz/fuzz_target.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto config = cavewall::config::parseDisplayConfig(text, "fuzz.json");
        cavewall::config::validateDisplayConfig(config, "fuzz.json");
    } catch (const cavewall::Error&) {}
    return 0;
}
