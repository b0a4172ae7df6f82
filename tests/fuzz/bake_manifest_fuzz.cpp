// Fuzz target: a bake cache's manifest.json.
#include "config/error.h"
#include "tests/fuzz/fuzz_target.h"
#include "walls/bake_manifest.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        auto m = cavewall::walls::manifestFromJson(std::string_view(reinterpret_cast<const char*>(data), size),
                                                   "manifest.json");
        // What is accepted writes back (as the current version, without the rejected entries)
        // and reads back the same, every entry passing its checks.
        m.version = cavewall::walls::kManifestVersion;
        m.rejected.clear();
        if (cavewall::walls::manifestFromJson(cavewall::walls::manifestToJson(m), "again.json") != m) __builtin_trap();
    } catch (const cavewall::Error&) {}
    return 0;
}
