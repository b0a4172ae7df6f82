// Fuzz target: one DTrack2 ASCII datagram. The parser must not throw at all (untrusted stream).
#include "config/error.h"
#include "input/packets.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    cavewall::input::PacketDrop drop = cavewall::input::PacketDrop::None;
    const auto frame = cavewall::input::parseDTrack(std::string_view(reinterpret_cast<const char*>(data), size), &drop);
    if (frame)
        for (const auto& body : frame->bodies)
            if (!std::isfinite(body.pose.position.x)) __builtin_trap();  // accepted packets are finite
    return 0;
}
