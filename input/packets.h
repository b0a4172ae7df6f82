#pragma once
// Tracker network protocols as pure functions on byte strings.
//
// Packets come from the network and are untrusted: a parser never throws, never reads past the
// end, and returns std::nullopt for anything it cannot fully accept, saying why in `*drop`
// (so the caller can count it). A packet with any NaN or infinite number is dropped as a whole.
//
// ART DTrack2 ASCII (one UDP datagram = one frame, lines separated by "\n" or "\r\n"):
//   fr <frame counter>
//   ts <timestamp, seconds>
//   6d <n> [id qu][sx sy sz eta theta phi][b0 b1 b2 b3 b4 b5 b6 b7 b8] ...     (n bodies)
//   6df2 <defined> <n> [id qu nbt nct][sx sy sz][b0 ... b8][bt0 ... ct0 ct1 ...]   (n Flysticks)
// Positions in millimetres (converted here to metres); b0..b8 is the rotation matrix column by
// column (R = [[b0 b3 b6], [b1 b4 b7], [b2 b5 b8]]); the Euler angles are ignored. A quality
// below 0 means "not tracked": such a device is reported with tracked = false and an identity
// orientation. Flystick buttons come as ceil(nbt / 32) integers (bit i = button i), then nct
// controller values in [-1, 1]; ct0 is the joystick's x, ct1 its y. Other line types (3d, 6dcal,
// gl, 6dmt, ...) are skipped. The packet is dropped when a known line is malformed, a rotation
// is not orthonormal (within 0.01), or the packet has neither an "fr" nor a 6d/6df2 line.
//
// opentrack "UDP over network" output: exactly 48 bytes, six little-endian IEEE doubles
//   x, y, z (centimetres), yaw, pitch, roll (degrees).
// Mapped to the tracker frame as: x -> +X (right), y -> +Y (up), z -> +Z (backwards, away from
// the screen), metres; orientation = yaw about +Y (positive turns left), then pitch about +X
// (positive looks up), then roll about +Z (positive tilts left), as input::yawPitchRoll. Setups
// whose signs differ flip them with the source's `invert` parameter. Plausibility limits:
// |position| <= 10000 cm, |angle| <= 360°, and no value that is not zero but smaller than
// 1e-12 in magnitude (no tracker measures picometres; such values are what random bytes
// decode to); anything else is dropped as malformed. Where the head may plausibly be is
// checked later, against the tracking volume (tracker_source.h).

#include "input/sample.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::input {

enum class PacketDrop : std::uint8_t { None, Malformed, NonFinite };

struct DTrackBody {
    int id = 0;            // DTrack's body id (as numbered in DTrack, from 0)
    double quality = 0.0;  // < 0: not tracked
    Pose pose;             // tracker frame, metres
    bool tracked() const { return quality >= 0.0; }
};

struct DTrackFlystick {
    int id = 0;
    double quality = 0.0;
    Pose pose;
    WandState wand;
    bool tracked() const { return quality >= 0.0; }
};

struct DTrackFrame {
    std::optional<std::uint64_t> frame;     // "fr"
    std::optional<double> timestamp;        // "ts", seconds since midnight (tracker clock)
    std::vector<DTrackBody> bodies;         // "6d"
    std::vector<DTrackFlystick> flysticks;  // "6df2"
};

std::optional<DTrackFrame> parseDTrack(std::string_view packet, PacketDrop* drop = nullptr);

// Which opentrack values to negate before mapping (see above).
struct OpenTrackInvert {
    bool x = false, y = false, z = false, yaw = false, pitch = false, roll = false;
};

std::optional<Pose> parseOpenTrack(std::string_view packet, const OpenTrackInvert& invert = {},
                                   PacketDrop* drop = nullptr);

// The 48-byte opentrack datagram for the given values (for tests and simulators).
std::string encodeOpenTrack(const double values[6]);

}  // namespace cavewall::input
