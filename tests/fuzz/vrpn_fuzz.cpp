// Fuzz target: the bytes a VRPN server sends on one TCP connection, fed to a session in chunks
// of varying size. The session must not throw, and every pose it passes on must be finite with a
// unit quaternion (untrusted stream).
#include "config/error.h"
#include "input/vrpn_protocol.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    cavewall::input::VrpnSession session("Tracker0", "Tracker0");
    const std::size_t chunk = size == 0 ? 1 : 1 + static_cast<std::size_t>(data[size - 1]) % 97;
    for (std::size_t at = 0; at < size; at += chunk) {
        cavewall::input::VrpnUpdates updates;
        session.feed(bytes.substr(at, chunk), updates);
        for (const auto& r : updates.poses) {
            const auto& p = r.pose.position;
            if (!std::isfinite(p.x + p.y + p.z)) __builtin_trap();
            if (std::fabs(glm::length(r.pose.orientation) - 1.0) > 1e-9) __builtin_trap();
        }
    }
    return 0;
}
