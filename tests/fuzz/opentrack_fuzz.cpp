// Fuzz target: one opentrack UDP datagram. The parser must not throw at all (untrusted stream).
#include "config/error.h"
#include "input/packets.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    cavewall::input::PacketDrop drop = cavewall::input::PacketDrop::None;
    const auto pose =
        cavewall::input::parseOpenTrack(std::string_view(reinterpret_cast<const char*>(data), size), {}, &drop);
    if (pose && !std::isfinite(pose->position.x + pose->position.y + pose->position.z)) __builtin_trap();
    return 0;
}
